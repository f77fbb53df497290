/*---------------------------------------------------------------------------*\
    dpmFoam2D: soft-sphere CFD-DEM for gas-solid fluidized beds
-------------------------------------------------------------------------------
    SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
    SPDX-License-Identifier: GPL-3.0-or-later
License
    This file is part of dpmFoam2D, free software under the GNU General
    Public License, version 3 or (at your option) any later version;
    see the file LICENSE.
-------------------------------------------------------------------------------
    particleEngine: the particle state's files. A state is written last at
    a write time, so that a time with it is complete; a restart checks,
    beyond the DEM's own settings (which the state file compares itself),
    the coupling models the run was made with, recorded in each state, and
    states of the other engine (a slab state in a discs2D case, or the
    reverse), named with the fix.
\*---------------------------------------------------------------------------*/

#include "particleEngine.H"
#include "Time.H"
#include "faultInjection.H"

#include <cmath>
#include <cstdio>

#include <sstream>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- "name value" lines of a run record, in order
std::vector<std::pair<std::string, std::string>> recordEntries
(
    const std::string& record
)
{
    std::vector<std::pair<std::string, std::string>> entries;
    std::istringstream lines(record);
    for (std::string line; std::getline(lines, line);)
    {
        std::istringstream words(line);
        std::string name, value;
        if (words >> name >> value) entries.emplace_back(name, value);
    }
    return entries;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::fileName Foam::particleEngine::stateFile
(
    const Time& time,
    const word& timeName
) const
{
    return time.path()/timeName/"uniform"/"dem.state";
}


bool Foam::particleEngine::hasStates(const Time& time) const
{
    for (const instant& t : Time::findTimes(time.path()))
    {
        if (isFile(stateFile(time, t.name())))
        {
            return true;
        }
    }
    return false;
}


void Foam::particleEngine::save(const fileName& file) const
{
    saveWithRecord(file, runRecord_);
}


void Foam::particleEngine::saveTime
(
    const Time& time,
    const scalar gasSpeedSum
) const
{
    std::string record = runRecord_ + "time " + time.timeName() + "\n";
    if (gasSpeedSum >= 0)
    {
        char gas[32];
        std::snprintf(gas, sizeof(gas), "%.17g", gasSpeedSum);
        record += std::string("gasSpeedSum ") + gas + "\n";
    }
    saveWithRecord(stateFile(time, time.timeName()), record);
}


void Foam::particleEngine::saveWithRecord
(
    const fileName& file,
    const std::string& record
) const
{
    faultInjection::at("stateWrite");
    // The write's own error (file, OS reason), not the settings' file
    try
    {
        dem_->setRunRecord(record);
        dem_->save(file);
    }
    catch (const dem::Error& err)
    {
        FatalErrorInFunction
            << "Cannot write the particle state: " << err.what()
            << exit(FatalError);
    }
    faultInjection::at("stateWrite", "done");
}


void Foam::particleEngine::loadRestart
(
    const fileName& restart,
    const bool slab
)
{
    try
    {
        dem_->load(restart);
    }
    catch (const dem::ForeignStateError& err)
    {
        FatalIOErrorInFunction(dict_)
            << "Cannot restart from " << restart << ": " << err.what()
            << ": " << foreignStateFix(err, slab, true).c_str()
            << exit(FatalIOError);
    }
    catch (const dem::Error& err)
    {
        FatalIOErrorInFunction(dict_)
            << "Cannot read the particle state (settings in "
            << dict_.name() << "):" << nl << "    " << err.what()
            << exit(FatalIOError);
    }
}


void Foam::particleEngine::checkRestartModels(const fileName& restart) const
{
    const std::string inFile = dem_->runRecord();
    if (inFile.empty())
    {
        WarningInFunction
            << "The particle state " << restart << " records no coupling"
            << " models (a state of an older dpmFoam2D): dragModel,"
            << " formulation, couplingSchedule and contactLaw of " << dict_.name()
            << " cannot be checked against the run it continues" << endl;
        return;
    }
    std::string differ, was;
    for (const auto& [name, here] : recordEntries(runRecord_))
    {
        for (const auto& [entry, there] : recordEntries(inFile))
        {
            if (entry == name && there != here)
            {
                differ += (differ.empty() ? "" : ", ") + name + " " + here;
                was += (was.empty() ? "" : ", ") + name + " " + there;
            }
        }
    }
    if (differ.empty())
    {
        return;
    }
    if (dict_.lookupOrDefault<bool>("allowModelChange", false))
    {
        Info<< "Particles: the run continues with " << differ.c_str()
            << " (allowModelChange in " << dict_.name() << "); "
            << restart << " was computed with " << was.c_str() << endl;
        return;
    }
    FatalIOErrorInFunction(dict_)
        << "Cannot restart from " << restart << ": the run was computed with "
        << was.c_str() << "; " << dict_.name() << " selects " << differ.c_str()
        << nl << "    Restore the entry to continue the run, set"
        << " 'allowModelChange yes;' in " << dict_.name() << " to continue it"
        << " with the change on purpose, or start anew from time 0"
        << " (startTime 0 in system/controlDict)" << exit(FatalIOError);
}


void Foam::particleEngine::checkRestartOrigin
(
    const fileName& restart,
    const Time& time,
    const scalar gasSpeedSum
) const
{
    std::string writtenAt, gas;
    for (const auto& [name, value] : recordEntries(dem_->runRecord()))
    {
        if (name == "time") writtenAt = value;
        if (name == "gasSpeedSum") gas = value;
    }
    scalar t;
    if
    (
        !writtenAt.empty() && readScalar(writtenAt, t)
     && mag(t - time.value()) > 1e-9*max(1, mag(time.value()))
    )
    {
        FatalErrorInFunction
            << "Cannot restart from " << restart << ": the state was written"
            << " at time " << writtenAt.c_str() << ", not at "
            << time.timeName() << " (the time directory it is in): a state"
            << " copied from another time" << nl
            << "    Restart from the time it belongs to (its whole directory),"
            << " or remove " << time.timePath() << exit(FatalError);
    }

    // The gas written beside it: U as read back, to the digits written
    // (writePrecision; exact in binary)
    scalar saved;
    const scalar tolerance =
        10*std::pow(10.0, -scalar(IOstream::defaultPrecision()));
    if
    (
        !gas.empty() && gasSpeedSum >= 0 && readScalar(gas, saved)
     && mag(saved - gasSpeedSum) > tolerance*max(mag(saved), mag(gasSpeedSum))
    )
    {
        FatalErrorInFunction
            << "Cannot restart from " << restart << ": the state was written"
            << " beside another gas than " << time.timePath()/"U" << " holds"
            << " (sum of the cells' |U| " << saved << " then, "
            << gasSpeedSum << " in the file): a state, or U, copied from"
            << " another case or time" << nl
            << "    Restart from a time directory as the run wrote it, or"
            << " remove " << time.timePath() << exit(FatalError);
    }
}


std::string Foam::particleEngine::foreignStateFix
(
    const dem::ForeignStateError& err,
    const bool slab,
    const bool restart
) const
{
    const word here(slab ? "slab3D" : "discs2D");
    const word there(err.fileDimension() == 3 ? "slab3D" : "discs2D");
    const std::string set =
        "this case runs " + here + ": set voidageModel " + there + " in "
      + dict_.name();
    return
        restart
      ? set + " to continue the run, or start anew from time 0 with a bed of"
        " this case's (remove the time directories and 0/uniform)"
      : set + ", or pack a " + (slab ? "slab" : "2D") + " bed (dpmPackBed)";
}


// ************************************************************************* //
