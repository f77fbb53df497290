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
    dpmCloud: what a restart checks beyond the DEM's own settings (which the
    state file compares itself): the coupling models the run was made with,
    recorded in each particle state, and states of the other engine (a slab
    state in a discs2D case, or the reverse), named with the fix.
\*---------------------------------------------------------------------------*/

#include "dpmCloud.H"

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


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

std::string Foam::dpmCloud::runRecord() const
{
    return
        "dragModel " + drag_->type() + "\n"
        "formulation " + formulation_->type() + "\n"
        "couplingSchedule " + schedule_->type() + "\n";
}


void Foam::dpmCloud::checkRestartModels(const fileName& restart) const
{
    const std::string inFile = dem_->runRecord();
    if (inFile.empty())
    {
        WarningInFunction
            << "The particle state " << restart << " records no coupling"
            << " models (a state of an older dpmFoam2D): dragModel,"
            << " formulation and couplingSchedule of " << dict_.name()
            << " cannot be checked against the run it continues" << endl;
        return;
    }
    std::string differ, was;
    for (const auto& [name, here] : recordEntries(runRecord()))
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


std::string Foam::dpmCloud::foreignStateFix
(
    const dem::ForeignStateError& err,
    const bool restart
) const
{
    const word here(slab_ ? "slab3D" : "discs2D");
    const word there(err.fileDimension() == 3 ? "slab3D" : "discs2D");
    const std::string set =
        "this case runs " + here + ": set voidageModel " + there + " in "
      + dict_.name();
    return
        restart
      ? set + " to continue the run, or start anew from time 0 with a bed of"
        " this case's (remove the time directories and 0/uniform)"
      : set + ", or pack a " + (slab_ ? "slab" : "2D") + " bed (dpmPackBed)";
}


void Foam::dpmCloud::warnUncheckedState() const
{
    if (!dem_->loadWarning().empty())
    {
        WarningInFunction
            << dem_->loadWarning().c_str() << endl;
    }
}



// ************************************************************************* //
