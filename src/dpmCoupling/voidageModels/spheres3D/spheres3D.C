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


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::scalar Foam::voidageModels::spheres3D::spreadingDiameter
(
    const dictionary& dict,
    const gasGrid& grid
)
{
    const dictionary* coeffs = dict.findDict("spheres3DCoeffs");
    if (!coeffs) return 0;
    checkKnownEntries
    (
        *coeffs, wordList{"spreadingDiameter"},
        "constant/particleProperties/spheres3DCoeffs"
    );
    return boundedEntryOrDefault
    (
        *coeffs, "spreadingDiameter", 0, 0, grid.largestSpreadingDiameter(),
        false
    );
}


Foam::voidageModels::spheres3D::spheres3D
(
    const dictionary& dict,
    const gasGrid& grid,
    const scalar voidageMin
)
:
    slab3D(grid, voidageMin),
    spreadingDiameter_(spreadingDiameter(dict, grid))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::string Foam::voidageModels::spheres3D::description() const
{
    OStringStream os;
    os  << "voidage model spheres3D: spheres in "
        << grid_.cellCounts().c_str() << " gas cells, eps = 1 -"
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


void Foam::voidageModels::spheres3D::report(Ostream& os) const
{
    if (!grid_.resolvedInDepth())
    {
        slab3D::report(os);
        return;
    }
    os  << "    3D spheres in a gas resolved in depth ("
        << grid_.cellCounts().c_str() << " cells), " << grid_.depth()
        << " m deep" << endl;
}


Foam::scalar Foam::voidageModels::spheres3D::largestDiameter() const
{
    return grid_.largestSpreadingDiameter();
}


Foam::string Foam::voidageModels::spheres3D::largestDiameterLimit() const
{
    return
        "the largest sphere voidageModel spheres3D maps (six of the smallest"
        " gas cells, " + grid_.cellSize() + " m)";
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
    grid_.sphereShares(n, x, y, z, d, spreadingDiameter_, nThreads, shares_);
}


// ************************************************************************* //
