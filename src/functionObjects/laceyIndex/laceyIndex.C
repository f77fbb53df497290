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
    laceyIndex function object: see laceyIndex.H
\*---------------------------------------------------------------------------*/

#include "laceyIndex.H"
#include "cloudFunctionObject.H"
#include "addToRunTimeSelectionTable.H"
#include "knownEntries.H"

#include <cmath>
#include <stdexcept>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(laceyIndex, 0);
    addToRunTimeSelectionTable(functionObject, laceyIndex, dictionary);
}
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- One corner of the box: (x y) or (x y z), z ignored
mixing::Region readCorner
(
    const dictionary& dict,
    ITstream& is,
    const char* which
)
{
    scalarList corner;
    is >> corner;
    if (corner.size() != 2 && corner.size() != 3)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'box' in " << dict.name() << ": the " << which
            << " corner " << corner << " has " << corner.size()
            << " components; allowed: box (xMin yMin) (xMax yMax),"
            << " a z component is ignored" << exit(FatalIOError);
    }
    mixing::Region r;
    r.xMin = r.xMax = corner[0];
    r.yMin = r.yMax = corner[1];
    return r;
}

} // End anonymous namespace


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

const Foam::dpmCloud& Foam::functionObjects::laceyIndex::cloud() const
{
    return cloudFunctionObject::find(mesh_, cloudName_, dict_);
}


void Foam::functionObjects::laceyIndex::calculate(const dpmCloud& cloud)
{
    // A class of a diameter distribution counts as particles of its mean
    // volume: its volume-mean diameter E[d^3]^(1/3)
    const scalarList& diameters = cloud.classVolumeDiameters();
    if (diameters.size() != 2)
    {
        FatalIOErrorInFunction(dict_)
            << "laceyIndex " << name() << " (" << dict_.name() << ")"
            << " needs exactly two particle size classes (small and large),"
            << " for the Lacey index of a binary mixture; cloud '"
            << cloudName_ << "' has " << diameters.size() << ": "
            << cloud.classNames() << " with diameters " << diameters
            << ". Allowed: two classes in constant/particleProperties."
            << exit(FatalIOError);
    }

    const dem::Simulation& particles = cloud.particles();
    const std::vector<double> classDiameters(diameters.begin(), diameters.end());

    // The bed's bounds unless a box is given
    mixing::LaceySettings settings(settings_);
    if (!settings.useRegion)
    {
        const gasGrid& grid = cloud.grid();
        settings.useRegion = true;
        settings.region = {grid.xMin(), grid.xMax(), grid.yMin(), grid.yMax()};
    }

    try
    {
        lacey_ = mixing::laceyIndex
        (
            particles.size(), particles.x(), particles.y(),
            particles.classIndex(), classDiameters, settings
        );
        segregation_ = mixing::segregationIndices
        (
            particles.size(), particles.x(), particles.y(),
            particles.classIndex(), classDiameters, &settings.region
        );
    }
    catch (const std::invalid_argument& err)
    {
        FatalIOErrorInFunction(dict_)
            << "laceyIndex " << name() << " (" << dict_.name() << "): "
            << err.what() << exit(FatalIOError);
    }

    settings_.region = settings.region;
}


void Foam::functionObjects::laceyIndex::createFiles()
{
    if (!writeToFile() || laceyFile_.valid())
    {
        return;
    }

    laceyFile_ = createFile("laceyIndex");
    segregationFile_ = createFile("segregation");

    const mixing::Region& r = settings_.region;
    const string region
    (
        "(" + Foam::name(r.xMin) + " " + Foam::name(r.yMin) + ") ("
      + Foam::name(r.xMax) + " " + Foam::name(r.yMax) + ")"
    );

    // A table of -postProcess says so: readers keep it apart from the run's
    // (dpmfoam2d.tables.read_postprocessing)
    const char* recomputed =
        "recomputed after the run (dpmFoam2D -postProcess) at the saved times";

    OFstream& lacey = laceyFile_();
    writeHeader(lacey, "Lacey mixing index (Norouzi et al. 2012, eqs 8-11)");
    if (functionObject::postProcess)
    {
        writeHeaderValue(lacey, "postProcess", recomputed);
    }
    writeHeaderValue(lacey, "cloud", cloudName_.c_str());
    writeHeaderValue
    (
        lacey,
        "varianceBasis",
        settings_.basis == mixing::VarianceBasis::wholeBed
      ? "wholeBed (N = equivalent particles in the region)"
      : "perSample (N = mean equivalent particles per occupied cell)"
    );
    writeHeaderValue
    (
        lacey,
        "equivalent particles per large one (d_large/d_small)^3",
        lacey_.weightLarge
    );
    writeHeaderValue(lacey, "cellSize [m]", settings_.cellSize);
    writeHeaderValue(lacey, "region [m]", region.c_str());
    writeCommented(lacey, "Time");
    for (const char* column : {"M", "S2", "S02", "SR2", "nCells"})
    {
        writeTabbed(lacey, column);
    }
    lacey << endl;

    OFstream& seg = segregationFile_();
    writeHeader
    (
        seg,
        "Segregation indices: mean height h above the floor and mean"
        " distance r from the centre line per class;"
        " vertical = (hSmall - hLarge)/hAll,"
        " horizontal = (rSmall - rLarge)/rAll"
    );
    if (functionObject::postProcess)
    {
        writeHeaderValue(seg, "postProcess", recomputed);
    }
    writeHeaderValue(seg, "cloud", cloudName_.c_str());
    writeHeaderValue(seg, "region [m]", region.c_str());
    writeCommented(seg, "Time");
    for
    (
        const char* column
      : {"hSmall", "hLarge", "vertical", "rSmall", "rLarge", "horizontal"}
    )
    {
        writeTabbed(seg, column);
    }
    seg << endl;
}


void Foam::functionObjects::laceyIndex::writeValue
(
    Ostream& os,
    const scalar value
) const
{
    os  << tab << setw(charWidth());
    if (std::isfinite(value))
    {
        os  << value;
    }
    else
    {
        os  << "nan";
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::laceyIndex::laceyIndex
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
    settings_()
{
    read(dict);

    // In a run the object is built when the time loop starts: record the
    // start state. (After the fact the solver builds the cloud per time.)
    if (!functionObject::postProcess && mesh_.foundObject<dpmCloud>(cloudName_))
    {
        write();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::laceyIndex::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);
    dict_ = dict;

    // Its own entries, and those every function object may have (v1912's
    // functionObject, timeControl, regionFunctionObject, writeFile)
    static const wordList known{"cloud", "cellSize", "box", "varianceBasis"};
    static const wordHashSet common(cloudFunctionObject::commonEntries(true));
    checkKnownEntries
    (
        dict, known, "function object '" + name() + "' (type laceyIndex)",
        common, "and those of every function object: type libs writeControl"
        " writeInterval timeStart timeEnd log writePrecision writeToFile ..."
    );

    cloudName_ = dict.lookupOrDefault<word>("cloud", "particles");

    settings_ = mixing::LaceySettings();
    settings_.cellSize = dict.lookupOrDefault<scalar>("cellSize", 5e-3);
    if (!(settings_.cellSize > 0) || !std::isfinite(settings_.cellSize))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'cellSize' = " << settings_.cellSize << " in "
            << dict.name() << "; allowed: a sampling cell size > 0 (m),"
            << " default 5e-3" << exit(FatalIOError);
    }

    if (dict.found("box"))
    {
        ITstream& is = dict.lookup("box");
        const mixing::Region lower = readCorner(dict, is, "lower-left");
        const mixing::Region upper = readCorner(dict, is, "upper-right");
        if (is.nRemainingTokens())
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'box' in " << dict.name() << " has more than"
                << " two corners; allowed: box (xMin yMin) (xMax yMax)"
                << exit(FatalIOError);
        }
        settings_.useRegion = true;
        settings_.region = {lower.xMin, upper.xMax, lower.yMin, upper.yMax};
        if
        (
            !(settings_.region.xMax > settings_.region.xMin)
         || !(settings_.region.yMax > settings_.region.yMin)
        )
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'box' in " << dict.name() << " is empty: "
                << "lower-left (" << lower.xMin << " " << lower.yMin
                << "), upper-right (" << upper.xMax << " " << upper.yMax
                << "); allowed: box (xMin yMin) (xMax yMax) with"
                << " xMin < xMax and yMin < yMax" << exit(FatalIOError);
        }
    }

    const word basis = dict.lookupOrDefault<word>("varianceBasis", "wholeBed");
    try
    {
        settings_.basis = mixing::varianceBasisFromString(basis.c_str());
    }
    catch (const std::invalid_argument&)
    {
        FatalIOErrorInFunction(dict)
            << "Unknown varianceBasis '" << basis << "' in " << dict.name()
            << "; allowed: wholeBed (N = equivalent particles in the whole"
            << " region, the paper's, default) or perSample (N = mean"
            << " equivalent particles per occupied cell, Lacey's)"
            << exit(FatalIOError);
    }

    return true;
}


bool Foam::functionObjects::laceyIndex::execute()
{
    return true;
}


bool Foam::functionObjects::laceyIndex::write()
{
    calculate(cloud());
    createFiles();

    if (laceyFile_.valid())
    {
        OFstream& lacey = laceyFile_();
        lacey << setw(charWidth()) << Time::timeName(time_.timeOutputValue());
        for (const scalar v : {lacey_.M, lacey_.S2, lacey_.S02, lacey_.SR2})
        {
            writeValue(lacey, v);
        }
        lacey << tab << setw(charWidth()) << label(lacey_.nCells) << endl;

        const mixing::SegregationResult& s = segregation_;
        OFstream& seg = segregationFile_();
        seg << setw(charWidth()) << Time::timeName(time_.timeOutputValue());
        for
        (
            const scalar v
          : {s.hSmall, s.hLarge, s.vertical, s.rSmall, s.rLarge, s.horizontal}
        )
        {
            writeValue(seg, v);
        }
        seg << endl;
    }

    Log << type() << ' ' << name() << ": t = " << time_.timeName()
        << ", M = " << lacey_.M << " (" << mixing::toString(settings_.basis)
        << ", " << label(lacey_.nCells) << " cells), vertical "
        << segregation_.vertical << ", horizontal "
        << segregation_.horizontal << endl;

    return true;
}


// ************************************************************************* //
