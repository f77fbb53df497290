/*---------------------------------------------------------------------------*\
    dpmFoam2D: soft-sphere CFD-DEM for gas-solid fluidized beds
-------------------------------------------------------------------------------
    SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
    SPDX-License-Identifier: GPL-3.0-or-later
License
    This file is part of dpmFoam2D, free software under the GNU General
    Public License, version 3 or (at your option) any later version;
    see the file LICENSE.
\*---------------------------------------------------------------------------*/

#include "diffusion.H"
#include "knownEntries.H"
#include "positiveEntry.H"
#include "OStringStream.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{
namespace coarseGrainings
{
    defineTypeNameAndDebug(diffusion, 0);
    addToRunTimeSelectionTable(coarseGraining, diffusion, grid);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

const Foam::cartesianGrid& Foam::coarseGrainings::diffusion::cartesianOf
(
    const dictionary& dict,
    const gasGrid& grid
)
{
    const cartesianGrid* cartesian = dynamic_cast<const cartesianGrid*>(&grid);
    if (!cartesian)
    {
        FatalIOErrorInFunction(dict)
            << "coarseGraining diffusion in " << dict.name() << " diffuses"
            << " along the lines of a Cartesian grid; the gas grid is "
            << grid.type() << ": set gasGrid cartesian, or coarseGraining"
            << " none" << exit(FatalIOError);
    }
    return *cartesian;
}


Foam::scalar Foam::coarseGrainings::diffusion::readBandwidth
(
    const dictionary& dict,
    const cartesianGrid& grid
)
{
    const dictionary& coeffs = dict.subDict("diffusionCoeffs");
    checkKnownEntries
    (
        coeffs, wordList{"bandwidth"},
        "constant/particleProperties/diffusionCoeffs"
    );

    // Below half a cell the kernel hardly leaves the cell a particle maps
    // to; beyond the domain's smallest extent it flattens the bed across it
    const bool inDepth = grid.resolvedInDepth();
    const scalar largestCell =
        inDepth ? max(max(grid.dx(), grid.dy()), grid.dz())
      : max(grid.dx(), grid.dy());
    const scalar smallestExtent =
        min
        (
            min(grid.xMax() - grid.xMin(), grid.yMax() - grid.yMin()),
            inDepth ? grid.depth() : GREAT
        );
    return boundedEntry
    (
        coeffs, "bandwidth", 0.5*largestCell, smallestExtent, false
    );
}


Foam::coarseGrainings::diffusion::axisKernel
Foam::coarseGrainings::diffusion::makeKernel
(
    const label n,
    const scalar h,
    const scalar T
)
{
    axisKernel K;
    K.n = n;
    K.first.setSize(n);
    K.start.setSize(n + 1);

    // The n x n Laplacian with zero-gradient ends has the eigenvectors
    // c_m cos(pi m (i + 1/2)/n) (the DCT-II basis) and the eigenvalues
    // -(4/h^2) sin^2(pi m/(2n)); exp(T L) keeps each mode, damped
    const scalar pi = constant::mathematical::pi;
    scalarList modes(n*n);      // modes[i*n + m] = c_m cos(..)
    scalarList decay(n);
    for (label m = 0; m < n; ++m)
    {
        const scalar c = std::sqrt((m == 0 ? 1.0 : 2.0)/n);
        const scalar s = std::sin(pi*m/(2*n));
        decay[m] = std::exp(-T*4*s*s/(h*h));
        for (label i = 0; i < n; ++i)
        {
            modes[i*n + m] = c*std::cos(pi*m*(i + 0.5)/n);
        }
    }

    DynamicList<scalar> weights(n);
    scalarList column(n);
    K.start[0] = 0;
    for (label j = 0; j < n; ++j)
    {
        scalar largest = 0;
        for (label i = 0; i < n; ++i)
        {
            scalar g = 0;
            for (label m = 0; m < n; ++m)
            {
                g += modes[i*n + m]*decay[m]*modes[j*n + m];
            }
            column[i] = g;
            largest = max(largest, g);
        }

        // The kernel falls off monotonically from its source cell: keep
        // the band above the cut, and make the column sum exactly one
        const scalar cut = 1e-15*largest;
        label lo = j, hi = j;
        while (lo > 0 && column[lo - 1] > cut) --lo;
        while (hi < n - 1 && column[hi + 1] > cut) ++hi;
        scalar sum = 0;
        for (label i = lo; i <= hi; ++i) sum += column[i];
        for (label i = lo; i <= hi; ++i) weights.append(column[i]/sum);
        K.first[j] = lo;
        K.start[j + 1] = weights.size();
    }
    K.weights.transfer(weights);
    return K;
}


void Foam::coarseGrainings::diffusion::applyAxis
(
    const label a,
    const scalarField& in,
    scalarField& out
) const
{
    const axisKernel& K = kernel_[a];
    const label stride = stride_[a];
    out = 0;
    for (const label line : lineStarts_[a])
    {
        for (label j = 0; j < K.n; ++j)
        {
            const scalar v = in[line + stride*j];
            if (v == 0) continue;       // most cells of a bed's freeboard
            label cell = line + stride*K.first[j];
            for (label w = K.start[j]; w < K.start[j + 1]; ++w)
            {
                out[cell] += K.weights[w]*v;
                cell += stride;
            }
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coarseGrainings::diffusion::diffusion
(
    const dictionary& dict,
    const gasGrid& grid
)
:
    coarseGraining(grid),
    cartesian_(cartesianOf(dict, grid)),
    bandwidth_(readBandwidth(dict, cartesian_))
{
    const cartesianGrid& g = cartesian_;
    const scalar T = 0.25*bandwidth_*bandwidth_;
    const label nx = g.nx(), ny = g.ny(), nz = g.nz();
    kernel_[0] = makeKernel(nx, g.dx(), T);
    kernel_[1] = makeKernel(ny, g.dy(), T);
    if (nz > 1)
    {
        kernel_[2] = makeKernel(nz, g.dz(), T);
    }
    stride_[0] = 1;
    stride_[1] = nx;
    stride_[2] = nx*ny;

    const label counts[3] = {nx, ny, nz};
    for (label a = 0; a < 3; ++a)
    {
        // The lines along axis a: every cell with index 0 along it
        labelList& starts = lineStarts_[a];
        starts.setSize(nx*ny*nz/counts[a]);
        label l = 0;
        for (label k = 0; k < (a == 2 ? 1 : nz); ++k)
        {
            for (label j = 0; j < (a == 1 ? 1 : ny); ++j)
            {
                for (label i = 0; i < (a == 0 ? 1 : nx); ++i)
                {
                    starts[l++] = i + nx*(j + ny*k);
                }
            }
        }
    }
    in_.setSize(nx*ny*nz);
    out_.setSize(nx*ny*nz);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::string Foam::coarseGrainings::diffusion::description() const
{
    OStringStream os;
    os.precision(6);
    os  << "coarse graining diffusion: the particle fraction, the mixture"
        << " and the reaction diffused over the bandwidth " << bandwidth_
        << " m (pseudo time b^2/4, no flux through the boundaries), in "
        << (grid_.resolvedInDepth() ? "x, y and z" : "x and y");
    return os.str();
}


void Foam::coarseGrainings::diffusion::smooth(scalarField& f) const
{
    const cartesianGrid& g = cartesian_;
    const label nx = g.nx(), ny = g.ny(), nz = g.nz();
    for (label k = 0; k < nz; ++k)
    {
        for (label j = 0; j < ny; ++j)
        {
            for (label i = 0; i < nx; ++i)
            {
                in_[i + nx*(j + ny*k)] = f[g.cellIJK(i, j, k)];
            }
        }
    }
    applyAxis(0, in_, out_);
    applyAxis(1, out_, in_);
    if (nz > 1)
    {
        applyAxis(2, in_, out_);
        in_.swap(out_);         // the result in in_, as in 2D
    }
    for (label k = 0; k < nz; ++k)
    {
        for (label j = 0; j < ny; ++j)
        {
            for (label i = 0; i < nx; ++i)
            {
                f[g.cellIJK(i, j, k)] = in_[i + nx*(j + ny*k)];
            }
        }
    }
}


// ************************************************************************* //
