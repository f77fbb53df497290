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

#include "couplingFormulation.H"
#include "choiceEntry.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::couplingFormulation> Foam::couplingFormulation::New
(
    const dictionary& dict
)
{
    const word choice = choiceEntry
    (
        dict, "formulation", dictionaryConstructorTablePtr_->sortedToc(), "B",
        "B (the gas sees the whole pressure gradient, the paper's, default)"
        " or A (particles also feel -V_p grad p, the gas eps grad p)"
    );
    return (*dictionaryConstructorTablePtr_)[choice]();
}


// ************************************************************************* //
