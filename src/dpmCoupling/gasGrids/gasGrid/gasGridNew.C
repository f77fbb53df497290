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

#include "gasGrid.H"
#include "choiceEntry.H"

Foam::autoPtr<Foam::gasGrid> Foam::gasGrid::New
(
    const dictionary& dict,
    const fvMesh& mesh
)
{
    const word choice = choiceEntry
    (
        dict, "gasGrid", meshConstructorTablePtr_->sortedToc(), "cartesian",
        "cartesian (a uniform Cartesian grid, one cell thick or resolved in"
        " depth; default), unstructured (any mesh with cells through the"
        " depth, the gas resolved in 3D: voidageModel spheres3D)"
    );
    return (*meshConstructorTablePtr_)[choice](dict, mesh);
}


// ************************************************************************* //
