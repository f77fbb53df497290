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
    caseChecks::writesInsideCase: the folders the project's writers write
    into resolve inside their case (docs/user-guide/output.md, "Links").
\*---------------------------------------------------------------------------*/

#include "caseChecks.H"

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>

#include <sys/stat.h>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- The path with every link resolved, or empty where it cannot be (a
//  link to nothing among them too: what is made through it lands where it
//  points); of a path not made yet, its nearest existing folder's
std::string resolved(const Foam::fileName& path)
{
    char buffer[PATH_MAX];
    for (Foam::fileName p = path; !p.empty() && p != "/"; p = p.path())
    {
        if (::realpath(p.c_str(), buffer)) return std::string(buffer);
        struct stat link;
        if (errno != ENOENT || ::lstat(p.c_str(), &link) == 0)
        {
            return std::string();
        }
    }
    return std::string();
}


//- The refusal of a writer's folder outside the case, or empty
std::string outsideCase
(
    const Foam::fileName& dir,
    const Foam::fileName& caseDir,
    const std::string& writer
)
{
    const std::string where = resolved(dir);
    const std::string top = resolved(caseDir);
    if (where.empty() || top.empty())
    {
        return
            writer + ": cannot resolve " + dir + " (" + std::strerror(errno)
          + "; a symbolic link to nothing on its way?); a run writes only"
            " inside its case";
    }
    if (where == top || where.compare(0, top.size() + 1, top + "/") == 0)
    {
        return std::string();
    }
    return
        writer + ": " + dir + " resolves to " + where + ", outside the case "
      + top + " (a symbolic link); a run writes only inside its case: remove"
        " the link, and copy or move the files after the run";
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::caseChecks::writesInsideCase
(
    const fileName& dir,
    const fileName& caseDir,
    const std::string& writer
)
{
    const std::string problem = outsideCase(dir, caseDir, writer);
    if (!problem.empty())
    {
        FatalErrorInFunction << problem.c_str() << exit(FatalError);
    }
}


void Foam::caseChecks::writesInsideCase
(
    const fileName& dir,
    const fileName& caseDir,
    const std::string& writer,
    const dictionary& dict
)
{
    const std::string problem = outsideCase(dir, caseDir, writer);
    if (!problem.empty())
    {
        FatalIOErrorInFunction(dict) << problem.c_str() << exit(FatalIOError);
    }
}


// ************************************************************************* //
