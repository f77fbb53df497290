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
    dpmCloud's output: the particle files (particleWriter), the log's
    summary, and the particle state of a write time (restart).
\*---------------------------------------------------------------------------*/

#include "dpmCloud.H"
#include "bedWalls.H"

#include <algorithm>
#include <cmath>


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::dpmCloud::particleFileDue() const
{
    const Time& time = mesh_.time();
    const scalar t = time.value();
    const scalar k = std::round(t/writeInterval_);
    return mag(t - k*writeInterval_) < 0.5*time.deltaTValue();
}


void Foam::dpmCloud::writeParticlesIfDue()
{
    if (particleFileDue())
    {
        writeParticles();
    }
}


void Foam::dpmCloud::writeParticles()
{
    writer_->write
    (
        engine_.dem(), exchange_.voidageP(), exchange_.gasVelocityP(),
        mesh_.time().value(), mesh_.time().timeName()
    );
    checkImpactSpeed();
}


void Foam::dpmCloud::checkImpactSpeed()
{
    const dem::Simulation& dem = engine_.dem();
    const dem::Settings& s = dem.settings();
    if (impactSpeedWarned_ || s.contact.law != dem::ContactLawType::hertzMindlin)
    {
        return;
    }
    // The fastest particle: at least the speed of its next impact on a
    // wall or on a particle at rest
    const label n = engine_.size();
    const double* vx = dem.vx();
    const double* vy = dem.vy();
    const double* vz = s.dimension == 3 ? dem.vz() : nullptr;
    double v2 = 0;
    for (label i = 0; i < n; ++i)
    {
        v2 = std::max(v2, vx[i]*vx[i] + vy[i]*vy[i] + (vz ? vz[i]*vz[i] : 0.0));
    }
    const scalar v = std::sqrt(v2);
    if (!(v > dem::hertzSpeed(s)))
    {
        return;
    }
    dem::Settings faster(s);
    faster.contact.impactSpeed = v;
    const scalar safe = dem::safeTimeStep(faster);
    if (s.dt <= safe)
    {
        return;
    }
    impactSpeedWarned_ = true;
    WarningInFunction
        << "At t = " << mesh_.time().timeName() << " s particles move at up to "
        << v << " m/s, faster than the impact speed " << dem::hertzSpeed(s)
        << " m/s the HertzMindlin step bounds were taken at ('impactSpeed' of"
        << " contact in " << dict_.name() << "): a Hertz contact that fast is"
        << " shorter, and the DEM step 'deltaT' = " << s.dt << " s is above"
        << " its safe bound " << safe << " s; set impactSpeed to the fastest"
        << " impact expected (at least " << v << " m/s) and deltaT within the"
        << " bound the log then prints" << endl;
}


void Foam::dpmCloud::writeStartParticles(const volVectorField& U)
{
    const Time& time = mesh_.time();
    if (!particleFileDue() || writer_->hasGasFields(time.timeName()))
    {
        return;
    }

    // The coupling's interpolation (the grid's stencils), into arrays of
    // the file's own: the coupling's are left as the first step makes them
    const label n = size();
    const scalarField& eps = exchange_.voidage().primitiveField();
    const vectorField& Uc = U.primitiveField();
    cellWeights stencils;
    grid_->interpolationStencils
    (
        n, engine_.dem().x(), engine_.dem().y(), engine_.z(), 1, stencils
    );
    scalarField voidageP(n);
    vectorField gasVelocityP(n);
    for (label i = 0; i < n; ++i)
    {
        voidageP[i] = stencils.interpolate(i, eps);
        gasVelocityP[i] = stencils.interpolate(i, Uc);
    }
    writer_->write(engine_.dem(), voidageP, gasVelocityP, time.value(), time.timeName());
}


Foam::scalar Foam::dpmCloud::gasSpeedSum() const
{
    if (!mesh_.foundObject<volVectorField>("U"))
    {
        return -1;      // no gas (a bed being packed)
    }
    const vectorField& U =
        mesh_.lookupObject<volVectorField>("U").primitiveField();
    scalar sum = 0;
    forAll(U, celli)
    {
        sum += mag(U[celli]);
    }
    return sum;
}


void Foam::dpmCloud::reportWalls(Ostream& os) const
{
    const std::vector<dem::WallSettings>& walls =
        engine_.dem().settings().walls;
    if (walls.empty()) return;
    const wordList names(bedWalls::wallPatches(mesh_));
    os  << "    walls (wallShapes, fitted to the mesh's patches):";
    auto text = [](const dem::Vector3& v)
    {
        return
            "(" + Foam::name(v.x) + " " + Foam::name(v.y) + " "
          + Foam::name(v.z) + ")";
    };
    forAll(names, k)
    {
        const dem::WallSettings& w = walls[k];
        os  << nl << "        " << names[k] << ": ";
        if (w.shape == dem::WallShape::plane)
        {
            os  << "plane through " << text(w.point).c_str()
                << ", normal " << text(w.normal).c_str();
        }
        else
        {
            os  << "cylinder about the axis " << text(w.axis).c_str()
                << " through " << text(w.point).c_str() << ", radius "
                << w.radius << " m";
        }
    }
    os  << nl;
}


void Foam::dpmCloud::reportContact(Ostream& os) const
{
    const dem::ContactSettings& c = engine_.dem().settings().contact;
    forAll(classNames_, a)
    {
        for (label b = a; b < classNames_.size(); ++b)
        {
            bool given = false;
            for (const dem::PairContactSettings& p : c.pairs)
            {
                given = given || (p.classA == a && p.classB == b)
                     || (p.classA == b && p.classB == a);
            }
            const dem::ContactCoefficients k = dem::pairCoefficients(c, a, b);
            os  << "    contact " << classNames_[a] << "-" << classNames_[b]
                << ": restitution " << k.restitution << ", frictionParticle "
                << k.friction << ", rollingFriction " << k.rollingFriction
                << (given ? " (contact/pairs)" : "") << nl;
        }
    }
    forAll(classNames_, a)
    {
        bool given = false;
        for (const dem::WallContactSettings& w : c.walls)
        {
            given = given || w.classIndex == a;
        }
        const dem::ContactCoefficients k = dem::wallCoefficients(c, a);
        os  << "    contact " << classNames_[a]
            << " on the walls: restitutionWall " << k.restitution
            << ", frictionWall " << k.friction
            << ", rollingFrictionWall " << k.rollingFriction
            << (given ? " (contact/walls)" : "") << nl;
    }
}


void Foam::dpmCloud::report(Ostream& os) const
{
    const dem::Settings& s = engine_.dem().settings();
    std::vector<label> counts(classNames_.size(), 0);
    for (label i = 0; i < size(); ++i) ++counts[engine_.dem().classIndex()[i]];
    const scalarList w = engine_.massFractions();

    os  << "Particles (" << dict_.name() << "):" << nl;
    forAll(classNames_, k)
    {
        const dem::ParticleClass& c = s.classes[k];
        os  << "    " << classNames_[k] << ": " << counts[k] << " particles, d = ";
        if (c.distribution.type == dem::DiameterDistributionType::single)
        {
            os  << c.diameter*1e3 << " mm";
        }
        else
        {
            // Its means and spread are in the line "Particles: class ..."
            os  << dem::meanDiameter(c)*1e3 << " mm (the number mean of its"
                << " distribution)";
        }
        os  << ", rho = " << c.density << " kg/m3, mass fraction " << w[k] << nl;
    }
    reportContact(os);
    os  << "    total mass " << engine_.totalMass() << " kg" << nl
        << "    drag model " << drag_->type()
        << (exchange_.mixtureNeeded() ? " (with the mixture of each cell)" : "")
        << nl;
    grid_->report(os);
    particleModel_.voidage().report(os);
    reportWalls(os);
    os
        << "    time steps: CFD " << mesh_.time().deltaTValue() << " s, DEM "
        << s.dt << " s (" << subSteps() << " sub-steps); safe bound "
        << dem::safeTimeStep(s) << " s (t_c/10), stable bound "
        << dem::stableTimeStep(s) << " s, eq. 7 bound "
        << engine_.dem().timeStepBound() << " s" << nl
        << "    particle files every " << writeInterval_ << " s in "
        << mesh_.time().path()/"particles" << nl
        << "    DEM threads: " << s.nThreads;
    if (s.nThreads > 1 && s.measureThreads)
    {
        os  << ", or one where the run's own timing finds one faster"
            << " (threadChoice measured; the same bits either way)";
    }
    os  << endl;
}


void Foam::dpmCloud::reportThreads(Ostream& os) const
{
    const dem::Settings& s = engine_.dem().settings();
    if (s.nThreads == 1 || !s.measureThreads)
    {
        return;
    }
    const label one = engine_.dem().stepsOnOneThread();
    const label all = engine_.dem().stepsOnAllThreads();
    os  << "DEM threads (threadChoice measured): " << s.nThreads << " in "
        << all << " CFD steps, one in " << one << " ("
        << label(100.0*one/max(one + all, label(1))) << "%); holds on "
        << s.nThreads << " ended by a slower step than one thread's: "
        << engine_.dem().threadHoldsCutShort()
        << "; trials skipped, too few cores free: "
        << engine_.dem().threadTrialsSkipped() << endl;
}


bool Foam::dpmCloud::writeObject
(
    IOstream::streamFormat,
    IOstream::versionNumber,
    IOstream::compressionType,
    const bool
) const
{
    engine_.saveTime(mesh_.time(), gasSpeedSum());
    return true;
}


// ************************************************************************* //
