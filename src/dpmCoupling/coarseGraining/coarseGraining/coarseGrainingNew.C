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

#include "coarseGraining.H"
#include "choiceEntry.H"

Foam::autoPtr<Foam::coarseGraining> Foam::coarseGraining::New
(
    const dictionary& dict,
    const gasGrid& grid
)
{
    const word choice = choiceEntry
    (
        dict, "coarseGraining", gridConstructorTablePtr_->sortedToc(), "none",
        "none (the fields as the voidage model maps them, default) or"
        " diffusion (the fields diffused over diffusionCoeffs/bandwidth)"
    );
    return (*gridConstructorTablePtr_)[choice](dict, grid);
}


// ************************************************************************* //
