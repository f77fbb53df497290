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

#include "dpmCloud.H"
#include "gasProperties.H"
#include "positiveEntry.H"
#include "caseChecks.H"
#include "particleChecks.H"
#include "faultInjection.H"

#include <exception>
#include <omp.h>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(dpmCloud, 0);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dpmCloud::checkSettings
(
    const gasProperties& gas,
    const startMode mode
) const
{
    const particleChecks checks(dict_, classNames_);
    checks.gasDensity(gas, engine_.classDensities());

    if (mode == startMode::postProcess) return;

    caseChecks::threadCount
    (
        dict_, "constant/particleProperties", engine_.dem().settings().nThreads,
        schedule_->gasThreads() > 0
    );

    if (mode != startMode::run) return;

    checks.writeInterval(writeInterval_, mesh_.time().deltaTValue());
}


void Foam::dpmCloud::initialise(const startMode mode)
{
    if (mode == startMode::pack)
    {
        return;     // dpmPackBed calls packBed
    }

    const fileName restart =
        engine_.stateFile(mesh_.time(), mesh_.time().timeName());
    if (isFile(restart))
    {
        engine_.loadRestart(restart, slab_);
        if (mode == startMode::run && mesh_.time().value() > 0)
        {
            // time 0's bed has seen no gas
            engine_.checkRestartModels(restart);
        }
        if (mode == startMode::run)
        {
            bed_.checkRestart(restart);
            engine_.checkRestartOrigin(restart, mesh_.time(), gasSpeedSum());
        }
        Info<< "Particles: " << size() << " read from " << restart << endl;
        return;
    }
    if (mode == startMode::postProcess && !engine_.hasStates(mesh_.time()))
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

    bed_.start();
}


void Foam::dpmCloud::setCouplingThreads()
{
    // The coupling's loops run on the DEM's team of the coming step (one
    // thread where the measured choice found one faster: a busy neighbour
    // makes a team of two slow in every parallel loop, not only the DEM's),
    // and in the concurrent schedule on the gas's thread too (idle then)
    const label team = engine_.dem().nextStepThreads() + schedule_->gasThreads();
    drag_->setThreads(team);
    exchange_.setThreads(team);
}


void Foam::dpmCloud::advanceParticles()
{
    if (frozen_)
    {
        exchange_.holdFrozen();
        return;
    }

    engine_.dem().advance(dtStep_);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dpmCloud::dpmCloud
(
    const word& name,
    const fvMesh& mesh,
    const gasProperties& gas,
    const vector& g,
    const startMode mode
)
:
    regIOobject
    (
        IOobject
        (
            name,
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE      // the solver writes the state last
        )
    ),
    mesh_(mesh),
    dict_
    (
        IOobject
        (
            "particleProperties",
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    ),
    grid_(gasGrid::New(dict_, mesh)),
    g_(g),
    classNames_(dict_.subDict("classes").toc()),
    drag_(dragModel::New(dict_, gas.rho(), gas.mu())),
    formulation_(couplingFormulation::New(dict_)),
    schedule_(couplingSchedule::New(dict_)),
    frozen_(dict_.lookupOrDefault<bool>("frozen", false)),
    sortInterval_
    (
        label
        (
            checkedRange
            (
                dict_, "sortInterval",
                dict_.lookupOrDefault<label>("sortInterval", 200), 0, GREAT, false
            )
        )
    ),
    writeInterval_(positiveEntry(dict_, "writeInterval", 0.01)),
    voidageMin_(boundedEntryOrDefault(dict_, "voidageMin", 0.1, 0, 1, true)),
    particleModel_(dict_, *grid_, voidageMin_),
    slab_(particleModel_.slab()),
    engine_(dict_, *grid_, classNames_),
    bed_(dict_, *grid_, classNames_, engine_, slab_, mesh.time().path()),
    exchange_
    (
        mesh, *grid_, engine_, *drag_, *formulation_, particleModel_,
        gas.rho(), g_, frozen_, voidageMin_, gas.inletPatch(),
        mode == startMode::run, keepsExchange(mode)
    ),
    fluidization_(engine_, *drag_, gas.rho()),
    dtStep_(mesh.time().deltaTValue())
{
    Info<< "Coupling: " << formulation_->description().c_str()
        << nl << "Coupling: " << schedule_->description().c_str()
        << nl << "Coupling: "
        << particleModel_.voidage().description().c_str()
        << nl << "Coupling: "
        << particleModel_.smoothing().description().c_str() << endl;

    if (classNames_.size() < 1)
    {
        FatalIOErrorInFunction(dict_)
            << "No particle classes in " << dict_.name() << "/classes"
            << exit(FatalIOError);
    }

    if (drag_->totalForceOfMixture() && formulation_->separatePressureForce())
    {
        FatalIOErrorInFunction(dict_)
            << "dragModel " << drag_->type() << " with formulation "
            << formulation_->type() << " in " << dict_.name()
            << ": the closure's polydisperse correction already holds each"
            << " particle's share of the pressure gradient, which formulation "
            << formulation_->type() << " adds again as -V_p grad p; use"
            << " formulation B with " << drag_->type()
            << " (docs/theory/drag-closures.md)"
            << exit(FatalIOError);
    }

    const particleChecks checks(dict_, classNames_);
    checks.entries(mesh_.time());
    caseChecks::gravity(g_);
    grid_->checkBedGeometry();

    const dem::Settings settings = engine_.settings(g_, particleModel_);
    engine_.setRunRecord
    (
        "dragModel " + drag_->type() + "\n"
        "formulation " + formulation_->type() + "\n"
        "couplingSchedule " + schedule_->type() + "\n"
        "contactLaw " + dem::contactLawName(settings.contact.law) + "\n"
    );
    // The voidage model's own check first (slab3D: the spheres fit in the
    // slab), in its words rather than the DEM's; a distribution's largest
    particleModel_.voidage().checkDiameters
    (
        dict_, classNames_, particleEngine::largestDiametersOf(settings)
    );
    checks.demStep(settings);
    engine_.create(settings);
    particleEngine::reportDiameters(settings);
    Info<< "DEM: kick and drift loops for "
        << dem::streamingLoopsInUse().c_str()
        << " (environment variable DEM_SIMD = baseline or avx2 chooses;"
        << " the same bits)" << endl;
    setCouplingThreads();
    checkSettings(gas, mode);

    subSteps();         // the DEM step must divide the CFD step
    {
        const scalar dMax = max(particleEngine::largestDiametersOf(settings));
        formulation_->checkBedDepth
        (
            dict_, grid_->depth(), dMax,
            particleModel_.voidage().densestFraction(dMax), voidageMin_
        );
    }
    if (mode == startMode::run)
    {
        faultInjection::install(mesh);      // before a bed is packed and saved
    }
    initialise(mode);

    writer_.reset
    (
        new particleWriter
        (
            mesh.time().path(), grid_->depth(), mesh.time().value()
        )
    );

    exchange_.updateVoidage();

    // Keep the start voidage as the old-time level of the first step, as a
    // run that went through this time would (restarts continue exactly)
    exchange_.voidage().oldTime();

    if (keepsExchange(mode))
    {
        exchange_.readSavedReaction();
    }
}


Foam::dpmCloud::~dpmCloud()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::dpmCloud::subSteps() const
{
    return engine_.subSteps(mesh_.time().deltaTValue());
}


void Foam::dpmCloud::evolve
(
    const volVectorField& U,
    const volScalarField& p_rgh,
    const std::function<void()>& gasVoidage,
    const std::function<void()>& gasStep,
    solverTimers& timers
)
{
    schedule_->step(*this, U, p_rgh, gasVoidage, gasStep, timers);
}


void Foam::dpmCloud::interpolateGas
(
    const volVectorField& U,
    const volScalarField& p_rgh
)
{
    // Renumber the particles by cell now and then; the overlaps follow the
    // new numbers, the other per-particle arrays are made anew below
    if
    (
        !frozen_ && sortInterval_ > 0
     && engine_.dem().stepCount() % sortInterval_ == 0
    )
    {
        engine_.dem().sortByCell();
        exchange_.updateOverlaps();
    }

    dtStep_ = mesh_.time().deltaTValue();
    setCouplingThreads();
    exchange_.interpolateGas(U, p_rgh);
}


void Foam::dpmCloud::advance()
{
    engine_.guarded(advanceError, [&]{ advanceParticles(); });
}


void Foam::dpmCloud::advanceBeside(const std::function<void()>& gasStep)
{
    // One team of the threads that run the coupling's loops: its worker,
    // which would otherwise spin idle through the gas step on the core the
    // DEM needs, runs the DEM (its own loops nested inside, on nThreads);
    // the gas stays on the main thread. The DEM touches only its own
    // arrays and the inputs interpolateGas gave it, the gas only the
    // cells' fields: nothing is shared. An exception must not leave the
    // parallel region: the DEM's is kept and thrown after it.
    std::exception_ptr demError;
    omp_set_max_active_levels(2);
    #pragma omp parallel num_threads(2)
    {
        // A team cut to one thread (OMP_THREAD_LIMIT) runs both in turn
        const int thread = omp_get_thread_num();
        if (thread == 0)
        {
            gasStep();
        }
        if (thread == 1 || omp_get_num_threads() == 1)
        {
            try
            {
                advanceParticles();
            }
            catch (...)
            {
                demError = std::current_exception();
            }
        }
    }
    if (demError)
    {
        engine_.guarded(advanceError, [&]{ std::rethrow_exception(demError); });
    }
}


// ************************************************************************* //
