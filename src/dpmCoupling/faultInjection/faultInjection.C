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

#include "faultInjection.H"
#include "dem/WritePoints.hpp"

#include <csignal>
#include <cstdlib>
#include <map>
#include <string>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

enum class action { none, kill, stop };

struct faultSpec
{
    std::string point;
    long n = 0;
    action what = action::none;
};

//- DPMFOAM2D_FAULT parsed once
const faultSpec& spec()
{
    static const faultSpec s = []
    {
        faultSpec f;
        const char* env = std::getenv("DPMFOAM2D_FAULT");
        if (!env || !*env) return f;
        const std::string v(env);
        const auto c1 = v.find(':');
        if (c1 == std::string::npos) return f;
        const auto c2 = v.find(':', c1 + 1);
        f.point = v.substr(0, c1);
        f.n = std::atol(v.substr(c1 + 1, c2 - c1 - 1).c_str());
        const std::string how = c2 == std::string::npos ? "" : v.substr(c2 + 1);
        f.what = how == "stop" ? action::stop : action::kill;
        return f;
    }();
    return s;
}


//- Does the armed point start with prefix?
bool armedUnder(const std::string& prefix)
{
    const faultSpec& f = spec();
    return
        f.what != action::none
     && f.point.compare(0, prefix.size(), prefix) == 0;
}


//- The DEM state writer's hook (dem/WritePoints.hpp)
void atDemPoint(const char* point)
{
    Foam::faultInjection::at(point);
}


//- Written with the gas fields (AUTO_WRITE): passes fieldWrite meanwhile
class fieldWritePoint
:
    public Foam::regIOobject
{
public:

    fieldWritePoint(const Foam::fvMesh& mesh)
    :
        regIOobject
        (
            Foam::IOobject
            (
                "faultInjection", mesh.time().timeName(), mesh,
                Foam::IOobject::NO_READ, Foam::IOobject::AUTO_WRITE
            )
        )
    {}

    bool writeObject
    (
        Foam::IOstream::streamFormat, Foam::IOstream::versionNumber,
        Foam::IOstream::compressionType, const bool
    ) const override
    {
        Foam::faultInjection::at("fieldWrite");
        return true;
    }

    bool writeData(Foam::Ostream&) const override { return true; }
};

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::faultInjection::at(const char* point, const char* stage)
{
    const faultSpec& f = spec();
    if (f.what == action::none) return;
    const std::string name =
        stage ? std::string(point) + '.' + stage : std::string(point);
    if (f.point != name) return;
    static long calls = 0;
    if (++calls != f.n) return;
    if (f.what == action::stop)
    {
        std::raise(SIGSTOP);
    }
    else
    {
        std::raise(SIGKILL);
        std::abort();       // not reached
    }
}


void Foam::faultInjection::install(const fvMesh& mesh)
{
    if (armedUnder("fieldWrite"))
    {
        regIOobject::store(new fieldWritePoint(mesh));
    }
    if (armedUnder("stateWrite."))
    {
        dem::setWritePointHook(atDemPoint);
    }
}


// ************************************************************************* //
