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

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(couplingSchedule, 0);
    defineRunTimeSelectionTable(couplingSchedule, dictionary);
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::couplingSchedule::particlesThenGas
(
    coupledParticles& particles,
    const volVectorField& U,
    const volScalarField& p_rgh,
    const std::function<void()>& gasVoidage,
    const std::function<void()>& gasStep,
    solverTimers& timers
)
{
    timers.start();
    particles.interpolateGas(U, p_rgh);
    timers.stop(solverTimers::coupling);

    timers.start();
    particles.advance();
    timers.stop(solverTimers::dem);

    timers.start();
    particles.exchangeToGas();
    particles.updateVoidage();
    gasVoidage();
    timers.stop(solverTimers::coupling);

    timers.start();
    gasStep();
    timers.stop(solverTimers::gas);
}


// ************************************************************************* //
