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

#include "concurrent.H"
#include "addToRunTimeSelectionTable.H"

#include <chrono>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace couplingSchedules
{
    defineTypeNameAndDebug(concurrent, 0);
    addToRunTimeSelectionTable(couplingSchedule, concurrent, dictionary);
}
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::string Foam::couplingSchedules::concurrent::description() const
{
    return
        "schedule concurrent: the gas advances beside the particles, on"
        " a thread of its own, with their voidage and reaction of the"
        " step before (docs/theory/coupling.md)";
}


void Foam::couplingSchedules::concurrent::step
(
    coupledParticles& particles,
    const volVectorField& U,
    const volScalarField& p_rgh,
    const std::function<void()>& gasVoidage,
    const std::function<void()>& gasStep,
    solverTimers& timers
) const
{
    if (!particles.reactionReady())
    {
        particlesThenGas(particles, U, p_rgh, gasVoidage, gasStep, timers);
        return;
    }

    // The particles' voidage and reaction of the last step for the gas,
    // the gas at the particles; then the DEM advances on a thread of its
    // own while the gas advances on this one
    timers.start();
    particles.updateVoidage();
    gasVoidage();
    particles.interpolateGas(U, p_rgh);
    timers.stop(solverTimers::coupling);

    timers.start();
    particles.advanceBeside
    (
        [&]
        {
            const auto gasStart = std::chrono::steady_clock::now();
            gasStep();
            timers.addGasBesideDem
            (
                std::chrono::duration<scalar>
                (
                    std::chrono::steady_clock::now() - gasStart
                ).count()
            );
        }
    );
    timers.stop(solverTimers::demBesideGas);

    timers.start();
    particles.exchangeToGas();
    timers.stop(solverTimers::coupling);
}


// ************************************************************************* //
