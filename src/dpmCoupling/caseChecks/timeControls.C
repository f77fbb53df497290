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

#include "caseChecks.H"
#include "IFstream.H"
#include "Time.H"

#include <cmath>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- FatalIOError naming entry `key` of controlDict, its value and `allowed`
void refuse
(
    const dictionary& dict,
    const word& key,
    const scalar value,
    const std::string& allowed
)
{
    FatalIOErrorInFunction(dict)
        << "Entry '" << key << "' = " << value << " in system/controlDict is"
        << " out of range; allowed: " << allowed.c_str()
        << exit(FatalIOError);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::caseChecks::timeControls(const fileName& casePath)
{
    const fileName file(casePath/"system"/"controlDict");
    IFstream is(file);
    if (!is.good())
    {
        return;     // Time names the missing file itself
    }
    const dictionary dict(is);

    const scalar endTime = dict.get<scalar>("endTime");
    if (!std::isfinite(endTime) || endTime < 0)
    {
        refuse(dict, "endTime", endTime, "a time >= 0 s to run to");
    }

    // A zero step divides the run's own checks and OpenFOAM's write
    // schedule; a step past endTime is a typo for a smaller one
    const scalar deltaT = dict.get<scalar>("deltaT");
    if (!std::isfinite(deltaT) || deltaT <= 0 || (endTime > 0 && deltaT > endTime))
    {
        refuse
        (
            dict, "deltaT", deltaT,
            "the CFD step in seconds, > 0 and at most endTime = "
          + std::string(Foam::name(endTime)) + " (the paper's bed: 1e-4)"
        );
    }

    // OpenFOAM divides by writeInterval when it reads it
    const word writeControl =
        dict.getOrDefault<word>("writeControl", "timeStep");
    const scalar writeInterval = dict.get<scalar>("writeInterval");
    if (writeControl == "timeStep")
    {
        if (!(writeInterval >= 1) || writeInterval != std::round(writeInterval))
        {
            refuse
            (
                dict, "writeInterval", writeInterval,
                "with writeControl timeStep, a whole number of CFD steps >= 1"
            );
        }
    }
    else if (!std::isfinite(writeInterval) || writeInterval <= 0)
    {
        refuse
        (
            dict, "writeInterval", writeInterval,
            "with writeControl " + writeControl + ", an interval > 0 (in"
            " seconds of " + (writeControl == "clockTime"
            || writeControl == "cpuTime" ? "wall or CPU" : "simulated")
          + " time)"
        );
    }
}


// ************************************************************************* //
