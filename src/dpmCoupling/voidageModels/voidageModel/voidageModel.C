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

#include "voidageModel.H"

namespace Foam
{
    defineTypeNameAndDebug(voidageModel, 0);
    defineRunTimeSelectionTable(voidageModel, grid);
}


Foam::voidageModel::voidageModel
(
    const gasGrid& grid,
    const scalar voidageMin
)
:
    grid_(grid),
    voidageMin_(voidageMin)
{}


void Foam::voidageModel::requireOneCellThick(const dictionary& dict) const
{
    if (grid_.resolvedInDepth())
    {
        FatalIOErrorInFunction(dict)
            << "voidageModel " << type() << " in " << dict.name()
            << " needs a gas mesh one cell thick in z, but the mesh has "
            << grid_.cellCounts().c_str() << " cells (system/bedGeometry"
            << " nz); use nz 1, or voidageModel spheres3D for a gas resolved"
            << " in depth" << exit(FatalIOError);
    }
}


Foam::scalar Foam::voidageModel::largestDiameter() const
{
    return grid_.minCellSize();
}


Foam::string Foam::voidageModel::largestDiameterLimit() const
{
    return "the gas cell (" + grid_.cellSize() + " m)";
}


void Foam::voidageModel::checkDiameters
(
    const dictionary& dict,
    const wordList& classNames,
    const scalarList& diameters
) const
{
    const scalar largest = largestDiameter();
    forAll(diameters, i)
    {
        if (diameters[i] > largest)
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'diameter' = " << diameters[i] << " of class "
                << classNames[i] << " in " << dict.name()
                << " is larger than " << largestDiameterLimit().c_str()
                << "; allowed range (0, " << largest << "]"
                << exit(FatalIOError);
        }
    }
}


// ************************************************************************* //
