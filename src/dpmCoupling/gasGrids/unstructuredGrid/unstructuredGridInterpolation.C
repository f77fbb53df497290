/*---------------------------------------------------------------------------*\
    dpmFoam2D: soft-sphere CFD-DEM for gas-solid fluidized beds
-------------------------------------------------------------------------------
    SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
    SPDX-License-Identifier: GPL-3.0-or-later
License
    This file is part of dpmFoam2D, free software under the GNU General
    Public License, version 3 or (at your option) any later version;
    see the file LICENSE.
-------------------------------------------------------------------------------
    unstructuredGrid: the interpolation, OpenFOAM's cell-point idea (the
    tet of the cell holding the particle, between the cell centre and three
    mesh points) with each point's value a least-squares linear fit to the
    cells around it, so that a linear field comes out exactly.
\*---------------------------------------------------------------------------*/

#include "unstructuredGrid.H"
#include "polyMeshTetDecomposition.H"
#include "tetPointRef.H"
#include "HashSet.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- The weights w_i (q_i . y) of the value at the origin of the linear fit
//  a + g.x to values at the points x (weights 1/|x|^2), A y = e0 with
//  A = sum w q q^T, q = (1, x/h); false when A is singular (the points in
//  one plane)
bool linearFitWeights(const List<vector>& x, scalarList& weights)
{
    const label n = x.size();
    scalar h = 0;
    for (const vector& xi : x) h = max(h, mag(xi));
    if (n < 4 || h <= 0) return false;

    double A[4][5] = {};
    scalarList w(n);
    for (label i = 0; i < n; ++i)
    {
        w[i] = 1/magSqr(x[i]/h);
        const double q[4] = {1, x[i].x()/h, x[i].y()/h, x[i].z()/h};
        for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
        {
            A[r][c] += w[i]*q[r]*q[c];
        }
    }
    A[0][4] = 1;

    // Gaussian elimination with partial pivoting; a pivot below 1e-10 of
    // the largest diagonal entry is a singular fit
    double largest = 0;
    for (int r = 0; r < 4; ++r) largest = std::max(largest, A[r][r]);
    for (int c = 0; c < 4; ++c)
    {
        int pivot = c;
        for (int r = c + 1; r < 4; ++r)
        {
            if (std::abs(A[r][c]) > std::abs(A[pivot][c])) pivot = r;
        }
        if (std::abs(A[pivot][c]) < 1e-10*largest) return false;
        for (int k = 0; k < 5; ++k) std::swap(A[c][k], A[pivot][k]);
        for (int r = 0; r < 4; ++r)
        {
            if (r == c) continue;
            const double f = A[r][c]/A[c][c];
            for (int k = c; k < 5; ++k) A[r][k] -= f*A[c][k];
        }
    }
    double y[4];
    for (int r = 0; r < 4; ++r) y[r] = A[r][4]/A[r][r];

    weights.setSize(n);
    for (label i = 0; i < n; ++i)
    {
        weights[i] =
            w[i]*(y[0] + (y[1]*x[i].x() + y[2]*x[i].y() + y[3]*x[i].z())/h);
    }
    return true;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::unstructuredGrid::makePointWeights()
{
    const pointField& points = mesh_.points();
    const vectorField& C = mesh_.cellCentres();
    const labelListList& pointCells = mesh_.pointCells();
    const labelListList& cellCells = mesh_.cellCells();

    // The boundary's points: their cells' centres lie in one layer
    boolList onBoundary(mesh_.nPoints(), false);
    for (label facei = mesh_.nInternalFaces(); facei < mesh_.nFaces(); ++facei)
    {
        for (const label pointi : mesh_.faces()[facei])
        {
            onBoundary[pointi] = true;
        }
    }

    pointCells_.setSize(mesh_.nPoints());
    pointWeights_.setSize(mesh_.nPoints());
    forAll(points, pointi)
    {
        labelHashSet cells(pointCells[pointi]);
        if (onBoundary[pointi])
        {
            for (const label celli : pointCells[pointi])
            {
                cells.insert(cellCells[celli]);
            }
        }
        for (label round = 0; ; ++round)
        {
            labelList cellList(cells.sortedToc());
            List<vector> x(cellList.size());
            forAll(cellList, k)
            {
                x[k] = C[cellList[k]] - points[pointi];
            }
            scalarList weights;
            if (linearFitWeights(x, weights))
            {
                pointCells_[pointi].transfer(cellList);
                pointWeights_[pointi].transfer(weights);
                break;
            }
            if (round == 3)
            {
                FatalErrorInFunction
                    << "No linear fit at point " << pointi << " "
                    << points[pointi] << " from the cells around it "
                    << cellList << exit(FatalError);
            }
            for (const label celli : cellList)
            {
                cells.insert(cellCells[celli]);
            }
        }
    }

    // A stencil: the cell and three of its points' cells
    stencilStride_ = 1;
    const labelListList& cellPoints = mesh_.cellPoints();
    forAll(cellPoints, celli)
    {
        labelHashSet cells;
        cells.insert(celli);
        for (const label pointi : cellPoints[celli])
        {
            cells.insert(pointCells_[pointi]);
        }
        stencilStride_ = max(stencilStride_, cells.size());
    }
}


Foam::label Foam::unstructuredGrid::stencil
(
    const point& p,
    const label celli,
    label* cells,
    scalar* weights
) const
{
    const tetIndices tet(polyMeshTetDecomposition::findTet(mesh_, celli, p));
    if (tet.face() == -1)
    {
        // Outside the mesh: the nearest cell's value
        cells[0] = celli;
        weights[0] = 1;
        return 1;
    }
    const pointField& points = mesh_.points();
    const triFace tri(tet.faceTriIs(mesh_));
    const barycentric b
    (
        tetPointRef
        (
            mesh_.cellCentres()[celli],
            points[tri[0]], points[tri[1]], points[tri[2]]
        ).pointToBarycentric(p)
    );

    label count = 0;
    auto add = [&](const label c, const scalar w)
    {
        for (label k = 0; k < count; ++k)
        {
            if (cells[k] == c)
            {
                weights[k] += w;
                return;
            }
        }
        cells[count] = c;
        weights[count] = w;
        ++count;
    };
    add(celli, b[0]);
    for (label k = 0; k < 3; ++k)
    {
        const labelList& pc = pointCells_[tri[k]];
        const scalarList& pw = pointWeights_[tri[k]];
        forAll(pc, j)
        {
            add(pc[j], b[k + 1]*pw[j]);
        }
    }
    return count;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::unstructuredGrid::interpolationStencils
(
    const label n,
    const double* x,
    const double* y,
    const double* z,
    const label nThreads,
    cellWeights& stencils
) const
{
    if (!z && n > 0)
    {
        FatalErrorInFunction
            << "Particles without z in a gas resolved in depth"
            << abort(FatalError);
    }
    if (lastStencilCell_.size() != n)
    {
        lastStencilCell_.setSize(n, -1);
    }
    stencils.setSize(n, stencilStride_);
    const label S = stencils.stride;
    #pragma omp parallel for num_threads(nThreads) schedule(static)
    for (label i = 0; i < n; ++i)
    {
        const point p(x[i], y[i], z[i]);
        label celli = locate(p, lastStencilCell_[i]);
        if (celli < 0)
        {
            // Outside the mesh (beside a curved wall): the nearest cell
            celli = mesh_.findNearestCell(p);
        }
        lastStencilCell_[i] = celli;
        stencils.counts[i] =
            stencil(p, celli, &stencils.cells[S*i], &stencils.weights[S*i]);
    }
}


// ************************************************************************* //
