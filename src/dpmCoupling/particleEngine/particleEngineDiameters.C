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
    particleEngine: a class's diameters (one, or a distribution: a normal
    cut to bounds, or measured samples from a list or a file) and the
    statistics the coupling takes of them (docs/theory/dem.md, "Diameter
    distributions").
\*---------------------------------------------------------------------------*/

#include "particleEngine.H"
#include "positiveEntry.H"
#include "finiteNumber.H"
#include "mathematicalConstants.H"
#include "Time.H"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- The diameters of a samples file: numbers separated by white space,
//  '#' or '//' to the end of a line a comment; false (and the line in
//  badLine) at a word that is not a finite number (nan, inf and 1e400
//  too: a non-finite value traps at its first comparison)
bool readSamples
(
    std::istream& in,
    std::vector<double>& values,
    Foam::label& badLine,
    std::string& badWord
)
{
    std::string line;
    badLine = 0;
    for (Foam::label n = 1; std::getline(in, line); ++n)
    {
        const std::size_t hash = line.find('#');
        const std::size_t slashes = line.find("//");
        line = line.substr(0, std::min(hash, slashes));
        std::istringstream words(line);
        for (std::string word; words >> word;)
        {
            double v = 0;
            if (!Foam::readFiniteNumber(word, v))
            {
                badLine = n;
                badWord = word;
                return false;
            }
            values.push_back(v);
        }
    }
    return true;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

dem::ParticleClass Foam::particleEngine::readClass
(
    const dictionary& c,
    const word& name
) const
{
    dem::ParticleClass pc
    {
        name, 0, c.get<scalar>("density"),
        c.lookupOrDefault<scalar>("youngsModulus", 0),
        c.lookupOrDefault<scalar>("poissonRatio", 0)
    };
    const dictionary* dPtr = c.findDict("diameter", keyType::LITERAL);
    if (!dPtr)
    {
        pc.diameter = c.get<scalar>("diameter");
        return pc;
    }

    const dictionary& d = *dPtr;
    dem::DiameterDistribution& dist = pc.distribution;
    const word type = d.get<word>("distribution");
    if (type == "normal")
    {
        dist.type = dem::DiameterDistributionType::truncatedNormal;
        dist.standardDeviation = positiveEntry(d, "standardDeviation");
        dist.min = positiveEntry(d, "min");
        dist.max = boundedEntry(d, "max", dist.min, GREAT, true);
        dist.mean = boundedEntry(d, "mean", dist.min, dist.max, false);
    }
    else if (type == "samples")
    {
        dist.type = dem::DiameterDistributionType::samples;
        const scalar scale = positiveEntry(d, "scale", 1.0);
        if (d.found("values") == d.found("file"))
        {
            FatalIOErrorInFunction(d)
                << "Entry 'diameter' of class " << name << " in "
                << dict_.name() << " (distribution samples) takes exactly one"
                << " of 'values' (a list of diameters) and 'file' (a file of"
                << " them); it has " << (d.found("values") ? "both" : "neither")
                << exit(FatalIOError);
        }
        std::vector<double> values;
        if (d.found("values"))
        {
            const scalarList list(d.get<scalarList>("values"));
            values.assign(list.begin(), list.end());
        }
        else
        {
            fileName file(d.get<fileName>("file"));
            file.expand();
            if (!file.isAbsolute())
            {
                file = dict_.time().path()/file;   // the case's directory
            }
            if (isDir(file))
            {
                FatalIOErrorInFunction(d)
                    << "Entry 'file' of classes/" << name << "/diameter in "
                    << dict_.name() << ": " << file << " is a folder;"
                    << " allowed: a readable file of diameters, one or more"
                    << " a line" << exit(FatalIOError);
            }
            std::ifstream in(file);
            if (!in)
            {
                FatalIOErrorInFunction(d)
                    << "Entry 'file' of classes/" << name << "/diameter in "
                    << dict_.name() << ": cannot read " << file
                    << " (no such file, or not readable); allowed: a"
                    << " readable file of diameters, one or more a line"
                    << exit(FatalIOError);
            }
            label badLine = 0;
            std::string badWord;
            if (!readSamples(in, values, badLine, badWord))
            {
                FatalIOErrorInFunction(d)
                    << "Entry 'file' of classes/" << name << "/diameter in "
                    << dict_.name() << ": line " << badLine << " of " << file
                    << " holds '" << badWord.c_str() << "', not a finite number;"
                    << " allowed: diameters separated by white space, '#'"
                    << " comments" << exit(FatalIOError);
            }
        }
        const word from(d.found("values") ? "values" : "file");
        if (values.empty())
        {
            FatalIOErrorInFunction(d)
                << "Entry '" << from << "' of classes/" << name
                << "/diameter in " << dict_.name() << " holds no diameters;"
                << " allowed: at least one diameter > 0" << exit(FatalIOError);
        }
        // A diameter as wide as the bed is a unit mix-up (micrometres read
        // as metres), named here rather than by the DEM step's bound
        const scalar width = grid_.xMax() - grid_.xMin();
        for (std::size_t q = 0; q < values.size(); ++q)
        {
            values[q] *= scale;
            if (!std::isfinite(values[q]) || !(values[q] > 0))
            {
                FatalIOErrorInFunction(d)
                    << "Entry '" << from << "' of classes/" << name
                    << "/diameter in " << dict_.name() << ": diameter "
                    << label(q + 1) << " = " << values[q] << " m (scale "
                    << scale << ") is outside the allowed range (0, inf)"
                    << exit(FatalIOError);
            }
            if (values[q] >= width)
            {
                FatalIOErrorInFunction(d)
                    << "Entry '" << from << "' of classes/" << name
                    << "/diameter in " << dict_.name() << ": diameter "
                    << label(q + 1) << " = " << values[q] << " m (scale "
                    << scale << ") is not below the bed's width " << width
                    << " m; samples in micrometres need 'scale 1e-6'"
                    << exit(FatalIOError);
            }
        }
        dist.samples = values;
    }
    else
    {
        FatalIOErrorInFunction(d)
            << "Entry 'distribution' = " << type << " of classes/" << name
            << "/diameter in " << dict_.name() << " is not a distribution;"
            << " allowed: normal, samples (or 'diameter' one number)"
            << exit(FatalIOError);
    }
    // What is left: a normal with almost none of it between its bounds
    try
    {
        dem::validateDistribution(dist, "classes/" + std::string(name));
    }
    catch (const dem::Error& err)
    {
        FatalIOErrorInFunction(d)
            << "Entry 'diameter' of class " << name << " in " << dict_.name()
            << ": " << err.what() << exit(FatalIOError);
    }
    // The class's diameter in the settings' record and the checks that
    // take one: its number mean
    pc.diameter = dem::meanDiameter(pc);
    return pc;
}


void Foam::particleEngine::reportDiameters(const dem::Settings& settings)
{
    for (const dem::ParticleClass& c : settings.classes)
    {
        const dem::DiameterDistribution& d = c.distribution;
        if (d.type == dem::DiameterDistributionType::single)
        {
            continue;
        }
        Info<< "Particles: class " << c.name.c_str() << " diameters ";
        if (d.type == dem::DiameterDistributionType::truncatedNormal)
        {
            Info<< "normal (mean " << d.mean << " m, standard deviation "
                << d.standardDeviation << " m) cut to [" << d.min << ", "
                << d.max << "] m";
        }
        else
        {
            Info<< "drawn from " << label(d.samples.size()) << " samples in ["
                << dem::smallestDiameter(c) << ", " << dem::largestDiameter(c)
                << "] m";
        }
        Info<< ": number mean " << dem::meanDiameter(c) << " m (its contact"
            << " laws'), standard deviation "
            << dem::diameterStandardDeviation(c) << " m, Sauter mean "
            << dem::sauterDiameter(c) << " m (the correlations'), volume"
            << " mean " << dem::volumeMeanDiameter(c) << " m" << endl;
    }
}


Foam::scalarList Foam::particleEngine::diametersOf(const dem::Settings& settings)
{
    scalarList d(settings.classes.size());
    forAll(d, k) d[k] = dem::sauterDiameter(settings.classes[k]);
    return d;
}


Foam::scalarList Foam::particleEngine::largestDiametersOf
(
    const dem::Settings& settings
)
{
    scalarList d(settings.classes.size());
    forAll(d, k) d[k] = dem::largestDiameter(settings.classes[k]);
    return d;
}


Foam::scalarList Foam::particleEngine::classDiameters() const
{
    return diametersOf(dem_->settings());
}


Foam::scalarList Foam::particleEngine::classVolumeDiameters() const
{
    const dem::Settings& s = dem_->settings();
    scalarList d(s.classes.size());
    forAll(d, k) d[k] = dem::volumeMeanDiameter(s.classes[k]);
    return d;
}


Foam::scalarList Foam::particleEngine::classDiameterMoments
(
    const dem::Settings& settings,
    const label p
)
{
    scalarList m(settings.classes.size());
    forAll(m, k)
    {
        const dem::ParticleClass& c = settings.classes[k];
        m[k] =
            c.distribution.type == dem::DiameterDistributionType::single
          ? (p == 2 ? sqr(c.diameter) : pow3(c.diameter))
          : dem::diameterMoment(c, int(p));
    }
    return m;
}


// ************************************************************************* //
