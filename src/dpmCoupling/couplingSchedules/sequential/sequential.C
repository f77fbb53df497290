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

#include "sequential.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace couplingSchedules
{
    defineTypeNameAndDebug(sequential, 0);
    addToRunTimeSelectionTable(couplingSchedule, sequential, dictionary);
}
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::string Foam::couplingSchedules::sequential::description() const
{
    return
        "schedule sequential: the particles advance, then the gas with"
        " their new voidage and reaction";
}


void Foam::couplingSchedules::sequential::step
(
    coupledParticles& particles,
    const volVectorField& U,
    const volScalarField& p_rgh,
    const std::function<void()>& gasVoidage,
    const std::function<void()>& gasStep,
    solverTimers& timers
) const
{
    particlesThenGas(particles, U, p_rgh, gasVoidage, gasStep, timers);
}


// ************************************************************************* //
