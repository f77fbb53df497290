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

#include "incompleteTimes.H"
#include "argList.H"
#include "Time.H"
#include "IFstream.H"
#include "OSspecific.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- The missing files of a time, in words: "Ustar, Fp"
std::string missingText(const Foam::fileName& timeDir)
{
    std::string text;
    for (const Foam::fileName& f : Foam::missingRestartFiles(timeDir))
    {
        text += (text.empty() ? "" : ", ") + f;
    }
    return text;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::fileNameList Foam::missingRestartFiles(const fileName& timeDir)
{
    fileNameList missing;
    for (const fileName f : {"U", "p_rgh", "uniform/dem.state"})
    {
        if (!isFile(timeDir/f))
        {
            missing.append(f);
        }
    }

    // The concurrent schedule's reaction: all three or none (a time of a
    // sequential run); with only some, the next step would start from
    // another state than the one the time was written in
    const fileNameList exchange({"Kc", "Fp", "Ustar"});
    fileNameList absent;
    for (const fileName& f : exchange)
    {
        if (!isFile(timeDir/f))
        {
            absent.append(f);
        }
    }
    if (absent.size() && absent.size() < exchange.size())
    {
        missing.append(absent);
    }
    return missing;
}


bool Foam::completeTime(const fileName& timeDir)
{
    return missingRestartFiles(timeDir).empty();
}


Foam::label Foam::setAsideIncompleteTimes(const argList& args)
{
    const fileName casePath = args.path();
    const fileName controlDictFile = casePath/"system"/"controlDict";
    if (!isFile(controlDictFile))
    {
        return 0;       // Time reports the missing file
    }
    IFstream is(controlDictFile);
    const dictionary controlDict(is);
    const word startFrom =
        controlDict.lookupOrDefault<word>("startFrom", "latestTime");

    const instantList times = Time::findTimes(casePath);

    if (startFrom == "startTime")
    {
        const scalar t0 = controlDict.lookupOrDefault<scalar>("startTime", 0);
        for (const instant& t : times)
        {
            if
            (
                t.value() > 0 && mag(t.value() - t0) <= 1e-12*max(1, mag(t0))
             && !completeTime(casePath/t.name())
            )
            {
                FatalErrorInFunction
                    << "Start time " << t.name() << " (startTime in "
                    << controlDictFile << ") is incomplete: "
                    << casePath/t.name() << " has no "
                    << missingText(casePath/t.name()).c_str()
                    << " (a run killed while writing it, or files lost)" << nl
                    << "    Remove " << casePath/t.name() << " or start from"
                    << " an earlier time (startFrom latestTime continues"
                    << " from the last complete one)" << exit(FatalError);
            }
        }
        return 0;
    }
    if (startFrom != "latestTime")
    {
        return 0;
    }

    label nSetAside = 0;
    for (label i = times.size() - 1; i >= 0; --i)
    {
        const instant& t = times[i];
        const fileName dir = casePath/t.name();
        if (t.value() <= 0 || completeTime(dir))
        {
            break;
        }
        const std::string missing = missingText(dir);
        fileName aside = dir + ".incomplete";
        for (label k = 2; exists(aside); ++k)
        {
            aside = dir + ".incomplete." + Foam::name(k);
        }
        if (!Foam::mv(dir, aside))
        {
            FatalErrorInFunction
                << "Time " << t.name() << " in " << casePath << " is"
                << " incomplete (no complete restart state) and cannot be"
                << " renamed to " << aside << nl
                << "    Remove " << dir << " and run again"
                << exit(FatalError);
        }
        Info<< "Restart: time " << t.name() << " is incomplete (no "
            << missing.c_str() << ": a run killed while writing it,"
            << " or files lost); set aside as " << aside.name() << endl;
        ++nSetAside;
    }
    return nSetAside;
}


// ************************************************************************* //
