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
    packedBed: the bed's packing, saved beds and their matching.
\*---------------------------------------------------------------------------*/

#include "packedBed.H"
#include "caseLock.H"
#include "caseChecks.H"

#include <cerrno>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- What a bed records, in the dictionary's words (after a refusal)
const char* const bedEntries =
    "    A bed is made for: each class's count (or massFraction and"
    " totalMass), diameter (or its distribution) and density; contact; the"
    " mesh's box; g; deltaT; initialBed's seed, settleTime, settleFriction,"
    " packHeight (the packing region's height, by default from the counts)"
    " and place (the particles laid first)";

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::packedBed::packedBed
(
    const IOdictionary& dict,
    const gasGrid& grid,
    const wordList& classNames,
    particleEngine& engine,
    const bool slab,
    const fileName& casePath
)
:
    dict_(dict),
    grid_(grid),
    classNames_(classNames),
    engine_(engine),
    slab_(slab),
    casePath_(casePath)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::fileName Foam::packedBed::bedFile() const
{
    const dictionary& bed = dict_.subDict("initialBed");
    if (!bed.found("file"))
    {
        return fileName();
    }
    caseChecks::fileNameEntry
    (
        bed, "file", "Entry 'file' of initialBed in " + dict_.name()
    );
    return bed.get<fileName>("file").expand();
}


void Foam::packedBed::checkOutput(const fileName& file) const
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


void Foam::packedBed::packNew(const dem::BedRecipe& r)
{
    Info<< "Particles: packing";
    forAll(classNames_, k)
    {
        Info<< ' ' << r.countPerClass[k] << ' ' << classNames_[k];
    }
    if (r.placed.size())
    {
        Info<< " (" << label(r.placed.size()) << " of them placed first)";
    }
    Info<< " at random in " << r.region.xMax - r.region.xMin << " x "
        << r.region.yMax - r.region.yMin << " m (seed " << label(r.seed)
        << "), then " << r.settleTime << " s of settling";
    if (r.settleFriction)
    {
        Info<< " with sliding friction " << *r.settleFriction
            << " on every contact (their own after)";
    }
    Info<< endl;

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
    engine_.guarded
    (
        "Cannot pack the initial bed",
        [&]{ engine_.dem().packBed(r, progress); }
    );

    Info<< "Particles: settled, kinetic energy "
        << engine_.dem().kineticEnergy() << " J, largest overlap "
        << engine_.dem().maxOverlap() << " m" << endl;
}


Foam::packedBed::bedMatch Foam::packedBed::read
(
    const fileName& file,
    const dem::BedRecipe& r,
    std::string& problem
)
{
    try
    {
        if (engine_.dem().loadBed(file, r))
        {
            return bedMatch::made;
        }
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
        problem =
            err.what() + std::string(": ")
          + engine_.foreignStateFix(err, slab_, false);
    }
    catch (const dem::Error& err)
    {
        problem = err.what();
    }
    return bedMatch::other;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::packedBed::start()
{
    const dictionary& bed = dict_.subDict("initialBed");
    if (bed.found("positions"))
    {
        // Listed positions are used as they are: nothing is packed or settled
        wordList ignored;
        for (const word key : {"file", "seed", "settleTime", "settleFriction", "packHeight", "place"})
        {
            if (bed.found(key, keyType::LITERAL)) ignored.append(key);
        }
        if (!ignored.empty())
        {
            WarningInFunction
                << "initialBed in " << dict_.name() << ": " << ignored
                << " ignored: the particles are placed from 'positions' as"
                << " listed, nothing is packed or settled" << endl;
        }
        const fileName file = bed.get<fileName>("positions").expand();
        readPositions(file);
        Info<< "Particles: " << engine_.size() << " placed from " << file
            << endl;
        return;
    }

    const fileName file = bedFile();
    const dem::BedRecipe r = recipe();
    noteUnsettled(r);
    if (!file.empty() && isFile(file))
    {
        std::string problem;
        const bedMatch match = read(file, r, problem);
        if (match == bedMatch::made)
        {
            Info<< "Particles: " << engine_.size() << " read from " << file
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
        Info<< "Particles: " << engine_.size() << " read from " << file
            << endl;
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
            file.path(), casePath_, program_invocation_short_name
        );
        checkOutput(file);
    }
    packNew(r);
    if (!file.empty())
    {
        engine_.save(file);
        Info<< "Particles: the settled bed saved to " << file
            << " for cases with the same particles" << endl;
    }
}


void Foam::packedBed::noteUnsettled(const dem::BedRecipe& r) const
{
    if (r.settleFriction && !(r.settleTime > 0))
    {
        WarningInFunction
            << "Entry 'settleFriction' in initialBed of " << dict_.name()
            << " is ignored: settleTime is " << r.settleTime << ", so the"
            << " bed is not settled" << endl;
    }
}


void Foam::packedBed::checkRestart(const fileName& restart) const
{
    const dictionary& bed = dict_.subDict("initialBed");
    if (engine_.dem().recipe() && !bed.found("positions"))
    {
        // The particles of a packed bed: still the dictionary's mix?
        const std::string differ =
            dem::bedDifferences
            (
                engine_.dem().settings(), *engine_.dem().recipe(), recipe()
            );
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
}


bool Foam::packedBed::pack(const fileName& file, const bool overwrite)
{
    if (engine_.size())
    {
        FatalErrorInFunction
            << "packBed: the particles exist already (a cloud made with"
            << " startMode::pack packs)" << abort(FatalError);
    }
    checkOutput(file);
    const dem::BedRecipe r = recipe();
    noteUnsettled(r);

    if (exists(file))
    {
        std::string problem;
        const bool same = read(file, r, problem) == bedMatch::made;
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
        engine_.create(engine_.dem().settings());
        Info<< "Overwriting " << file << " (-overwrite): "
            << (same ? std::string("a bed for the same settings") : problem).c_str()
            << endl;
    }

    packNew(r);
    engine_.save(file);
    return true;
}


// ************************************************************************* //
