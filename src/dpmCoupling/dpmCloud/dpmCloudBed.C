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
    dpmCloud: how the particles start (constant/particleProperties
    initialBed): a restart state, listed positions, a saved bed that was made
    for these particles, or a new packing settled under gravity (saved for
    reuse). A saved bed records its recipe (counts per class, packing region,
    seed, settling; the DEM's state file) and a bed made otherwise is refused
    with the difference named, never taken silently.
\*---------------------------------------------------------------------------*/

#include "dpmCloud.H"
#include "mathematicalConstants.H"
#include "caseLock.H"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- A whole number written as one (no trailing characters)
bool readWhole(const std::string& text, label& value)
{
    errno = 0;
    char* end = nullptr;
    const long v = std::strtol(text.c_str(), &end, 10);
    if (*end != '\0' || errno != 0 || v < labelMin || v > labelMax) return false;
    value = label(v);
    return true;
}

//- A finite number written as one (no nan or inf, no trailing characters)
bool readFinite(const std::string& text, scalar& value)
{
    char* end = nullptr;
    value = std::strtod(text.c_str(), &end);
    return *end == '\0' && std::isfinite(value);
}

//- What a bed records, in the dictionary's words (after a refusal)
const char* const bedEntries =
    "    A bed is made for: each class's count (or massFraction and"
    " totalMass), diameter and density; contact; the mesh's box; g; deltaT;"
    " initialBed's seed, settleTime and packHeight (the packing region's"
    " height, by default from the counts)";

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::fileName Foam::dpmCloud::bedFile() const
{
    const dictionary& bed = dict_.subDict("initialBed");
    return bed.found("file") ? bed.get<fileName>("file").expand() : fileName();
}


dem::BedRecipe Foam::dpmCloud::bedRecipe() const
{
    const dictionary& bed = dict_.subDict("initialBed");
    dem::BedRecipe r;
    r.countPerClass = classCounts();
    const scalar width = grid_.xMax() - grid_.xMin();
    scalar area = 0;
    forAll(classNames_, k)
    {
        const scalar d = dem_->settings().classes[k].diameter;
        area += r.countPerClass[k]*constant::mathematical::pi*d*d/4;
    }
    const scalar filled =
        slab_ ? slabPackHeight(r.countPerClass) : 3*area/width;

    // The region holds at least one of the largest particles: a few
    // particles fill less than a row, so their default is one diameter
    label largest = 0;
    forAll(classNames_, k)
    {
        if
        (
            dem_->settings().classes[k].diameter
          > dem_->settings().classes[largest].diameter
        )
        {
            largest = k;
        }
    }
    const scalar dMax = dem_->settings().classes[largest].diameter;
    const scalar columnHeight = grid_.yMax() - grid_.yMin();
    if (width < dMax || columnHeight < dMax)
    {
        FatalIOErrorInFunction(dict_)
            << "The column of system/bedGeometry (width " << width
            << " m, height " << columnHeight << " m) is narrower than a"
            << " particle of class '" << classNames_[largest] << "' (d = "
            << dMax << " m, " << dict_.name() << "): make width and height"
            << " larger (then blockMesh) or the particles smaller"
            << exit(FatalIOError);
    }
    const scalar packHeight = bed.lookupOrDefault<scalar>
    (
        "packHeight", min(max(filled, dMax), columnHeight)
    );
    if (packHeight < dMax || packHeight > columnHeight)
    {
        FatalIOErrorInFunction(bed)
            << "Entry 'packHeight' = " << packHeight << " in initialBed of "
            << dict_.name() << " is outside the allowed range [" << dMax
            << ", " << columnHeight << "]: the packing region must hold a"
            << " particle of class '" << classNames_[largest] << "' (d = "
            << dMax << " m) and fit in the column (height " << columnHeight
            << " m, system/bedGeometry); set initialBed/packHeight in that"
            << " range, or leave it out (the default follows the counts)"
            << exit(FatalIOError);
    }
    r.region =
        dem::Box
        {
            grid_.xMin(), grid_.xMax(), grid_.yMin(), grid_.yMin() + packHeight
        };
    r.seed = std::uint64_t(bed.lookupOrDefault<label>("seed", 1));
    r.settleTime = bed.lookupOrDefault<scalar>("settleTime", 1.0);
    r.keTolerance = 0;
    return r;
}


void Foam::dpmCloud::checkBedOutput(const fileName& file) const
{
    try
    {
        dem::checkStatePath(file);
    }
    catch (const dem::Error& err)
    {
        FatalIOErrorInFunction(dict_)
            << "Cannot save the bed (initialBed/file of " << dict_.name()
            << ", or dpmPackBed -output): " << err.what() << nl
            << "    Nothing was packed: name a file in a writable directory"
            << exit(FatalIOError);
    }
}


void Foam::dpmCloud::packNewBed(const dem::BedRecipe& r)
{
    Info<< "Particles: packing";
    forAll(classNames_, k)
    {
        Info<< ' ' << r.countPerClass[k] << ' ' << classNames_[k];
    }
    Info<< " at random in " << r.region.xMax - r.region.xMin << " x "
        << r.region.yMax - r.region.yMin << " m (seed " << label(r.seed)
        << "), then " << r.settleTime << " s of settling" << endl;

    // A bed of 10^4 spheres settles for many minutes: say how far it is, every 0.1 s
    // of settling (the report does not change the bed).
    scalar nextReport = 0.1;
    const dem::SettleProgress progress = [&](double t, double ke)
    {
        if (t + 1e-9 < nextReport) return;
        Info<< "Particles: settling, " << t << " s of " << r.settleTime
            << ", kinetic energy per particle " << ke << " J" << endl;
        nextReport += 0.1;
    };
    guarded("Cannot pack the initial bed", [&]{ dem_->packBed(r, progress); });

    Info<< "Particles: settled, kinetic energy " << dem_->kineticEnergy()
        << " J, largest overlap " << dem_->maxOverlap() << " m" << endl;
}


Foam::dpmCloud::bedMatch Foam::dpmCloud::readBed
(
    const fileName& file,
    const dem::BedRecipe& r,
    std::string& problem
)
{
    try
    {
        if (dem_->loadBed(file, r))
        {
            warnUncheckedState();
            return bedMatch::made;
        }
        warnUncheckedState();
        problem =
            std::string
            (
                slab_
              ? "it carries no record of how it was packed (the slab mode's"
                " state file holds none yet)"
              : "it carries no record of how it was packed (a bed of an older"
                " dpmFoam2D, or particles not packed)"
            )
          + ": its counts per class match " + dict_.name() + ", its seed,"
            " settleTime and packHeight cannot be checked";
        return bedMatch::unrecorded;
    }
    catch (const dem::ForeignStateError& err)
    {
        problem = err.what() + std::string(": ") + foreignStateFix(err, false);
    }
    catch (const dem::Error& err)
    {
        problem = err.what();
    }
    return bedMatch::other;
}


void Foam::dpmCloud::initialise(const startMode mode)
{
    if (mode == startMode::pack)
    {
        return;     // dpmPackBed calls packBed
    }

    const fileName restart = stateFile(mesh_.time().timeName());
    if (isFile(restart))
    {
        try
        {
            dem_->load(restart);
        }
        catch (const dem::ForeignStateError& err)
        {
            FatalIOErrorInFunction(dict_)
                << "Cannot restart from " << restart << ": " << err.what()
                << ": " << foreignStateFix(err, true).c_str()
                << exit(FatalIOError);
        }
        catch (const dem::Error& err)
        {
            FatalIOErrorInFunction(dict_)
                << "Cannot read the particle state (settings in "
                << dict_.name() << "):" << nl << "    " << err.what()
                << exit(FatalIOError);
        }
        warnUncheckedState();
        if (mode == startMode::run && mesh_.time().value() > 0)
        {
            checkRestartModels(restart);    // time 0's bed has seen no gas
        }
        const dictionary& bed = dict_.subDict("initialBed");
        if (mode == startMode::run && dem_->recipe() && !bed.found("positions"))
        {
            // The particles of a packed bed: still the dictionary's mix?
            const std::string differ =
                dem::bedDifferences(dem_->settings(), *dem_->recipe(), bedRecipe());
            if (!differ.empty())
            {
                FatalIOErrorInFunction(dict_)
                    << "The particle state " << restart << " continues a bed"
                    << " made for other particles than " << dict_.name()
                    << " asks for: " << differ.c_str() << nl << bedEntries
                    << nl << "    To start the new mix, remove the time"
                    << " directories (and 0/uniform); else restore the entries"
                    << exit(FatalIOError);
            }
        }
        Info<< "Particles: " << size() << " read from " << restart << endl;
        return;
    }
    if (mode == startMode::postProcess && !hasParticleStates())
    {
        FatalErrorInFunction
            << "Nothing to post-process in " << mesh_.time().path()
            << ": no time directory has a particle state (uniform/dem.state);"
            << " the case has not been run. Run dpmFoam2D first"
            << exit(FatalError);
    }
    if (mode == startMode::postProcess)
    {
        // -postProcess reads the particles of the times a run saved
        FatalErrorInFunction
            << "No particle state " << restart << " for time "
            << mesh_.time().timeName() << ": -postProcess works on the times"
            << " a run has written" << nl << "    "
            << (
                   mesh_.time().value() > 0
                 ? "The time is incomplete (a run killed while writing it?):"
                   " leave it out (-time) or remove it"
                 : "Run dpmFoam2D first (or leave time 0 out with -time)"
               )
            << exit(FatalError);
    }
    if (mode == startMode::run && mesh_.time().value() > 0)
    {
        // A restart without particles (a new bed starts at time 0): the
        // run was killed while it wrote this time, or the state was removed
        FatalErrorInFunction
            << "No particle state " << restart << " for time "
            << mesh_.time().timeName() << nl
            << "    The time directory is incomplete (a run killed while"
            << " writing it?): remove it and restart from an earlier time"
            << exit(FatalError);
    }

    const dictionary& bed = dict_.subDict("initialBed");
    if (bed.found("positions"))
    {
        const fileName file = bed.get<fileName>("positions").expand();
        readPositions(file);
        Info<< "Particles: " << size() << " placed from " << file << endl;
        return;
    }

    const fileName file = bedFile();
    const dem::BedRecipe r = bedRecipe();
    if (!file.empty() && isFile(file))
    {
        std::string problem;
        const bedMatch match = readBed(file, r, problem);
        if (match == bedMatch::made)
        {
            Info<< "Particles: " << size() << " read from " << file
                << " (a bed made for these particles)" << endl;
            return;
        }
        if (match == bedMatch::other)
        {
            FatalIOErrorInFunction(dict_)
                << "Cannot start from initialBed/file of " << dict_.name()
                << ": " << problem.c_str() << nl << bedEntries << nl
                << "    Give initialBed/file a new path (the case packs a bed"
                << " there when it starts), or replace the bed with"
                << " dpmPackBed -overwrite (the cases that share it then"
                << " start from the new bed)" << exit(FatalIOError);
        }
        // An older bed whose counts match: used, with the caveat in the log
        WarningInFunction
            << "initialBed/file " << file << ": " << problem.c_str() << nl
            << "    dpmPackBed -overwrite makes a bed that carries its"
            << " record" << endl;
        Info<< "Particles: " << size() << " read from " << file << endl;
        return;
    }

    // Random well-mixed packing, then settling under gravity with no gas;
    // the bed's file is checked first, not after a long packing. A bed
    // shared by cases is locked while it is made, so that two cases
    // starting together do not both pack it
    autoPtr<caseLock> bedLock;
    if (!file.empty())
    {
        bedLock = caseLock::outsideCase
        (
            file.path(), mesh_.time().path(), program_invocation_short_name
        );
        checkBedOutput(file);
    }
    packNewBed(r);
    if (!file.empty())
    {
        save(file);
        Info<< "Particles: the settled bed saved to " << file
            << " for cases with the same particles" << endl;
    }
}


void Foam::dpmCloud::readPositions(const fileName& file)
{
    std::ifstream is(file);
    if (!is.good())
    {
        FatalIOErrorInFunction(dict_)
            << "Cannot read initialBed/positions " << file << " of "
            << dict_.name() << exit(FatalIOError);
    }
    auto bad = [&](const label lineNo, const std::string& what)
    {
        FatalIOErrorInFunction(dict_)
            << "initialBed/positions " << file << " line " << lineNo << ": "
            << what.c_str() << "; each line is "
            << (slab_ ? "'class x y [z]'" : "'class x y'")
            << " (class index, position in m"
            << (slab_ ? "; z the slab's mid-plane if left out" : "")
            << "), '#' starts a comment" << exit(FatalIOError);
    };

    std::string line;
    label lineNo = 0;
    while (std::getline(is, line))
    {
        ++lineNo;
        const auto hash = line.find('#');
        if (hash != std::string::npos) line.erase(hash);
        std::istringstream fields(line);
        std::vector<std::string> words;
        for (std::string w; fields >> w;) words.push_back(w);
        if (words.empty()) continue;        // blank or a comment

        const bool hasZ = slab_ && words.size() == 4;
        if (words.size() != 3 && !hasZ)
        {
            bad
            (
                lineNo,
                std::to_string(words.size()) + " fields, "
              + (slab_ ? "3 or 4" : "3")
              + " wanted"
            );
        }
        label classIndex = -1;
        if (!readWhole(words[0], classIndex))
        {
            bad(lineNo, "class '" + words[0] + "' is not a whole number");
        }
        if (classIndex < 0 || classIndex >= classNames_.size())
        {
            bad
            (
                lineNo,
                "class " + words[0] + " is outside [0, "
              + std::to_string(classNames_.size() - 1) + "]"
            );
        }
        scalar xy[3];
        for (label k = 0; k + 1 < label(words.size()); ++k)
        {
            if (!readFinite(words[k + 1], xy[k]))
            {
                bad
                (
                    lineNo,
                    std::string(1, "xyz"[k]) + " = '" + words[k + 1]
                  + "' is not a finite number"
                );
            }
        }
        if (slab_)
        {
            addListedSphere(classIndex, xy, hasZ);
            continue;
        }
        guarded
        (
            "Cannot place a particle of initialBed/positions",
            [&]{ dem_->addParticle(classIndex, xy[0], xy[1]); }
        );
    }
    if (!size())
    {
        FatalIOErrorInFunction(dict_)
            << "initialBed/positions " << file << " of " << dict_.name()
            << " lists no particle (" << lineNo << " lines, none 'class x y')"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::dpmCloud::packBed(const fileName& file, const bool overwrite)
{
    if (size())
    {
        FatalErrorInFunction
            << "packBed: the particles exist already (a cloud made with"
            << " startMode::pack packs)" << abort(FatalError);
    }
    checkBedOutput(file);
    const dem::BedRecipe r = bedRecipe();

    if (exists(file))
    {
        std::string problem;
        const bool same = readBed(file, r, problem) == bedMatch::made;
        if (same && !overwrite)
        {
            Info<< "The bed " << file << " was made for these particles and"
                << " settings already: kept as it is (dpmPackBed -overwrite"
                << " packs it anew)" << endl;
            return false;
        }
        if (!overwrite)
        {
            FatalErrorInFunction
                << "Not overwriting " << file << ": " << problem.c_str() << nl
                << bedEntries << nl
                << "    dpmPackBed -overwrite replaces it (the cases that share"
                << " it then start from the new bed); or save the new bed"
                << " elsewhere (-output <file>, or another initialBed/file)"
                << exit(FatalError);
        }
        // A bed read for the comparison is set aside for the new packing
        dem_.reset(new dem::Simulation(dem_->settings()));
        Info<< "Overwriting " << file << " (-overwrite): "
            << (same ? std::string("a bed for the same settings") : problem).c_str()
            << endl;
    }

    packNewBed(r);
    save(file);
    return true;
}


// ************************************************************************* //
