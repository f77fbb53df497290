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
    summary and exchange balance, and the particle state (restart, or a bed
    to reuse), written last at a write time so that a time with it is
    complete.
\*---------------------------------------------------------------------------*/

#include "dpmCloud.H"
#include "faultInjection.H"


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dpmCloud::writeParticlesIfDue()
{
    const Time& time = mesh_.time();
    const scalar t = time.value();
    const scalar k = std::round(t/writeInterval_);
    if (mag(t - k*writeInterval_) < 0.5*time.deltaTValue())
    {
        writeParticles();
    }
}


void Foam::dpmCloud::writeParticles()
{
    writer_->write
    (
        *dem_, voidageP_, gasVelocityP_,
        mesh_.time().value(), mesh_.time().timeName()
    );
}


void Foam::dpmCloud::writeStartParticles(const volVectorField& U)
{
    const Time& time = mesh_.time();
    const scalar t = time.value();
    const scalar k = std::round(t/writeInterval_);
    if (mag(t - k*writeInterval_) >= 0.5*time.deltaTValue())
    {
        return;
    }

    // The coupling's interpolation (cartesianGrid2D::interpolate), into
    // arrays of the file's own: the coupling's are left as the first step
    // makes them
    const label n = size();
    const scalarField& eps = voidage_.primitiveField();
    const vectorField& Uc = U.primitiveField();
    const double* x = dem_->x();
    const double* y = dem_->y();
    scalarField voidageP(n);
    vectorField gasVelocityP(n);
    for (label i = 0; i < n; ++i)
    {
        grid_.interpolate(x[i], y[i], eps, Uc, voidageP[i], gasVelocityP[i]);
    }
    writer_->write(*dem_, voidageP, gasVelocityP, t, time.timeName());
}


void Foam::dpmCloud::reportBalance(Ostream& os) const
{
    vector particleForce = Zero;
    if (K_.size() == size())
    {
        vectorField F;
        exchangedForces(F);
        for (const vector& Fi : F) particleForce += Fi;
    }
    const vector gasForce = gSum(Fp_.primitiveField())*grid_.cellVolume();

    os  << "Exchange: force on particles " << particleForce
        << " N, reaction mapped to the gas " << gasForce << " N" << nl;
    particleModel_.voidage().reportBalance
    (
        os, size(), dem_->diameter(), particleFraction_.primitiveField()
    );
}


void Foam::dpmCloud::report(Ostream& os) const
{
    const dem::Settings& s = dem_->settings();
    std::vector<label> counts(classNames_.size(), 0);
    for (label i = 0; i < size(); ++i) ++counts[dem_->classIndex()[i]];
    const scalarList w = massFractions();

    os  << "Particles (" << dict_.name() << "):" << nl;
    forAll(classNames_, k)
    {
        os  << "    " << classNames_[k] << ": " << counts[k]
            << " particles, d = " << s.classes[k].diameter*1e3 << " mm, rho = "
            << s.classes[k].density << " kg/m3, mass fraction " << w[k] << nl;
    }
    os  << "    total mass " << totalMass() << " kg" << nl
        << "    drag model " << drag_->type()
        << (mixtureNeeded_ ? " (with the mixture of each cell)" : "") << nl
        << "    bed depth (mesh thickness) " << grid_.depth()*1e3 << " mm, gas cells "
        << grid_.dx()*1e3 << " x " << grid_.dy()*1e3 << " mm ("
        << grid_.nx() << " x " << grid_.ny() << ")" << nl;
    if (slab_)
    {
        reportSlab(os);
    }
    os
        << "    time steps: CFD " << mesh_.time().deltaTValue() << " s, DEM "
        << s.dt << " s (" << subSteps() << " sub-steps); safe bound "
        << dem::safeTimeStep(s) << " s (t_c/10), stable bound "
        << dem::stableTimeStep(s) << " s, eq. 7 bound "
        << dem_->timeStepBound() << " s" << nl
        << "    particle files every " << writeInterval_ << " s in "
        << mesh_.time().path()/"particles" << endl;
}


bool Foam::dpmCloud::writeObject
(
    IOstream::streamFormat,
    IOstream::versionNumber,
    IOstream::compressionType,
    const bool
) const
{
    save(stateFile(mesh_.time().timeName()));
    return true;
}


void Foam::dpmCloud::save(const fileName& file) const
{
    faultInjection::at("stateWrite");
    // The write's own error (file, OS reason), not the settings' file
    try
    {
        dem_->setRunRecord(runRecord());
        dem_->save(file);
    }
    catch (const dem::Error& err)
    {
        FatalErrorInFunction
            << "Cannot write the particle state: " << err.what()
            << exit(FatalError);
    }
    faultInjection::at("stateWrite", "done");
}


// ************************************************************************* //
