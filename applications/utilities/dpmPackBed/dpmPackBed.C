/*---------------------------------------------------------------------------*\
Application
    dpmPackBed

Description
    Packs the particles of constant/particleProperties at random (well
    mixed) and settles them under gravity with no gas, as the paper does
    before the gas is turned on, and saves the bed so that cases with the
    same particles, box and contact settings start from it:

        initialBed { file "<path>"; }

    in their constant/particleProperties. Also writes the bed's particle
    file (particles/<startTime>.h5) for a look in ParaView.

    A case whose initialBed names a file that does not exist yet packs,
    settles and saves the bed itself when it starts; dpmPackBed does it
    ahead of time (and always anew).

Usage
    dpmPackBed [-output <file>]
    (default: initialBed/file of constant/particleProperties, else
    constant/packedBed.state)

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "gasProperties.H"
#include "dpmCloud.H"

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

    #include "setRootCase.H"
    #include "createTime.H"
    Sout.precision(8);
    #include "createMesh.H"
    #include "readGravitationalAcceleration.H"

    gasProperties gas(mesh);
    dpmCloud particles
    (
        "particles", mesh, gas, g.value(), dpmCloud::startMode::pack
    );

    // Where to save: -output, else initialBed/file, else constant/
    const dictionary& bed =
        mesh.lookupObject<IOdictionary>("particleProperties")
       .subDict("initialBed");
    const fileName output
    (
        args.found("output")
      ? args.get<fileName>("output")
      : bed.lookupOrDefault<fileName>
        (
            "file", runTime.constant()/"packedBed.state"
        ).expand()
    );
    particles.report(Info);

    particles.save(output);
    particles.writeParticles();

    Info<< nl << "Saved the bed of " << particles.size() << " particles to "
        << output << nl << "End\n" << endl;

    return 0;
}
