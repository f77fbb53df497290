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
    unstructuredGrid: a sphere's volume shared among the cells by a
    quadrature of points of equal volume, on the DEM's threads (each
    particle's own entries, so the thread count changes nothing).
\*---------------------------------------------------------------------------*/

#include "unstructuredGrid.H"
#include "mathematicalConstants.H"
#include "DynamicList.H"
#include "tensor.H"

#ifdef _OPENMP
    #include <omp.h>
#endif

#include <algorithm>
#include <cstdint>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- The point's place on the Z-order curve of a 1024^3 lattice over the
//  cube [-1, 1]^3 (neighbours on the curve are mostly neighbours in space)
std::uint64_t mortonKey(const vector& v)
{
    std::uint64_t key = 0;
    std::uint64_t c[3];
    for (int d = 0; d < 3; ++d)
    {
        c[d] = std::uint64_t(std::min(1023.0, std::max(0.0, 512*(v[d] + 1))));
    }
    for (int bit = 9; bit >= 0; --bit)
    {
        for (int d = 0; d < 3; ++d)
        {
            key = (key << 1) | ((c[d] >> bit) & 1);
        }
    }
    return key;
}

//- Rotation by angle a about the x (axis 0) or z (axis 2) axis
tensor rotation(const int axis, const scalar a)
{
    const scalar c = std::cos(a), s = std::sin(a);
    return
        axis == 0
      ? tensor(1, 0, 0, 0, c, -s, 0, s, c)
      : tensor(c, -s, 0, s, c, 0, 0, 0, 1);
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::unstructuredGrid::makeQuadrature
(
    const label nShells,
    const label nDirections
)
{
    if (nShells < 1 || nDirections < 2 || nDirections % 2)
    {
        FatalErrorInFunction
            << "The sphere quadrature needs at least one shell and an even"
            << " number of directions, not " << nShells << " x "
            << nDirections << exit(FatalError);
    }
    const scalar pi = constant::mathematical::pi;
    const scalar golden = 0.5*(1 + std::sqrt(5.0));
    const label half = nDirections/2;

    quadrature_.setSize(nShells*nDirections);
    label q = 0;
    for (label k = 0; k < nShells; ++k)
    {
        // Equal volumes: the shell's middle in r^3
        const scalar r = std::cbrt((k + 0.5)/nShells);
        const tensor turn =
            rotation(2, k*golden*golden*pi) & rotation(0, k*golden*pi);
        for (label j = 0; j < half; ++j)
        {
            // The upper half of a Fibonacci lattice of nDirections points
            const scalar cz = 1 - (2*j + 1.0)/nDirections;
            const scalar sz = std::sqrt(1 - cz*cz);
            const scalar phi = 2*pi*j/golden;
            const vector d =
                turn & vector(sz*std::cos(phi), sz*std::sin(phi), cz);
            quadrature_[q++] = r*d;
            quadrature_[q++] = -r*d;
        }
    }

    // Along the Z-order curve: each point's walk starts from the cell of
    // its neighbour on the curve
    List<std::uint64_t> keys(quadrature_.size());
    forAll(quadrature_, i)
    {
        keys[i] = mortonKey(quadrature_[i]);
    }
    labelList order(identity(quadrature_.size()));
    std::stable_sort
    (
        order.begin(), order.end(),
        [&keys](const label a, const label b) { return keys[a] < keys[b]; }
    );
    quadrature_ = vectorField(quadrature_, order);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::unstructuredGrid::sphereShares
(
    const label n,
    const double* x,
    const double* y,
    const double* z,
    const double* d,
    const scalar spreadingDiameter,
    const label nThreads,
    cellWeights& shares
) const
{
    if (!z && n > 0)
    {
        FatalErrorInFunction
            << "Particles without z in a gas resolved in depth"
            << abort(FatalError);
    }
    if (lastShareCell_.size() != n)
    {
        lastShareCell_.setSize(n, -1);
    }
    const label N = quadrature_.size();
    const scalar Rs = 0.5*spreadingDiameter;
    const vectorField& Cf = mesh_.faceCentres();
    const labelList& owner = mesh_.faceOwner();

    // Each thread's cells and shares, particle i's from start[i] in the
    // buffers of thread of[i]
    const label nT = max(nThreads, label(1));
    List<DynamicList<label>> threadCells(nT);
    List<DynamicList<scalar>> threadShares(nT);
    labelList start(n), of(n), counts(n);

    #pragma omp parallel num_threads(nT)
    {
        #ifdef _OPENMP
        const label t = omp_get_thread_num();
        #else
        const label t = 0;
        #endif
        DynamicList<label>& myCells = threadCells[t];
        DynamicList<scalar>& myShares = threadShares[t];
        DynamicList<label> cells;
        DynamicList<label> hits;

        #pragma omp for schedule(static)
        for (label i = 0; i < n; ++i)
        {
            const point c(x[i], y[i], z[i]);
            const scalar R = max(0.5*d[i], Rs);
            label c0 = locate(c, lastShareCell_[i]);
            if (c0 < 0)
            {
                c0 = mesh_.findNearestCell(c);
            }
            lastShareCell_[i] = c0;

            // Behind every face plane of its cell by R: the sphere is there
            // whole (every point of the quadrature would be)
            bool whole = true;
            for (const label facei : mesh_.cells()[c0])
            {
                scalar s = (c - Cf[facei]) & faceNormals_[facei];
                if (owner[facei] != c0) s = -s;
                if (s > -R)
                {
                    whole = false;
                    break;
                }
            }

            cells.clear();
            hits.clear();
            if (whole)
            {
                cells.append(c0);
                hits.append(N);
            }
            else
            {
                label previous = c0;
                for (const vector& u : quadrature_)
                {
                    const point p(c + R*u);
                    bool beyond = false;
                    label celli = walk(p, previous, beyond);
                    if (celli < 0)
                    {
                        // A walk that went round in circles: the search
                        celli = mesh_.findCell(p);
                        if (celli < 0) celli = previous;
                    }
                    previous = celli;
                    const label k = cells.find(celli);
                    if (k == -1)
                    {
                        cells.append(celli);
                        hits.append(1);
                    }
                    else
                    {
                        ++hits[k];
                    }
                }
            }

            of[i] = t;
            start[i] = myCells.size();
            counts[i] = cells.size();
            forAll(cells, k)
            {
                myCells.append(cells[k]);
                myShares.append(scalar(hits[k])/N);
            }
        }
    }

    label stride = 1;
    for (const label count : counts) stride = max(stride, count);
    shares.setSize(n, stride);
    #pragma omp parallel for num_threads(nT) schedule(static)
    for (label i = 0; i < n; ++i)
    {
        shares.counts[i] = counts[i];
        for (label k = 0; k < counts[i]; ++k)
        {
            shares.cells[stride*i + k] = threadCells[of[i]][start[i] + k];
            shares.weights[stride*i + k] = threadShares[of[i]][start[i] + k];
        }
    }
}


// ************************************************************************* //
