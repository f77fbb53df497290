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
    mesh points) with each point's value a positive-weight mean of the
    cells around it: the maximum-entropy weights nearest inverse distance
    whose mean centre is the point (along the walls at a boundary point),
    so that every weight is >= 0 and a linear field comes out exactly
    wherever the cells' centres surround the points (unstructuredGrid.H).
\*---------------------------------------------------------------------------*/

#include "unstructuredGrid.H"
#include "polyMeshTetDecomposition.H"
#include "tetPointRef.H"
#include "HashSet.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- Solve the d x d system A x = b (d <= 3) by Gaussian elimination with
//  partial pivoting; false when a pivot is below 1e-14 of the largest
//  diagonal entry
bool solveSmall(const label d, double A[3][3], double b[3], double x[3])
{
    double largest = 0;
    for (label r = 0; r < d; ++r)
    {
        largest = std::max(largest, std::abs(A[r][r]));
    }
    for (label c = 0; c < d; ++c)
    {
        label pivot = c;
        for (label r = c + 1; r < d; ++r)
        {
            if (std::abs(A[r][c]) > std::abs(A[pivot][c])) pivot = r;
        }
        if (!(std::abs(A[pivot][c]) > 1e-14*largest)) return false;
        for (label k = 0; k < d; ++k) std::swap(A[c][k], A[pivot][k]);
        std::swap(b[c], b[pivot]);
        for (label r = c + 1; r < d; ++r)
        {
            const double f = A[r][c]/A[c][c];
            for (label k = c; k < d; ++k) A[r][k] -= f*A[c][k];
            b[r] -= f*b[c];
        }
    }
    for (label r = d - 1; r >= 0; --r)
    {
        double s = b[r];
        for (label k = r + 1; k < d; ++k) s -= A[r][k]*x[k];
        x[r] = s/A[r][r];
    }
    return true;
}


//- The maximum-entropy weights of the values at the offsets y_i (d <= 3
//  components each, scaled to about 1) relative to the prior q_i: the
//  weights w_i = q_i exp(-lambda.y_i)/Z closest to q (relative entropy)
//  whose mean offset sum w_i y_i is zero, lambda minimising log Z by
//  Newton's method with halved steps. The weights are positive and add up
//  to 1 whatever lambda; the mean offset is zero (to 1e-13) when the
//  origin lies inside the convex hull of the y_i, and otherwise as small
//  as 100 steps with |lambda| <= 1000 make it. Returns |sum w_i y_i|.
scalar maxEntropyWeights
(
    const label d,
    const List<FixedList<double, 3>>& y,
    const scalarList& q,
    scalarList& w
)
{
    const label n = y.size();
    w.setSize(n);
    double lambda[3] = {0, 0, 0};

    // log Z at lambda and, into w, the weights
    auto logZ = [&](const double l[3])
    {
        double top = -GREAT;
        for (label i = 0; i < n; ++i)
        {
            double a = std::log(q[i]);
            for (label k = 0; k < d; ++k) a -= l[k]*y[i][k];
            w[i] = a;
            top = std::max(top, a);
        }
        double Z = 0;
        for (label i = 0; i < n; ++i)
        {
            w[i] = std::exp(w[i] - top);
            Z += w[i];
        }
        for (label i = 0; i < n; ++i) w[i] /= Z;
        return top + std::log(Z);
    };
    auto mean = [&](double m[3])
    {
        double size = 0;
        for (label k = 0; k < d; ++k)
        {
            m[k] = 0;
            for (label i = 0; i < n; ++i) m[k] += w[i]*y[i][k];
            size += m[k]*m[k];
        }
        return std::sqrt(size);
    };

    double F = logZ(lambda);
    double m[3] = {0, 0, 0};
    double residual = mean(m);
    for (label step = 0; step < 100 && residual > 1e-13; ++step)
    {
        // The Hessian of log Z: the offsets' covariance under w
        double H[3][3];
        for (label r = 0; r < d; ++r)
        for (label c = 0; c < d; ++c)
        {
            double s = 0;
            for (label i = 0; i < n; ++i) s += w[i]*y[i][r]*y[i][c];
            H[r][c] = s - m[r]*m[c];
        }
        // The gradient of log Z is -m: the Newton step solves H dl = m
        double rhs[3] = {m[0], m[1], m[2]};
        double dl[3] = {0, 0, 0};
        if (!solveSmall(d, H, rhs, dl))
        {
            // The offsets span fewer than d directions: the gradient's
            for (label k = 0; k < d; ++k) dl[k] = m[k];
        }
        // The step, halved until log Z falls; near the minimum, where the
        // fall is below round-off, until the mean offset does
        double t = 1;
        double trial[3];
        bool accepted = false;
        for (label halving = 0; halving < 60 && !accepted; ++halving, t *= 0.5)
        {
            double size = 0;
            for (label k = 0; k < 3; ++k)
            {
                trial[k] = lambda[k] + t*dl[k];
                size += trial[k]*trial[k];
            }
            // Beyond |lambda| = 1000 (the offsets about 1) a weight is
            // e^-1000 of another's: zero. The origin then lies outside the
            // offsets' hull, and the weights stay as they are
            if (!(size < 1e6)) continue;
            const double Ft = logZ(trial);
            double mt[3] = {0, 0, 0};
            const double rt = mean(mt);
            if (Ft < F || (Ft <= F + 1e-13*(1 + std::abs(F)) && rt < residual))
            {
                accepted = true;
                F = Ft;
                residual = rt;
                for (label k = 0; k < 3; ++k)
                {
                    lambda[k] = trial[k];
                    m[k] = mt[k];
                }
            }
        }
        if (!accepted)
        {
            // No step lowers either: the weights at lambda
            logZ(lambda);
            break;
        }
    }
    return residual;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::unstructuredGrid::makePointWeights()
{
    const pointField& points = mesh_.points();
    const vectorField& C = mesh_.cellCentres();
    const vectorField& Sf = mesh_.faceAreas();
    const labelListList& pointCells = mesh_.pointCells();
    const labelListList& pointFaces = mesh_.pointFaces();

    pointCells_.setSize(mesh_.nPoints());
    pointWeights_.setSize(mesh_.nPoints());
    nInexactPoints_ = 0;
    forAll(points, pointi)
    {
        // The walls at the point: its boundary faces' normals, those within
        // 30 degrees of each other one wall (a curved wall's faces), then
        // made orthonormal (a box's edge two, its corner three)
        DynamicList<vector> walls;
        for (const label facei : pointFaces[pointi])
        {
            if (mesh_.isInternalFace(facei)) continue;
            const vector n = Sf[facei]/mag(Sf[facei]);
            bool joined = false;
            for (vector& wall : walls)
            {
                if ((n & (wall/mag(wall))) > 0.866)
                {
                    wall += Sf[facei];
                    joined = true;
                    break;
                }
            }
            if (!joined) walls.append(Sf[facei]);
        }
        DynamicList<vector> normals;
        for (const vector& wall : walls)
        {
            vector n = wall/mag(wall);
            for (const vector& e : normals) n -= (n & e)*e;
            if (normals.size() < 3 && mag(n) > 0.1) normals.append(n/mag(n));
        }

        // The directions along the walls, in which a linear field is kept
        const label d = 3 - normals.size();
        List<vector> along(d);
        if (d == 3)
        {
            along[0] = vector(1, 0, 0);
            along[1] = vector(0, 1, 0);
            along[2] = vector(0, 0, 1);
        }
        else if (d == 2)
        {
            const vector& n = normals[0];
            // The axis least along the normal
            direction least = 0;
            for (direction k = 1; k < 3; ++k)
            {
                if (mag(n[k]) < mag(n[least])) least = k;
            }
            vector a(Zero);
            a[least] = 1;
            a -= (a & n)*n;
            along[0] = a/mag(a);
            along[1] = n ^ along[0];
        }
        else if (d == 1)
        {
            const vector t = normals[0] ^ normals[1];
            along[0] = t/mag(t);
        }

        // The cells' offsets from the point, along the walls, over the
        // farthest; the prior: inverse distance (volPointInterpolation's)
        const labelList& cells = pointCells[pointi];
        const label n = cells.size();
        scalar h = 0;
        for (const label celli : cells)
        {
            h = max(h, mag(C[celli] - points[pointi]));
        }
        List<FixedList<double, 3>> y(n);
        scalarList q(n);
        forAll(cells, i)
        {
            const vector x = C[cells[i]] - points[pointi];
            q[i] = 1/max(mag(x), SMALL*h);
            for (label k = 0; k < 3; ++k)
            {
                y[i][k] = k < d ? (x & along[k])/h : 0;
            }
        }
        scalarList w;
        if (maxEntropyWeights(d, y, q, w) > 1e-10)
        {
            ++nInexactPoints_;
        }
        pointCells_[pointi] = cells;
        pointWeights_[pointi].transfer(w);
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

    // Inside the tet the coordinates are >= 0; round-off (a point on a
    // face) may leave one just below: clipped, the rest scaled to sum 1
    scalar l[4];
    scalar lSum = 0;
    for (label k = 0; k < 4; ++k)
    {
        l[k] = max(b[k], scalar(0));
        lSum += l[k];
    }
    for (label k = 0; k < 4; ++k) l[k] /= lSum;

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
    add(celli, l[0]);
    for (label k = 0; k < 3; ++k)
    {
        const labelList& pc = pointCells_[tri[k]];
        const scalarList& pw = pointWeights_[tri[k]];
        forAll(pc, j)
        {
            add(pc[j], l[k + 1]*pw[j]);
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
