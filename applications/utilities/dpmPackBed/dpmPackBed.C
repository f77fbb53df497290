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
Application
    dpmPackBed

Description
    Packs the particles of constant/particleProperties at random (well
    mixed) and settles them under gravity with no gas, as the paper does
    before the gas is turned on (the log reports the settling time reached
    and the kinetic energy per particle every 0.1 s of settling), and saves
    the bed so that cases with the same particles, box and contact settings
    start from it:

        initialBed { file "<path>"; }

    in their constant/particleProperties. Also writes the bed's particle
    file (particles/<startTime>.h5) for a look in ParaView.

    A case whose initialBed names a file that does not exist yet packs,
    settles and saves the bed itself when it starts; dpmPackBed does it
    ahead of time.

    In the slab mode (voidageModel slab3D) it packs 3D spheres between the
    slab's front and back walls (the mesh's thickness apart). The slab's
    state file holds no record of how it was made yet (dem::Simulation
    saves none for the slab): its counts per class are checked, and a
    second dpmPackBed refuses to overwrite it without -overwrite.

    The bed records what it was made for (counts per class, packing region,
    seed, settleTime, settleFriction; diameters, densities, contact settings, box, gravity
    and DEM step): a case whose particles differ is refused with the
    difference named.

Usage
    dpmPackBed [-output <file>] [-overwrite]

    -output <file>  where to save the bed (default: initialBed/file of
                    constant/particleProperties, else
                    constant/packedBed.state)
    -overwrite      replace an existing bed whatever it was made for, and
                    say so (the cases that share it then start from the new
                    bed)

    If the file exists already:
      - a bed made for these particles and settings is kept as it is
        ("kept as it is" in the output, exit 0, nothing packed): running
        dpmPackBed twice gives the same bed once;
      - a bed made for others (another count, mass fraction, diameter,
        seed, ...), an older bed that carries no record, or a file that is
        no bed is not overwritten: dpmPackBed stops, naming the difference,
        before packing (exit 1), unless -overwrite.
    The path is checked before the packing (a directory, a parent that is a
    file, no permission: an error at once, nothing written).

    Like dpmFoam2D it locks the case (caseLock), and the bed's directory
    when that lies outside the case: a second packer or a solver there is
    refused at once, naming the holder.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "gasProperties.H"
#include "dpmCloud.H"
#include "caseChecks.H"
#include "caseLock.H"
#include "dictionaryScan.H"

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Pack and settle the particles of constant/particleProperties and"
        " save the bed for reuse (initialBed { file ...; })"
    );
    argList::noParallel();
    argList::addOption
    (
        "output",
        "file",
        "Where to save the bed (default initialBed/file, else"
        " constant/packedBed.state)"
    );
    argList::addBoolOption
    (
        "overwrite",
        "Replace an existing bed even if it was made for other particles or"
        " settings (else it is kept if made for these, refused otherwise)"
    );

    Foam::caseChecks::caseNameCharacters(argc, argv);
    #include "setRootCase.H"
    const caseLock lock(args.path(), args.executable());
    caseChecks::dictionaryFiles(args.path());    // before OpenFOAM parses them
    caseChecks::timeControls(args.path());       // before Time divides by them
    #include "createTime.H"
    Sout.precision(8);
    #include "createMesh.H"
    #include "readGravitationalAcceleration.H"

    gasProperties gas(mesh);
    dpmCloud particles      // no particles yet: packBed below
    (
        "particles", mesh, gas, g.value(), dpmCloud::startMode::pack
    );

    if (args.found("output"))
    {
        caseChecks::fileNameCharacters(args["output"], "Option -output");
    }

    // Where to save: -output, else initialBed/file, else constant/
    const fileName bedFile = particles.bedFile();
    const fileName output
    (
        args.found("output") ? args.get<fileName>("output")
      : !bedFile.empty() ? bedFile
      : runTime.constant()/"packedBed.state"
    );
    const autoPtr<caseLock> bedLock
    (
        caseLock::outsideCase(output.path(), args.path(), args.executable())
    );
    const bool packed = particles.packBed(output, args.found("overwrite"));
    particles.report(Info);
    particles.writeParticles();

    if (packed)
    {
        Info<< nl << "Saved the bed of " << particles.size()
            << " particles to " << output;
    }
    else
    {
        Info<< nl << "Kept the bed of " << particles.size()
            << " particles in " << output;
    }
    Info<< nl << "End\n" << endl;

    return 0;
}
