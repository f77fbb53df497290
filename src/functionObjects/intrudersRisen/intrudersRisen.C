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
    intrudersRisen function object: see intrudersRisen.H
\*---------------------------------------------------------------------------*/

#include "intrudersRisen.H"
#include "cloudFunctionObject.H"
#include "addToRunTimeSelectionTable.H"
#include "knownEntries.H"
#include "caseChecks.H"

#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(intrudersRisen, 0);
    addToRunTimeSelectionTable(functionObject, intrudersRisen, dictionary);
}
}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

double Foam::functionObjects::intrudersRisen::surfaceHeight
(
    std::vector<float>& heights,
    const double q
)
{
    const std::size_t n = heights.size();
    if (n == 0)
    {
        return std::nan("");
    }
    const double index = double(n - 1)*q;
    if (index >= double(n - 1))
    {
        return *std::max_element(heights.begin(), heights.end());
    }
    const std::size_t below = std::size_t(std::floor(index));
    std::nth_element(heights.begin(), heights.begin() + below, heights.end());
    const float a = heights[below];
    const float b =
        *std::min_element(heights.begin() + below + 1, heights.end());
    const double gamma = index - double(below);
    const float diff = b - a;       // in single precision, as numpy does

    // numpy's _lerp: from the nearer end
    return gamma >= 0.5 ? b - double(diff)*(1 - gamma) : a + double(diff)*gamma;
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

const Foam::dpmCloud& Foam::functionObjects::intrudersRisen::cloud() const
{
    return cloudFunctionObject::find(mesh_, cloudName_, dict_);
}


void Foam::functionObjects::intrudersRisen::sample()
{
    const dpmCloud& particles = cloud();
    const scalar t = time_.value();
    if (!particles.particleFileDue() || t == lastSample_)
    {
        return;
    }
    lastSample_ = t;

    const label cls = particles.classNames().find(className_);
    if (cls < 0)
    {
        FatalIOErrorInFunction(dict_)
            << "Entry 'class' = " << className_ << " in " << dict_.name()
            << ": not a class of cloud '" << cloudName_ << "'; allowed: "
            << particles.classNames() << exit(FatalIOError);
    }

    const dem::Simulation& dem = particles.particles();
    const std::size_t n = dem.size();
    const double* y = dem.y();
    const int* classIndex = dem.classIndex();

    bedHeights_.clear();
    for (std::size_t i = 0; i < n; ++i)
    {
        if (classIndex[i] != cls)
        {
            bedHeights_.push_back(float(y[i]));
        }
    }
    const double surface = surfaceHeight(bedHeights_, fraction_);

    const std::int64_t* id = dem.id();
    label total = 0;
    label atSurface = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
        if (classIndex[i] == cls)
        {
            ++total;
            if (double(float(y[i])) >= surface)
            {
                ++atSurface;
                risen_.insert(label(id[i]));
            }
        }
    }
    const label risen = risen_.size();
    const bool allRisen = total > 0 && risen == total;

    // Kept with each written time (uniform/functionObjects/
    // functionObjectProperties), so that a restart knows who had risen
    setProperty("risen", risen_.sortedToc());

    if (writeToFile())
    {
        if (!file_.valid())
        {
            caseChecks::writesInsideCase
            (
                baseTimeDir(), time_.path(), "intrudersRisen", dict_
            );
            file_ = createFile("intrudersRisen");
            OFstream& os = file_();
            writeHeader
            (
                os,
                "Particles of class " + className_ + " at or above the"
                " bed's surface, at the particle files' times"
            );
            writeHeaderValue
            (
                os,
                "surface",
                "the height below which the fraction q of the other"
                " particles' centres lie (m)"
            );
            writeHeaderValue(os, "q", fraction_);
            writeCommented(os, "Time");
            for (const char* column : {"surface", "atSurface", "risen", "n"})
            {
                writeTabbed(os, column);
            }
            os  << endl;
        }
        OFstream& os = file_();
        os  << setw(charWidth()) << time_.timeName()
            << tab << setw(charWidth()) << surface
            << tab << setw(charWidth()) << atSurface
            << tab << setw(charWidth()) << risen
            << tab << setw(charWidth()) << total << endl;
    }

    Log << type() << ' ' << name() << ": t = " << time_.timeName() << ", "
        << atSurface << " of " << total << ' ' << className_
        << " at or above the surface " << surface << " m (q " << fraction_
        << "), " << risen << " risen so far" << endl;

    if (allRisen && endRun_ && cloudFunctionObject::endAfterNextStep(time_))
    {
        Info<< type() << ' ' << name() << ": every " << className_
            << " has risen to the surface (q " << fraction_ << ") by t = "
            << time_.timeName() << "; ending the run after one more step"
            << endl;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::intrudersRisen::intrudersRisen
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
    className_(),
    fraction_(0.999),
    endRun_(true),
    lastSample_(-GREAT),
    risen_()
{
    read(dict);

    // Who had risen before a restart, then the start's own particle file
    labelList risen;
    if (getProperty("risen", risen))
    {
        risen_.insert(risen);
    }
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

bool Foam::functionObjects::intrudersRisen::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);
    dict_ = dict;

    static const wordList known{"cloud", "class", "fraction", "endRun"};
    static const wordHashSet common(cloudFunctionObject::commonEntries(false));
    checkKnownEntries
    (
        dict, known, "function object '" + name() + "' (type intrudersRisen)",
        common, "and those of every function object: type libs timeStart"
        " timeEnd log writePrecision writeToFile ..."
    );

    cloudName_ = dict.lookupOrDefault<word>("cloud", "particles");
    if (!dict.found("class"))
    {
        FatalIOErrorInFunction(dict)
            << "No entry 'class' in " << dict.name() << ": the class that"
            << " rises, by its name in constant/particleProperties"
            << " (e.g. class intruder;)" << exit(FatalIOError);
    }
    className_ = dict.get<word>("class");

    fraction_ = dict.lookupOrDefault<scalar>("fraction", 0.999);
    if (!(fraction_ > 0 && fraction_ < 1))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'fraction' = " << fraction_ << " in " << dict.name()
            << "; allowed: the bed's fraction below the surface, in (0, 1),"
            << " default 0.999" << exit(FatalIOError);
    }
    endRun_ = dict.lookupOrDefault<bool>("endRun", true);

    return true;
}


bool Foam::functionObjects::intrudersRisen::execute()
{
    if (!functionObject::postProcess)
    {
        sample();
    }
    return true;
}


bool Foam::functionObjects::intrudersRisen::write()
{
    return true;
}


// ************************************************************************* //
