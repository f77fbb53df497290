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

#include "particleEngine.H"
#include "positiveEntry.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- Warning naming the Hertz-Mindlin law's entries given to the linear law,
//  which reads none of them: said, not ignored silently
void noteHertzEntries
(
    const fileName& file,
    const dictionary& classes,
    const dictionary& contact
)
{
    std::string unused;
    const auto add = [&unused](const std::string& entry)
    {
        unused += (unused.empty() ? "" : ", ") + entry;
    };
    for (const char* key : {"wallYoungsModulus", "wallPoissonRatio", "impactSpeed"})
    {
        if (contact.found(key, keyType::LITERAL)) add("contact/" + word(key));
    }
    for (const word& name : classes.sortedToc())
    {
        const dictionary* c = classes.findDict(name);
        for (const char* key : {"youngsModulus", "poissonRatio"})
        {
            if (c && c->found(key, keyType::LITERAL))
            {
                add("classes/" + name + "/" + word(key));
            }
        }
    }
    if (!unused.empty())
    {
        WarningInFunction
            << file << ": " << unused.c_str()
            << " not used: the contactLaw is linear (kn, kt and restitution"
            << " set the contact); select contactLaw HertzMindlin for them,"
            << " or remove the entries" << endl;
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleEngine::particleEngine
(
    const IOdictionary& dict,
    const cartesianGrid2D& grid,
    const wordList& classNames
)
:
    dict_(dict),
    grid_(grid),
    classNames_(classNames)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

dem::Settings Foam::particleEngine::settings
(
    const vector& g,
    const particleModel& model
) const
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
            << " HertzMindlin (docs/theory/dem.md, \"The Hertz-Mindlin law\")"
            << exit(FatalIOError);
    }
    if (cs.law == dem::ContactLawType::linear)
    {
        noteHertzEntries(dict_.name(), classes, contact);
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
    s.gravity[0] = g.x();
    s.gravity[1] = g.y();
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
    model.selectEngine(s, grid_);
    return s;
}


void Foam::particleEngine::create(const dem::Settings& settings)
{
    guarded
    (
        "Invalid particle settings",
        [&]{ dem_.reset(new dem::Simulation(settings)); }
    );
}


std::vector<int> Foam::particleEngine::classCounts() const
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


// Sums by class (count x particle mass), not over the particles: they do not
// depend on the particles' numbering, which sortByCell changes, so a restart
// gets the same U0 to the last bit
Foam::scalarList Foam::particleEngine::classMasses() const
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


Foam::scalar Foam::particleEngine::totalMass() const
{
    return sum(classMasses());
}


Foam::scalar Foam::particleEngine::totalVolume() const
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


Foam::scalarList Foam::particleEngine::massFractions() const
{
    scalarList w(classMasses());
    const scalar M = sum(w);
    forAll(w, k) w[k] /= max(M, VSMALL);
    return w;
}


Foam::scalarList Foam::particleEngine::diametersOf(const dem::Settings& settings)
{
    scalarList d(settings.classes.size());
    forAll(d, k) d[k] = settings.classes[k].diameter;
    return d;
}


Foam::scalarList Foam::particleEngine::classDiameters() const
{
    return diametersOf(dem_->settings());
}


Foam::scalarList Foam::particleEngine::classDensities() const
{
    scalarList rho(classNames_.size());
    forAll(rho, k) rho[k] = dem_->settings().classes[k].density;
    return rho;
}


Foam::label Foam::particleEngine::subSteps(const scalar dtGas) const
{
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
