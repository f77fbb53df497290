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
    bedAtRest function object: see bedAtRest.H
\*---------------------------------------------------------------------------*/

#include "bedAtRest.H"
#include "cloudFunctionObject.H"
#include "addToRunTimeSelectionTable.H"
#include "knownEntries.H"
#include "caseChecks.H"

#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(bedAtRest, 0);
    addToRunTimeSelectionTable(functionObject, bedAtRest, dictionary);
}
}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::scalar Foam::functionObjects::bedAtRest::bedSpeed
(
    const scalar kineticEnergy,
    const scalar mass
)
{
    return mass > 0 ? std::sqrt(2*kineticEnergy/mass) : 0;
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::functionObjects::bedAtRest::sample()
{
    const dpmCloud& particles =
        cloudFunctionObject::find(mesh_, cloudName_, dict_);
    const scalar t = time_.value();
    if (!particles.particleFileDue() || t == lastSample_)
    {
        return;
    }
    lastSample_ = t;

    const dem::Simulation& dem = particles.particles();
    const double* m = dem.mass();
    double mass = 0;
    for (std::size_t i = 0; i < dem.size(); ++i)
    {
        mass += m[i];
    }
    const scalar speed = bedSpeed(dem.kineticEnergy(), mass);

    if (speed >= speed_)
    {
        restSince_ = -1;
    }
    else if (restSince_ < 0)
    {
        restSince_ = t;
    }

    // Kept with each written time, so that a restart knows since when
    setProperty("restSince", restSince_);

    if (writeToFile())
    {
        if (!file_.valid())
        {
            caseChecks::writesInsideCase
            (
                baseTimeDir(), time_.path(), "bedAtRest", dict_
            );
            file_ = createFile("bedAtRest");
            OFstream& os = file_();
            writeHeader
            (
                os,
                "The bed's speed sqrt(2 E_k/M) at the particle files' times"
            );
            writeHeaderValue(os, "speed below which at rest (m/s)", speed_);
            writeHeaderValue(os, "duration (s)", duration_);
            writeCommented(os, "Time");
            writeTabbed(os, "speed");
            writeTabbed(os, "restSince");
            os  << endl;
        }
        OFstream& os = file_();
        os  << setw(charWidth()) << time_.timeName()
            << tab << setw(charWidth()) << speed
            << tab << setw(charWidth()) << restSince_ << endl;
    }

    Log << type() << ' ' << name() << ": t = " << time_.timeName()
        << ", the bed's speed " << speed << " m/s";
    if (restSince_ >= 0)
    {
        Log << ", at rest (below " << speed_ << " m/s) since t = "
            << restSince_;
    }
    Log << endl;

    // Half a step's tolerance: the sample times are sums of steps
    const scalar halfStep = 0.5*time_.deltaTValue();
    if
    (
        restSince_ >= 0 && t - restSince_ >= duration_ - halfStep
     && endRun_ && cloudFunctionObject::endAfterNextStep(time_)
    )
    {
        Info<< type() << ' ' << name() << ": the bed has been at rest"
            << " (its speed below " << speed_ << " m/s) since t = "
            << restSince_ << ", for " << duration_ << " s by t = "
            << time_.timeName() << "; ending the run after one more step"
            << endl;
    }
}


Foam::scalar Foam::functionObjects::bedAtRest::readPositive
(
    const dictionary& dict,
    const word& entry,
    const scalar deflt,
    const char* meaning
) const
{
    const scalar value = dict.lookupOrDefault<scalar>(entry, deflt);
    if (!(value > 0 && std::isfinite(value)))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << entry << "' = " << value << " in " << dict.name()
            << "; allowed: " << meaning << ", > 0, default " << deflt
            << exit(FatalIOError);
    }
    return value;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::bedAtRest::bedAtRest
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, typeName, true),
    dict_(dict),
    cloudName_("particles"),
    speed_(0.01),
    duration_(2),
    endRun_(true),
    lastSample_(-GREAT),
    restSince_(-1)
{
    read(dict);

    // Since when the bed was at rest before a restart, then the start's
    // own particle file
    getProperty("restSince", restSince_);
    if
    (
        cloudFunctionObject::samplesStart
        (
            mesh_, cloudName_, dict, runTime.value()
        )
    )
    {
        sample();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::bedAtRest::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);
    dict_ = dict;

    static const wordList known{"cloud", "speed", "duration", "endRun"};
    static const wordHashSet common(cloudFunctionObject::commonEntries(false));
    checkKnownEntries
    (
        dict, known, "function object '" + name() + "' (type bedAtRest)",
        common, "and those of every function object: type libs timeStart"
        " timeEnd log writePrecision writeToFile ..."
    );

    cloudName_ = dict.lookupOrDefault<word>("cloud", "particles");
    speed_ = readPositive
    (
        dict, "speed", 0.01, "the bed's speed below which it is at rest, m/s"
    );
    duration_ = readPositive
    (
        dict, "duration", 2, "how long the bed stays at rest before the run"
        " ends, s"
    );
    endRun_ = dict.lookupOrDefault<bool>("endRun", true);

    return true;
}


bool Foam::functionObjects::bedAtRest::execute()
{
    if (!functionObject::postProcess)
    {
        sample();
    }
    return true;
}


bool Foam::functionObjects::bedAtRest::write()
{
    return true;
}


// ************************************************************************* //
