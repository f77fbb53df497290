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

#include "solverTimers.H"

Foam::solverTimers::solverTimers(const Time& runTime, const scalar reportInterval)
:
    runTime_(runTime),
    startTime_(runTime.value()),
    wallStart_(clock::now()),
    lastReport_(wallStart_),
    partStart_(wallStart_),
    reportInterval_(reportInterval),
    seconds_{0, 0, 0, 0, 0},
    gasBesideDem_(0)
{}


Foam::scalar Foam::solverTimers::wallSeconds() const
{
    return std::chrono::duration<scalar>(clock::now() - wallStart_).count();
}


void Foam::solverTimers::stop(const part p)
{
    seconds_[p] += std::chrono::duration<scalar>(clock::now() - partStart_).count();
}


void Foam::solverTimers::progress()
{
    const clock::time_point now = clock::now();
    if (std::chrono::duration<scalar>(now - lastReport_).count() < reportInterval_)
    {
        return;
    }
    lastReport_ = now;

    const scalar t = runTime_.value();
    const scalar endTime = runTime_.endTime().value();
    const scalar simulated = t - startTime_;
    const scalar wall = wallSeconds();
    const scalar rate = simulated > 0 ? wall/simulated : 0;
    const scalar percent = 100*(t - startTime_)/max(endTime - startTime_, VSMALL);
    const scalar eta = rate*(endTime - t);

    Info<< "Progress: t = " << t << " s (" << label(percent) << "%), "
        << rate << " wall s per simulated s, ETA " << label(eta) << " s"
        << endl;
}


void Foam::solverTimers::summary() const
{
    const scalar wall = max(wallSeconds(), VSMALL);
    const scalar simulated = runTime_.value() - startTime_;
    if (simulated <= 0)
    {
        Info<< "Nothing to run: the start time is the end time" << endl;
        return;
    }
    const char* names[nParts] =
        {"DEM", "coupling", "gas", "output", "DEM beside gas"};
    Info<< "Wall time " << wall << " s for " << simulated << " simulated s ("
        << wall/simulated << " wall s per simulated s):";
    for (int p = 0; p < nParts; ++p)
    {
        if (p == demBesideGas && seconds_[p] == 0)
        {
            continue;       // the sequential schedule
        }
        Info<< ' ' << names[p] << ' ' << seconds_[p] << " s ("
            << label(100*seconds_[p]/wall) << "%)";
    }
    if (seconds_[demBesideGas] > 0)
    {
        Info<< ", of which the gas " << gasBesideDem_ << " s";
    }
    Info<< endl;
}
