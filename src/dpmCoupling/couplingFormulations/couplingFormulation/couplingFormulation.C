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

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(couplingFormulation, 0);
    defineRunTimeSelectionTable(couplingFormulation, dictionary);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::volScalarField> Foam::couplingFormulation::gasFraction
(
    const volScalarField& particleFraction,
    const scalar voidageMin
)
{
    return tmp<volScalarField>::New
    (
        "gasFraction",
        max
        (
            1 - particleFraction,
            dimensionedScalar("voidageMin", dimless, voidageMin)
        )
    );
}


// ************************************************************************* //
