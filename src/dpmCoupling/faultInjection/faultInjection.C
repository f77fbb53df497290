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
#include "OSspecific.H"
#include "OStringStream.H"

#include <csignal>
#include <cstdlib>
#include <fstream>
#include <map>
#include <string>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

struct faultSpec
{
    std::string point;
    long n = 0;
    Foam::faultInjection::action what = Foam::faultInjection::action::none;
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
        f.what = how == "stop"
            ? Foam::faultInjection::action::stop
            : Foam::faultInjection::action::kill;
        return f;
    }();
    return s;
}


//- Written with the gas fields (AUTO_WRITE); acts when fieldWrite is due
class fieldWriteFault
:
    public Foam::regIOobject
{
public:

    fieldWriteFault(const Foam::fvMesh& mesh)
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
        using namespace Foam;
        const faultInjection::action a = faultInjection::due("fieldWrite");
        if (a == faultInjection::action::stop)
        {
            faultInjection::stop();
        }
        else if (a == faultInjection::action::kill)
        {
            // A half-written p_rgh, as a kill in the middle of it leaves
            const regIOobject& p = db().lookupObject<regIOobject>("p_rgh");
            OStringStream os;
            p.writeHeader(os);
            p.writeData(os);
            const std::string text = os.str();
            const fileName dir = time().timePath();
            mkDir(dir);
            std::ofstream(dir/"p_rgh", std::ios::trunc)
                << text.substr(0, text.size()/2) << std::flush;
            faultInjection::kill();
        }
        return true;
    }

    bool writeData(Foam::Ostream&) const override { return true; }
};

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::faultInjection::action Foam::faultInjection::due(const char* point)
{
    const faultSpec& f = spec();
    if (f.what == action::none || f.point != point) return action::none;
    static std::map<std::string, long> calls;
    return ++calls[point] == f.n ? f.what : action::none;
}


void Foam::faultInjection::kill()
{
    std::raise(SIGKILL);
    std::abort();       // not reached
}


void Foam::faultInjection::stop()
{
    std::raise(SIGSTOP);
}


void Foam::faultInjection::watchFieldWrite(const fvMesh& mesh)
{
    if (spec().point == "fieldWrite")
    {
        regIOobject::store(new fieldWriteFault(mesh));
    }
}


// ************************************************************************* //
