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

#include <algorithm>
#include <fstream>
#include <string>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Does a field file written by OpenFOAM end with the divider its writer
//  puts last (IOobject::writeEndDivider)? A compressed file is not looked
//  into. A file cut short (files lost or damaged after the run) lacks it.
bool endsWithDivider(const Foam::fileName& file)
{
    std::ifstream is(file, std::ios::binary);
    if (!is)
    {
        return true;    // a compressed or missing file: not judged here
    }
    is.seekg(0, std::ios::end);
    const std::streamoff size = is.tellg();
    const std::streamoff n = std::min<std::streamoff>(size, 256);
    std::string tail(size_t(n), '\0');
    is.seekg(size - n);
    is.read(&tail[0], n);
    const auto end = tail.find_last_not_of(" \t\r\n");
    if (end == std::string::npos)
    {
        return false;
    }
    const auto line = tail.rfind('\n', end);
    const std::string last =
        tail.substr(line == std::string::npos ? 0 : line + 1, end - line);
    return last.size() > 6 && last.compare(0, 4, "// *") == 0
        && last.compare(last.size() - 2, 2, "//") == 0;
}


//- What a time lacks, in words: "no Ustar, Fp; U cut short"
std::string incompleteText(const Foam::fileName& timeDir)
{
    std::string missing, cut;
    for (const Foam::fileName& f : Foam::missingRestartFiles(timeDir))
    {
        missing += (missing.empty() ? "no " : ", ") + f;
    }
    for (const Foam::fileName& f : Foam::cutShortRestartFiles(timeDir))
    {
        cut += (cut.empty() ? "" : ", ") + f;
    }
    if (!cut.empty()) cut += " cut short";
    return missing + (missing.empty() || cut.empty() ? "" : "; ") + cut;
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


Foam::fileNameList Foam::cutShortRestartFiles(const fileName& timeDir)
{
    fileNameList cut;
    for (const fileName f : {"U", "p_rgh", "Kc", "Fp", "Ustar"})
    {
        if (isFile(timeDir/f, false) && !endsWithDivider(timeDir/f))
        {
            cut.append(f);
        }
    }
    return cut;
}


bool Foam::completeTime(const fileName& timeDir)
{
    return missingRestartFiles(timeDir).empty()
        && cutShortRestartFiles(timeDir).empty();
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
                    << casePath/t.name() << " has "
                    << incompleteText(casePath/t.name()).c_str()
                    << " (a run killed while writing it, or files lost or"
                    << " damaged)" << nl
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
        const std::string missing = incompleteText(dir);
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
        Info<< "Restart: time " << t.name() << " is incomplete ("
            << missing.c_str() << ": a run killed while writing it,"
            << " or files lost); set aside as " << aside.name() << endl;
        ++nSetAside;
    }
    return nSetAside;
}


// ************************************************************************* //
