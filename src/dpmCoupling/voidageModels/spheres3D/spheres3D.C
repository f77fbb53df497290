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

#include "spheres3D.H"
#include "forEachSphereBoxOverlap.H"
#include "knownEntries.H"
#include "positiveEntry.H"
#include "OStringStream.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{
namespace voidageModels
{
    defineTypeNameAndDebug(spheres3D, 0);
    addToRunTimeSelectionTable(voidageModel, spheres3D, grid);
}
}


namespace
{
    // The cells a sphere of diameter D spans at most, in all directions
    Foam::label cellsSpanned(const Foam::cartesianGrid& grid, const Foam::scalar D)
    {
        using Foam::sphereCellSpan;
        return
            sphereCellSpan(D, grid.dx())*sphereCellSpan(D, grid.dy())
           *(grid.resolvedInDepth() ? sphereCellSpan(D, grid.dz()) : 1);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::scalar Foam::voidageModels::spheres3D::spreadingDiameter
(
    const dictionary& dict,
    const cartesianGrid& grid
)
{
    const dictionary* coeffs = dict.findDict("spheres3DCoeffs");
    if (!coeffs) return 0;
    checkKnownEntries
    (
        *coeffs, wordList{"spreadingDiameter"},
        "constant/particleProperties/spheres3DCoeffs"
    );
    // A sphere of diameter D spans ceil(D/h) + 1 cells of size h, at most
    // maxSplits + 1
    const scalar largest =
        sphereBoxDetail::maxSplits*grid.minCellSize();
    return boundedEntryOrDefault
    (
        *coeffs, "spreadingDiameter", 0, 0, largest, false
    );
}


Foam::voidageModels::spheres3D::spheres3D
(
    const dictionary& dict,
    const cartesianGrid& grid,
    const scalar voidageMin
)
:
    // The particles are at most one cell across (the cloud checks it)
    slab3D
    (
        grid, voidageMin,
        cellsSpanned
        (
            grid, max(spreadingDiameter(dict, grid), grid.minCellSize())
        )
    ),
    spreadingDiameter_(spreadingDiameter(dict, grid))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::string Foam::voidageModels::spheres3D::description() const
{
    OStringStream os;
    os  << "voidage model spheres3D: spheres in " << grid_.nx() << " x "
        << grid_.ny() << " x " << grid_.nz() << " gas cells, eps = 1 -"
        << " (sphere volume in the cell)/(cell volume), used as it is; ";
    if (spreadingDiameter_ > 0)
    {
        os  << "each particle spread over a sphere of diameter "
            << spreadingDiameter_ << " m";
    }
    else
    {
        os  << "each particle's own volume";
    }
    return os.str();
}


void Foam::voidageModels::spheres3D::updateOverlaps
(
    const label n,
    const double* x,
    const double* y,
    const double* z,
    const double* d,
    const label nThreads
)
{
    const scalar Rs = 0.5*spreadingDiameter_;
    storeOverlaps
    (
        n, d, nThreads,
        [this, x, y, z, Rs](const label i, const scalar r, const auto& op)
        {
            forEachSphereBoxOverlap(grid_, x[i], y[i], z[i], max(r, Rs), op);
        },
        [Rs](const scalar r)
        {
            const scalar R = max(r, Rs);
            return 4*constant::mathematical::pi*R*R*R/3;
        }
    );
}


// ************************************************************************* //
