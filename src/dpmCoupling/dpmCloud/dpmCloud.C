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
#include "emptyFvPatch.H"
#include "fixedValueFvPatchFields.H"
#include "zeroGradientFvPatchFields.H"
#include "mathematicalConstants.H"
#include "faultInjection.H"


// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(dpmCloud, 0);
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- Patch types of the voidage: the distributor sees particle-free gas
//  (voidage 1, so the face flux there is exactly U0), others zero gradient
wordList voidagePatchTypes(const fvMesh& mesh, const word& inletPatch)
{
    wordList types(mesh.boundary().size(), zeroGradientFvPatchScalarField::typeName);
    forAll(mesh.boundary(), patchi)
    {
        const fvPatch& patch = mesh.boundary()[patchi];
        if (isA<emptyFvPatch>(patch))
        {
            types[patchi] = emptyFvPatch::typeName;
        }
        else if (patch.name() == inletPatch)
        {
            types[patchi] = fixedValueFvPatchScalarField::typeName;
        }
    }
    return types;
}

IOobject fieldIO(const word& name, const fvMesh& mesh, const bool write)
{
    return IOobject
    (
        name,
        mesh.time().timeName(),
        mesh,
        IOobject::NO_READ,
        write ? IOobject::AUTO_WRITE : IOobject::NO_WRITE
    );
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::fileName Foam::dpmCloud::stateFile(const word& timeName) const
{
    return mesh_.time().path()/timeName/"uniform"/"dem.state";
}


dem::Settings Foam::dpmCloud::demSettings() const
{
    dem::Settings s;

    const dictionary& classes = dict_.subDict("classes");
    for (const word& name : classNames_)
    {
        const dictionary& c = classes.subDict(name);
        s.classes.push_back
        (
            dem::ParticleClass
            {
                name, c.get<scalar>("diameter"), c.get<scalar>("density"),
                c.lookupOrDefault<scalar>("youngsModulus", 0),
                c.lookupOrDefault<scalar>("poissonRatio", 0)
            }
        );
        if (s.classes.back().diameter > min(grid_.dx(), grid_.dy()))
        {
            FatalIOErrorInFunction(c)
                << "Entry 'diameter' = " << s.classes.back().diameter
                << " of class " << name << " in " << dict_.name()
                << " is larger than the gas cell (" << grid_.dx() << " x "
                << grid_.dy() << " m); allowed range (0, "
                << min(grid_.dx(), grid_.dy()) << "]" << exit(FatalIOError);
        }
    }

    const dictionary& contact = dict_.subOrEmptyDict("contact");
    dem::ContactSettings& cs = s.contact;
    const word law =
        contact.lookupOrDefault<word>("contactLaw", dem::contactLawName(cs.law));
    try
    {
        cs.law = dem::contactLawFromName(law);
    }
    catch (const dem::Error&)
    {
        FatalIOErrorInFunction(contact)
            << "Entry 'contactLaw' = " << law << " in " << contact.name()
            << " is not allowed; allowed: linear (the paper's, default) or"
            << " HertzMindlin (docs/model.md, \"The Hertz-Mindlin law\")"
            << exit(FatalIOError);
    }
    cs.wallYoungsModulus =
        contact.lookupOrDefault<scalar>("wallYoungsModulus", cs.wallYoungsModulus);
    cs.wallPoissonRatio =
        contact.lookupOrDefault<scalar>("wallPoissonRatio", cs.wallPoissonRatio);
    cs.impactSpeed = contact.lookupOrDefault<scalar>("impactSpeed", cs.impactSpeed);
    cs.kn = contact.lookupOrDefault<scalar>("kn", cs.kn);
    cs.kt = contact.lookupOrDefault<scalar>("kt", cs.kt);
    cs.restitution = contact.lookupOrDefault<scalar>("restitution", cs.restitution);
    cs.restitutionWall =
        contact.lookupOrDefault<scalar>("restitutionWall", cs.restitutionWall);
    cs.frictionParticle =
        contact.lookupOrDefault<scalar>("frictionParticle", cs.frictionParticle);
    cs.frictionWall = contact.lookupOrDefault<scalar>("frictionWall", cs.frictionWall);
    cs.tangentialDampingRatio =
        contact.lookupOrDefault<scalar>
        (
            "tangentialDampingRatio", cs.tangentialDampingRatio
        );
    cs.rollingFriction =
        contact.lookupOrDefault<scalar>("rollingFriction", cs.rollingFriction);
    cs.rollingFrictionWall =
        contact.lookupOrDefault<scalar>("rollingFrictionWall", cs.rollingFrictionWall);

    s.box = dem::Box{grid_.xMin(), grid_.xMax(), grid_.yMin(), grid_.yMax()};
    s.gravity[0] = g_.x();
    s.gravity[1] = g_.y();
    s.dt = dict_.get<scalar>("deltaT");
    s.nThreads = dict_.lookupOrDefault<label>("nThreads", 1);

    // Verlet skin of the neighbour list (default: the DEM's, for discs
    // chosen at each list build from the fastest particle's displacement,
    // 0.1-0.8 d_min; 0.1 d_min in the slab): a wider skin means fewer list
    // builds but more candidate pairs each step (docs/performance.md). An entry fixes it
    if (dict_.found("neighbourSkin"))
    {
        scalar dMin = GREAT;
        for (const dem::ParticleClass& c : s.classes)
        {
            dMin = min(dMin, c.diameter);
        }
        s.neighbourSkin = boundedEntry(dict_, "neighbourSkin", 0, dMin, true);
    }
    particleModel_.selectEngine(s, grid_);
    return s;
}


std::vector<int> Foam::dpmCloud::classCounts() const
{
    const dictionary& classes = dict_.subDict("classes");
    std::vector<int> counts;
    for (const word& name : classNames_)
    {
        const dictionary& c = classes.subDict(name);
        if (c.found("count"))
        {
            counts.push_back(c.get<label>("count"));
        }
        else
        {
            // A mass fraction of the bed's total mass
            const scalar w = boundedEntry(c, "massFraction", 0, 1, false);
            const scalar M = positiveEntry(dict_, "totalMass");
            const scalar d = c.get<scalar>("diameter");
            const scalar m =
                c.get<scalar>("density")*constant::mathematical::pi*d*d*d/6;
            counts.push_back(int(std::round(w*M/m)));
        }
        if (counts.back() < 1)
        {
            FatalIOErrorInFunction(c)
                << "Class " << name << " in " << dict_.name()
                << " has " << counts.back() << " particles; each class needs"
                << " 'count' >= 1 (or a massFraction that gives one)"
                << exit(FatalIOError);
        }
    }
    return counts;
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
    grid_(mesh),
    rhoGas_(gas.rho()),
    g_(g),
    classNames_(dict_.subDict("classes").toc()),
    drag_(dragModel::New(dict_, gas.rho(), gas.mu())),
    formulation_(couplingFormulation::New(dict_)),
    schedule_(couplingSchedule::New(dict_)),
    couplingThreads_(1),
    exchangeReady_(false),
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
    particleModel_(dict_, grid_, voidageMin_),
    slab_(particleModel_.slab()),
    voidage_
    (
        fieldIO("voidage", mesh, mode == startMode::run),
        mesh,
        dimensionedScalar("one", dimless, 1.0),
        voidagePatchTypes(mesh, gas.inletPatch())
    ),
    particleFraction_
    (
        fieldIO("particleFraction", mesh, false),
        mesh,
        dimensionedScalar("zero", dimless, 0.0),
        zeroGradientFvPatchScalarField::typeName
    ),
    mixtureNeeded_(drag_->needsMixture()),
    Kc_
    (
        fieldIO("Kc", mesh, keepsExchange(mode)),
        mesh,
        dimensionedScalar(dimDensity/dimTime, Zero),
        zeroGradientFvPatchScalarField::typeName
    ),
    Fp_
    (
        fieldIO("Fp", mesh, keepsExchange(mode)),
        mesh,
        dimensionedVector(dimForce/dimVolume, Zero),
        zeroGradientFvPatchVectorField::typeName
    ),
    Ustar_
    (
        fieldIO("Ustar", mesh, keepsExchange(mode)),
        mesh,
        dimensionedVector(dimVelocity, Zero),
        zeroGradientFvPatchVectorField::typeName
    ),
    dtStep_(mesh.time().deltaTValue())
{
    Info<< "Coupling: " << formulation_->description().c_str()
        << nl << "Coupling: " << schedule_->description().c_str()
        << nl << "Coupling: "
        << particleModel_.voidage().description().c_str() << endl;

    if (classNames_.size() < 1)
    {
        FatalIOErrorInFunction(dict_)
            << "No particle classes in " << dict_.name() << "/classes"
            << exit(FatalIOError);
    }

    checkEntries();
    caseChecks::gravity(g_);
    caseChecks::bedGeometry(mesh_, grid_);

    const dem::Settings settings = demSettings();
    // The voidage model's own check first (slab3D: the spheres fit in the
    // slab), in its words rather than the DEM's
    particleModel_.voidage().checkDiameters(dict_, diametersOf(settings));
    checkDemStep(settings);
    guarded
    (
        "Invalid particle settings",
        [&]{ dem_.reset(new dem::Simulation(settings)); }
    );
    Info<< "DEM: kick and drift loops for "
        << dem::streamingLoopsInUse().c_str()
        << " (environment variable DEM_SIMD = baseline or avx2 chooses;"
        << " the same bits)" << endl;
    couplingThreads_ = settings.nThreads + schedule_->gasThreads();
    drag_->setThreads(couplingThreads_);
    checkSettings(gas, mode);

    subSteps();         // the DEM step must divide the CFD step
    formulation_->checkBedDepth
    (
        dict_, grid_, classDiameters(), slab_, voidageMin_
    );
    if (mode == startMode::run)
    {
        faultInjection::install(mesh);      // before a bed is packed and saved
    }
    initialise(mode);

    writer_.reset
    (
        new particleWriter
        (
            mesh.time().path(), grid_.depth(), mesh.time().value()
        )
    );

    updateVoidage();

    // Keep the start voidage as the old-time level of the first step, as a
    // run that went through this time would (restarts continue exactly)
    voidage_.oldTime();

    if (keepsExchange(mode))
    {
        readExchange();
    }
}


Foam::dpmCloud::~dpmCloud()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

// Sums by class (count x particle mass), not over the particles: they do not
// depend on the particles' numbering, which sortByCell changes, so a restart
// gets the same U0 to the last bit
Foam::scalarList Foam::dpmCloud::classMasses() const
{
    labelList n(classNames_.size(), Zero);
    for (label i = 0; i < size(); ++i)
    {
        ++n[dem_->classIndex()[i]];
    }
    const scalarList d(classDiameters());
    const scalarList rho(classDensities());
    scalarList m(n.size());
    forAll(m, k)
    {
        m[k] = n[k]*rho[k]*constant::mathematical::pi*pow3(d[k])/6;
    }
    return m;
}


Foam::scalar Foam::dpmCloud::totalMass() const
{
    return sum(classMasses());
}


Foam::scalar Foam::dpmCloud::totalVolume() const
{
    const scalarList m(classMasses());
    const scalarList rho(classDensities());
    scalar V = 0;
    forAll(m, k)
    {
        V += m[k]/rho[k];
    }
    return V;
}


Foam::scalarList Foam::dpmCloud::massFractions() const
{
    scalarList w(classMasses());
    const scalar M = sum(w);
    forAll(w, k) w[k] /= max(M, VSMALL);
    return w;
}


Foam::scalarList Foam::dpmCloud::diametersOf(const dem::Settings& settings)
{
    scalarList d(settings.classes.size());
    forAll(d, k) d[k] = settings.classes[k].diameter;
    return d;
}


Foam::scalarList Foam::dpmCloud::classDiameters() const
{
    return diametersOf(dem_->settings());
}


Foam::scalarList Foam::dpmCloud::classDensities() const
{
    scalarList rho(classNames_.size());
    forAll(rho, k) rho[k] = dem_->settings().classes[k].density;
    return rho;
}


Foam::label Foam::dpmCloud::subSteps() const
{
    const scalar dtGas = mesh_.time().deltaTValue();
    const scalar dtDem = dem_->settings().dt;
    const label n = label(std::round(dtGas/dtDem));
    if (n < 1 || mag(n*dtDem - dtGas) > 1e-9*dtGas)
    {
        FatalIOErrorInFunction(dict_)
            << "The DEM step 'deltaT' = " << dtDem << " in " << dict_.name()
            << " does not divide the CFD step deltaT = " << dtGas
            << " of system/controlDict; allowed: deltaT(CFD)/deltaT(DEM)"
            << " a whole number >= 1" << exit(FatalIOError);
    }
    return n;
}


// ************************************************************************* //
