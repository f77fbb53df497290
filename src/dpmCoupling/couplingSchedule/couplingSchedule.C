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

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::couplingSchedule Foam::readCouplingSchedule(const dictionary& dict)
{
    const word choice = choiceEntry
    (
        dict, "couplingSchedule", {"sequential", "concurrent"}, "sequential",
        "sequential (the gas after the particles, default) or concurrent (the"
        " gas beside the particles on a thread of its own, one CFD step"
        " behind them)"
    );
    return
        choice == "concurrent"
      ? couplingSchedule::concurrent
      : couplingSchedule::sequential;
}


Foam::string Foam::scheduleDescription(const couplingSchedule s)
{
    if (s == couplingSchedule::concurrent)
    {
        return
            "schedule concurrent: the gas advances beside the particles, on"
            " a thread of its own, with their voidage and reaction of the"
            " step before (docs/model.md)";
    }
    return
        "schedule sequential: the particles advance, then the gas with"
        " their new voidage and reaction";
}


// ************************************************************************* //
