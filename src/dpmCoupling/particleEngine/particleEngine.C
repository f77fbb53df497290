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
#include "bedWalls.H"
#include "positiveEntry.H"
#include "mathematicalConstants.H"

#include <algorithm>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleEngine::particleEngine
(
    const IOdictionary& dict,
    const gasGrid& grid,
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
        s.classes.push_back(readClass(c, name));
    }

    s.contact = contactSettings();

    s.box = dem::Box{grid_.xMin(), grid_.xMax(), grid_.yMin(), grid_.yMax()};
    s.gravity[0] = g.x();
    s.gravity[1] = g.y();
    s.dt = dict_.get<scalar>("deltaT");
    s.nThreads = dict_.lookupOrDefault<label>("nThreads", 1);

    // How many of the nThreads a CFD step's DEM sub-steps run on: the faster
    // of one and all, timed on the run (threads sleeping at each barrier, or
    // cores shared with other runs, can make more threads slower), or all
    const word threadChoice =
        dict_.lookupOrDefault<word>("threadChoice", "measured");
    if (threadChoice != "measured" && threadChoice != "fixed")
    {
        FatalIOErrorInFunction(dict_)
            << "Entry 'threadChoice' = " << threadChoice
            << " in constant/particleProperties; allowed: measured (the faster"
            << " of one thread and nThreads, timed on the run) or fixed"
            << " (nThreads)"
            << exit(FatalIOError);
    }
    s.measureThreads = threadChoice == "measured";

    // Verlet skin of the neighbour list (default: the DEM's, for discs
    // chosen at each list build from the fastest particle's displacement,
    // 0.1-0.8 d_min; 0.1 d_min in the slab): a wider skin means fewer list
    // builds but more candidate pairs each step (docs/performance.md). An entry fixes it
    if (dict_.found("neighbourSkin"))
    {
        scalar dMin = GREAT;
        for (const dem::ParticleClass& c : s.classes)
        {
            dMin = min(dMin, dem::smallestDiameter(c));
        }
        s.neighbourSkin = boundedEntry(dict_, "neighbourSkin", 0, dMin, true);
    }
    model.selectEngine(s, grid_);
    if (s.dimension == 3)
    {
        scalar dMin = GREAT;
        for (const dem::ParticleClass& c : s.classes)
        {
            dMin = min(dMin, dem::smallestDiameter(c));
        }
        s.walls = bedWalls::read(dict_, grid_.mesh(), g, 0.5*dMin);
    }
    else if (dict_.found("wallShapes", keyType::LITERAL))
    {
        FatalIOErrorInFunction(dict_)
            << "Entry 'wallShapes' in " << dict_.name() << " names the walls"
            << " of spheres; the voidage model's particles are discs, whose"
            << " walls are the box's: allowed with voidageModel slab3D or"
            << " spheres3D" << exit(FatalIOError);
    }
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
            // A distribution's particles weigh rho pi/6 E[d^3] on average
            const scalar w = boundedEntry(c, "massFraction", 0, 1, false);
            const scalar M = positiveEntry(dict_, "totalMass");
            const dem::ParticleClass pc(readClass(c, name));
            const scalar d = pc.diameter;
            const scalar m =
                pc.distribution.type == dem::DiameterDistributionType::single
              ? c.get<scalar>("density")*constant::mathematical::pi*d*d*d/6
              : dem::meanParticleMass(pc);
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
// gets the same U0 to the last bit. A class with a diameter distribution sums
// its particles' masses in the order of their ids, which the numbering does
// not change either
Foam::scalarList Foam::particleEngine::classMasses() const
{
    const dem::Settings& s = dem_->settings();
    labelList n(classNames_.size(), Zero);
    std::vector<std::pair<std::int64_t, label>> distributed;
    for (label i = 0; i < size(); ++i)
    {
        const int k = dem_->classIndex()[i];
        ++n[k];
        if (s.classes[k].distribution.type != dem::DiameterDistributionType::single)
        {
            distributed.emplace_back(dem_->id()[i], i);
        }
    }
    std::sort(distributed.begin(), distributed.end());
    const scalarList rho(classDensities());
    scalarList m(n.size(), Zero);
    forAll(m, k)
    {
        if (s.classes[k].distribution.type == dem::DiameterDistributionType::single)
        {
            const scalar d = s.classes[k].diameter;
            m[k] = n[k]*rho[k]*constant::mathematical::pi*pow3(d)/6;
        }
    }
    for (const auto& particle : distributed)
    {
        const label i = particle.second;
        m[dem_->classIndex()[i]] += dem_->mass()[i];
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
