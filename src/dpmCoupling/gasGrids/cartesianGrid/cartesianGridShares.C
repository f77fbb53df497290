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
    cartesianGrid: the interpolation stencils and the shares of whole
    particle arrays, on the DEM's threads (each particle's own entries, so
    the thread count changes nothing).
\*---------------------------------------------------------------------------*/

#include "cartesianGrid.H"
#include "forEachSphereOverlap.H"
#include "forEachSphereBoxOverlap.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::cartesianGrid::interpolationStencils
(
    const label n,
    const double* x,
    const double* y,
    const double* z,
    const label nThreads,
    cellWeights& stencils
) const
{
    if (nz_ > 1 && !z && n > 0)
    {
        FatalErrorInFunction
            << "Particles without z in a gas resolved in depth"
            << abort(FatalError);
    }
    stencils.setSize(n, nz_ > 1 ? 8 : 4);
    const label S = stencils.stride;
    #pragma omp parallel for num_threads(nThreads) schedule(static)
    for (label i = 0; i < n; ++i)
    {
        stencils.counts[i] = interpolationStencil
        (
            x[i], y[i], z ? z[i] : 0,
            &stencils.cells[S*i], &stencils.weights[S*i]
        );
    }
}


void Foam::cartesianGrid::discShares
(
    const label n,
    const double* x,
    const double* y,
    const double* d,
    const label nThreads,
    cellWeights& shares
) const
{
    // A disc at most a cell across covers 2 x 2 cells at most
    storeShares
    (
        n, d, nThreads, 4,
        [this, x, y](const label i, const scalar r, const auto& op)
        {
            forEachDiscOverlap(x[i], y[i], r, op);
        },
        [](const scalar r) { return constant::mathematical::pi*r*r; },
        shares
    );
}


void Foam::cartesianGrid::sphereColumnShares
(
    const label n,
    const double* x,
    const double* y,
    const double* d,
    const label nThreads,
    cellWeights& shares
) const
{
    storeShares
    (
        n, d, nThreads, 4,
        [this, x, y](const label i, const scalar r, const auto& op)
        {
            forEachSphereOverlap(*this, x[i], y[i], r, op);
        },
        [](const scalar r) { return 4*constant::mathematical::pi*r*r*r/3; },
        shares
    );
}


void Foam::cartesianGrid::sphereShares
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
    // The cells a sphere spans at most, in all directions: the largest
    // particle's or the spreading sphere's (at most largestSpreadingDiameter:
    // the voidage model checks it)
    scalar D = spreadingDiameter;
    for (label i = 0; i < n; ++i)
    {
        D = max(D, d[i]);
    }
    const label stride =
        sphereCellSpan(D, dx_)*sphereCellSpan(D, dy_)
       *(resolvedInDepth() ? sphereCellSpan(D, dz_) : 1);

    const scalar Rs = 0.5*spreadingDiameter;
    storeShares
    (
        n, d, nThreads, stride,
        [this, x, y, z, Rs](const label i, const scalar r, const auto& op)
        {
            forEachSphereBoxOverlap(*this, x[i], y[i], z[i], max(r, Rs), op);
        },
        [Rs](const scalar r)
        {
            const scalar R = max(r, Rs);
            return 4*constant::mathematical::pi*R*R*R/3;
        },
        shares
    );
}


Foam::scalar Foam::cartesianGrid::largestSpreadingDiameter() const
{
    // A sphere of diameter D spans ceil(D/h) + 1 cells of size h, at most
    // maxSplits + 1
    return sphereBoxDetail::maxSplits*minCellSize();
}


// ************************************************************************* //
