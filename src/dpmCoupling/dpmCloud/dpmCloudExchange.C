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
    dpmCloud's coupling step: the gas interpolated to the particles, the DEM
    advance, and the exchange back to the gas (forces and voidage).
\*---------------------------------------------------------------------------*/

#include "dpmCloud.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

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
     && dem_->stepCount() % sortInterval_ == 0
    )
    {
        dem_->sortByCell();
        updateOverlaps();
    }

    dtStep_ = mesh_.time().deltaTValue();
    const label n = size();
    const label nThreads = couplingThreads_;
    const scalar pi = constant::mathematical::pi;
    const scalarField& eps = voidage_.primitiveField();
    const vectorField& Uc = U.primitiveField();

    const double* x = dem_->x();
    const double* y = dem_->y();
    const double* vx = dem_->vx();
    const double* vy = dem_->vy();
    const double* d = dem_->diameter();

    voidageP_.setSize(n);
    gasVelocityP_.setSize(n);
    diameterP_.setSize(n);
    slipP_.setSize(n);
    double* uX = dem_->gasVelocityX();
    double* uY = dem_->gasVelocityY();
    double* fX = dem_->extraForceX();
    double* fY = dem_->extraForceY();
    // One pass for all the per-particle inputs: gas, slip, and the
    // buoyancy of the hydrostatic gas pressure
    #pragma omp parallel for num_threads(nThreads) schedule(static)
    for (label i = 0; i < n; ++i)
    {
        scalar e;
        vector u;
        grid_.interpolate(x[i], y[i], eps, Uc, e, u);
        voidageP_[i] = e;
        gasVelocityP_[i] = u;
        diameterP_[i] = d[i];
        uX[i] = u.x();
        uY[i] = u.y();
        const scalar sx = u.x() - (frozen_ ? 0 : vx[i]);
        const scalar sy = u.y() - (frozen_ ? 0 : vy[i]);
        slipP_[i] = std::sqrt(sx*sx + sy*sy);   // not hypot: 5x dearer, no gain here
        const scalar Vp = pi*d[i]*d[i]*d[i]/6;
        fX[i] = -rhoGas_*Vp*g_.x();
        fY[i] = -rhoGas_*Vp*g_.y();
    }

    if (slab_)
    {
        slabGasInputs(slipP_);
    }
    if (mixtureNeeded_)
    {
        interpolateMixture();
    }

    K_.setSize(n);
    drag_->dragCoefficient(voidageP_, diameterP_, slipP_, mixtureP_, K_);

    double* Kd = dem_->dragCoefficient();
    #pragma omp parallel for num_threads(nThreads) schedule(static)
    for (label i = 0; i < n; ++i)
    {
        Kd[i] = K_[i];
    }
    formulation_->addPressureForce
    (
        *dem_, K_, grid_, p_rgh, particleFraction_, voidageMin_, nThreads
    );
    gasVelocitySeen_ = Uc;
}


void Foam::dpmCloud::advance()
{
    guarded(advanceError, [&]{ advanceParticles(); });
}


void Foam::dpmCloud::advanceParticles()
{
    if (frozen_)
    {
        // A fixed bed: the fluid force on particles held at rest
        const label n = size();
        frozenForce_.setSize(n);
        for (label i = 0; i < n; ++i)
        {
            frozenForce_[i] = vector
            (
                K_[i]*dem_->gasVelocityX()[i] + dem_->extraForceX()[i],
                K_[i]*dem_->gasVelocityY()[i] + dem_->extraForceY()[i],
                0
            );
        }
        return;
    }

    dem_->advance(dtStep_);
}


void Foam::dpmCloud::exchangedForces(vectorField& F) const
{
    formulation_->exchangedForces(*dem_, K_, frozen_, frozenForce_, F);
}


Foam::tmp<Foam::volScalarField> Foam::dpmCloud::gasFraction() const
{
    return couplingFormulation::gasFraction(particleFraction_, voidageMin_);
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


void Foam::dpmCloud::exchangeToGas()
{
    // The reaction on the gas, shared by the cells as the particle was at
    // the start of the step, where the gas was interpolated
    const label n = size();
    const scalar Vc = grid_.cellVolume();
    scalarField& Kc = Kc_.primitiveFieldRef();
    vectorField& Fp = Fp_.primitiveFieldRef();
    Kc = 0;
    Fp = Zero;
    vectorField exchanged;
    exchangedForces(exchanged);
    const labelList& counts = particleModel_.voidage().counts();
    const labelList& cells = particleModel_.voidage().cells();
    const scalarList& fractions = particleModel_.voidage().fractions();
    for (label i = 0; i < n; ++i)
    {
        const vector& F = exchanged[i];
        for (label k = 4*i; k < 4*i + counts[i]; ++k)
        {
            const label c = cells[k];
            const scalar f = fractions[k]/Vc;
            Kc[c] += f*K_[i];
            Fp[c] += f*F;
        }
    }
    Kc_.correctBoundaryConditions();
    Fp_.correctBoundaryConditions();
    // The boundary values too: the pressure equation takes the explicit
    // force Kc U* - Fp on the distributor face (constrainPressure); with U*
    // left 0 there it counted half the bottom row's drag a second time in
    // the distributor's pressure (docs/model.md, "The gas-side excess")
    Ustar_.primitiveFieldRef() = gasVelocitySeen_;
    Ustar_.correctBoundaryConditions();
    exchangeReady_ = true;
}


void Foam::dpmCloud::updateOverlaps()
{
    particleModel_.voidage().updateOverlaps
    (
        size(), dem_->x(), dem_->y(), dem_->diameter(),
        couplingThreads_
    );
}


void Foam::dpmCloud::updateVoidage()
{
    updateOverlaps();
    particleModel_.voidage().updateFields
    (
        size(), dem_->diameter(),
        voidage_.primitiveFieldRef(), particleFraction_.primitiveFieldRef()
    );
    particleFraction_.correctBoundaryConditions();
    voidage_.correctBoundaryConditions();

    if (mixtureNeeded_)
    {
        updateMixture();
    }
}


// ************************************************************************* //
