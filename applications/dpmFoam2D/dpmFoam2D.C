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
    dpmFoam2D

Group
    grpLagrangianSolvers

Description
    Soft-sphere CFD-DEM solver for 2D gas-solid fluidized beds of binary
    particle mixtures (Norouzi, Mostoufi and Sotudeh-Gharebagh, 2012).

    The gas: volume-averaged incompressible Navier-Stokes in the formulation
    where the gas sees the whole pressure gradient (B, the paper's) or its
    share eps_g grad p (A; `formulation` in constant/particleProperties),
    solved with PIMPLE on a one-cell-thick Cartesian mesh; p_rgh is the
    pressure less the gas's hydrostatic head, relative to the outlet. The particles: the DEM of
    src/dem advanced in sub-steps each CFD step, with the drag coupled
    semi-implicitly. In the sequential schedule (default) the gas follows
    the particles within a step; in the concurrent one (`couplingSchedule`
    in constant/particleProperties) it advances beside them, on a thread of
    its own, with their voidage and reaction of the step before. See
    docs/model.md.

    One run a case: the run locks it (caseLock), a second is refused naming
    the first; -postProcess takes no lock. The end time is written whatever
    the write intervals, so a finished run ends with its state on disk.

Usage
    dpmFoam2D [-cloud name] [-postProcess [-func name]]

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "pimpleControl.H"
#include "gasProperties.H"
#include "fluidization.H"
#include "dpmCloud.H"
#include "solverTimers.H"
#include "caseChecks.H"
#include "caseLock.H"
#include "dictionaryScan.H"
#include "incompleteTimes.H"
#include "writeFailureReason.H"
#include "fixedValueFvPatchFields.H"
#include "staticReconstruction.H"

#define PIMPLE_CONTROL

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

//- The step that ends the run (Time::run's test), unless told to stop
//  without writing
static bool lastStep(const Foam::Time& runTime)
{
    return
        runTime.value()
     >= runTime.endTime().value() - 0.5*runTime.deltaTValue()
     && runTime.stopAt() != Foam::Time::stopAtControls::saNoWriteNow;
}

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Soft-sphere CFD-DEM solver for 2D gas-solid fluidized beds"
        " of binary particle mixtures."
    );
    argList::addOption
    (
        "cloud",
        "name",
        "Name of the particle cloud (default 'particles')"
    );

    caseChecks::caseNameCharacters(argc, argv);
    #include "postProcess.H"

    #include "addCheckCaseOptions.H"
    #include "setRootCaseLists.H"
    caseChecks::serialRun(args.executable());    // threads, not MPI
    const caseLock lock(args.path(), args.executable());  // one run a case
    caseChecks::dictionaryFiles(args.path());    // before OpenFOAM parses them
    caseChecks::timeControls(args.path());       // before Time divides by them
    #include "setAsideIncompleteTimes.H"
    #include "createTime.H"
    Sout.precision(8);      // a readable log; fields keep writePrecision
    #include "createMesh.H"
    #include "createControl.H"
    #include "createFields.H"
    #include "createInletVelocity.H"
    #include "readFaceMomentum.H"

    // The initial state: the restart state, the voidage and the first
    // particle file
    if (!isFile(runTime.timePath()/"uniform"/"dem.state"))
    {
        particles.write();
        voidage.write();
    }
    particles.writeStartParticles(U);

    solverTimers timers(runTime);

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        ++runTime;

        Info<< "Time = " << runTime.timeName() << nl << endl;

        // Gas at the particles, DEM sub-steps, reaction and voidage for
        // the gas, the gas's PIMPLE: in the order of the coupling schedule
        particles.evolve
        (
            U, p_rgh,
            [&]
            {
                #include "interpolateVoidage.H"
            },
            [&]
            {
                #include "gasStep.H"
            },
            timers
        );

        timers.start();
        // The end time is saved whatever the write intervals: a finished
        // run leaves its last state to continue from or to look at
        const bool endTimeStep = lastStep(runTime);
        if (endTimeStep)
        {
            particles.writeParticles();
        }
        else
        {
            particles.writeParticlesIfDue();
        }
        if (runTime.writeTime())
        {
            particles.reportBalance(Info);
        }
        #include "writeTime.H"
        timers.stop(solverTimers::output);

        runTime.printExecutionTime(Info);
        timers.progress();
    }

    timers.summary();
    particles.reportThreads(Info);

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
