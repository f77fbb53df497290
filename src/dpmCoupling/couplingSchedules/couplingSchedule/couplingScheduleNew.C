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

#include "couplingSchedule.H"
#include "choiceEntry.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::couplingSchedule> Foam::couplingSchedule::New
(
    const dictionary& dict
)
{
    const word choice = choiceEntry
    (
        dict, "couplingSchedule", dictionaryConstructorTablePtr_->sortedToc(),
        "sequential",
        "sequential (the gas after the particles, default) or concurrent (the"
        " gas beside the particles on a thread of its own, one CFD step"
        " behind them)"
    );
    return (*dictionaryConstructorTablePtr_)[choice]();
}


// ************************************************************************* //
