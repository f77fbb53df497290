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

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::couplingFormulation Foam::readCouplingFormulation
(
    const dictionary& dict
)
{
    const word choice = choiceEntry
    (
        dict, "formulation", {"A", "B"}, "B",
        "B (the gas sees the whole pressure gradient, the paper's, default)"
        " or A (particles also feel -V_p grad p, the gas eps grad p)"
    );
    return choice == "A" ? couplingFormulation::A : couplingFormulation::B;
}


Foam::string Foam::formulationDescription(const couplingFormulation f)
{
    if (f == couplingFormulation::A)
    {
        return
            "formulation A (Zhou et al. 2010 set I): particles feel the"
            " drag eps_g K_B (u - v) and the pressure-gradient force"
            " -V_p grad p; the gas carries eps_g grad p and the drag only";
    }
    return
        "formulation B (the paper's, Zhou et al. 2010 set II): the gas"
        " sees the whole pressure gradient; particles feel the drag"
        " K_B (u - v) and the buoyancy -rho_g V_p g";
}


// ************************************************************************* //
