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
#include "Time.H"
#include "Pstream.H"
#include "unitConversion.H"

#include <cmath>
#include <cstdlib>
#include <thread>
#include <sched.h>
#include <unistd.h>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- Processes of an MPI launch, 1 without one (mpirun sets these)
label launchedProcesses()
{
    for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"})
    {
        const char* value = std::getenv(var);
        if (value && std::atoi(value) > 1) return std::atoi(value);
    }
    return 1;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::caseChecks::gravity(const vector& g)
{
    const char* fix = "the fix: value (0 -9.81 0); in constant/g";
    if (mag(g) < VSMALL)
    {
        FatalErrorInFunction
            << "Gravity g = " << g << " in constant/g is zero: a fluidized"
            << " bed needs gravity (the bed's weight, its settling, Umf); "
            << fix << exit(FatalError);
    }
    if (mag(g.z()) > 0)
    {
        FatalErrorInFunction
            << "Gravity g = " << g << " in constant/g has a z component:"
            << " the bed lies in the x-y plane (z is the one-cell thickness),"
            << " so the particles would not feel it; " << fix
            << exit(FatalError);
    }
    if (!(g.y() < 0))
    {
        FatalErrorInFunction
            << "Gravity g = " << g << " in constant/g does not point down the"
            << " column (-y): the particles would not rest on the"
            << " distributor at the bottom; " << fix << exit(FatalError);
    }
    if (mag(g.x()) > 0)
    {
        WarningInFunction
            << "Gravity g = " << g << " in constant/g is tilted by "
            << radToDeg(std::atan2(mag(g.x()), -g.y())) << " degrees from -y:"
            << " the column is simulated tilted; " << fix << endl;
    }
}


Foam::label Foam::caseChecks::availableCores()
{
    cpu_set_t set;
    if (sched_getaffinity(0, sizeof(set), &set) == 0)
    {
        return CPU_COUNT(&set);
    }
    return max(label(std::thread::hardware_concurrency()), 1);
}


void Foam::caseChecks::threadCount
(
    const dictionary& dict,
    const string& where,
    const label nThreads,
    const bool gasThread
)
{
    const label cores = availableCores();
    const label extra = gasThread ? 1 : 0;
    if (nThreads + extra > cores)
    {
        IOWarningInFunction(dict)
            << "nThreads " << nThreads << " in " << where.c_str()
            << (gasThread ? ", and the gas's own thread of the concurrent"
                " schedule," : "")
            << " is above the " << cores << " cores this run may use: the"
            << " threads would take turns on them, which makes a run many"
            << " times slower; use nThreads " << max(cores - extra, 1)
            << " or fewer" << endl;
    }
}


void Foam::caseChecks::serialRun(const word& application)
{
    const label nProcs = Pstream::parRun() ? Pstream::nProcs() : launchedProcesses();
    if (nProcs > 1)
    {
        FatalErrorInFunction
            << application << " was started as " << nProcs << " processes"
            << (Pstream::parRun() ? " (-parallel)" : " (mpirun)") << ", but it"
            << " runs in one process: the particles are shared among threads"
            << " (nThreads in constant/particleProperties), not among MPI"
            << " processes. Run it as '" << application << "' alone, without"
            << " mpirun and -parallel (decomposePar is not needed)"
            << exit(FatalError);
    }
}


void Foam::caseChecks::fileNameCharacters
(
    const std::string& path,
    const std::string& what
)
{
    for (size_t i = 0; i < path.size(); ++i)
    {
        if (!fileName::valid(path[i]))
        {
            const char c = path[i];
            const std::string found =
                c == ' ' ? "a space" : c == '\t' ? "a tab"
              : c == '\n' ? "a newline" : c == '"' ? "a double quote"
              : c == '\'' ? "a single quote" : "a white-space character";
            FatalErrorInFunction
                << what.c_str() << " \"" << path.c_str() << "\" has "
                << found.c_str() << " (character " << label(i + 1)
                << "); OpenFOAM's file names allow no white space (spaces,"
                << " tabs, newlines) and no quotes (' \"): rename the"
                << " directory or choose a path without them"
                << exit(FatalError);
        }
    }
}


void Foam::caseChecks::fileNameEntry
(
    const dictionary& dict,
    const word& key,
    const std::string& what
)
{
    const entry* e = dict.findEntry(key, keyType::LITERAL);
    if (e && e->isStream())
    {
        const token path(e->stream());
        if (path.isStringType())
        {
            fileNameCharacters(path.stringToken(), what);
        }
    }
}


void Foam::caseChecks::caseNameCharacters(int argc, char* argv[])
{
    std::string path;
    if (char* cwd = ::getcwd(nullptr, 0))
    {
        path = cwd;
        std::free(cwd);
    }
    for (int i = 1; i + 1 < argc; ++i)
    {
        if (std::string(argv[i]) == "-case")
        {
            const std::string dir(argv[i + 1]);
            path = (!dir.empty() && dir[0] == '/') ? dir : path + "/" + dir;
        }
    }
    std::string application(argv[0]);
    application.erase(0, application.rfind('/') + 1);
    fileNameCharacters(path, application + ": the case path");
}


// ************************************************************************* //
