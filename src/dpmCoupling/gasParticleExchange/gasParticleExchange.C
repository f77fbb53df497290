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
    gasParticleExchange: the gas interpolated to the particles with their
    drag, the reaction mapped back to the gas, and the voidage.
\*---------------------------------------------------------------------------*/

#include "gasParticleExchange.H"
#include "emptyFvPatch.H"
#include "fixedValueFvPatchFields.H"
#include "zeroGradientFvPatchFields.H"
#include "mathematicalConstants.H"

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


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::gasParticleExchange::gasParticleExchange
(
    const fvMesh& mesh,
    const gasGrid& grid,
    particleEngine& engine,
    const dragModel& drag,
    const couplingFormulation& formulation,
    particleModel& model,
    const scalar rhoGas,
    const vector& g,
    const bool frozen,
    const scalar voidageMin,
    const word& inletPatch,
    const bool writeVoidage,
    const bool writeReaction
)
:
    mesh_(mesh),
    grid_(grid),
    engine_(engine),
    drag_(drag),
    formulation_(formulation),
    particleModel_(model),
    rhoGas_(rhoGas),
    g_(g),
    frozen_(frozen),
    voidageMin_(voidageMin),
    nThreads_(1),
    reactionReady_(false),
    voidage_
    (
        fieldIO("voidage", mesh, writeVoidage),
        mesh,
        dimensionedScalar("one", dimless, 1.0),
        voidagePatchTypes(mesh, inletPatch)
    ),
    particleFraction_
    (
        fieldIO("particleFraction", mesh, false),
        mesh,
        dimensionedScalar("zero", dimless, 0.0),
        zeroGradientFvPatchScalarField::typeName
    ),
    mixtureNeeded_(drag.needsMixture()),
    Kc_
    (
        fieldIO("Kc", mesh, writeReaction),
        mesh,
        dimensionedScalar(dimDensity/dimTime, Zero),
        zeroGradientFvPatchScalarField::typeName
    ),
    Fp_
    (
        fieldIO("Fp", mesh, writeReaction),
        mesh,
        dimensionedVector(dimForce/dimVolume, Zero),
        zeroGradientFvPatchVectorField::typeName
    ),
    Ustar_
    (
        fieldIO("Ustar", mesh, writeReaction),
        mesh,
        dimensionedVector(dimVelocity, Zero),
        zeroGradientFvPatchVectorField::typeName
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::volScalarField> Foam::gasParticleExchange::gasFraction() const
{
    return couplingFormulation::gasFraction(particleFraction_, voidageMin_);
}


void Foam::gasParticleExchange::interpolateGas
(
    const volVectorField& U,
    const volScalarField& p_rgh
)
{
    dem::Simulation& dem = engine_.dem();
    const label n = engine_.size();
    const label nThreads = nThreads_;
    const scalar pi = constant::mathematical::pi;
    const scalarField& eps = voidage_.primitiveField();
    const vectorField& Uc = U.primitiveField();

    const double* vx = dem.vx();
    const double* vy = dem.vy();
    const double* d = dem.diameter();

    voidageP_.setSize(n);
    gasVelocityP_.setSize(n);
    diameterP_.setSize(n);
    slipP_.setSize(n);
    double* uX = dem.gasVelocityX();
    double* uY = dem.gasVelocityY();
    double* fX = dem.extraForceX();
    double* fY = dem.extraForceY();
    grid_.interpolationStencils
    (
        n, dem.x(), dem.y(), engine_.z(), nThreads, stencils_
    );
    // One pass for all the per-particle inputs: gas, slip, and the
    // buoyancy of the hydrostatic gas pressure
    #pragma omp parallel for num_threads(nThreads) schedule(static)
    for (label i = 0; i < n; ++i)
    {
        const scalar e = stencils_.interpolate(i, eps);
        const vector u = stencils_.interpolate(i, Uc);
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

    if (engine_.movesInDepth())
    {
        depthGasInputs(slipP_);
    }
    if (mixtureNeeded_)
    {
        interpolateMixture();
    }

    K_.setSize(n);
    drag_.dragCoefficient(voidageP_, diameterP_, slipP_, mixtureP_, K_);

    double* Kd = dem.dragCoefficient();
    #pragma omp parallel for num_threads(nThreads) schedule(static)
    for (label i = 0; i < n; ++i)
    {
        Kd[i] = K_[i];
    }
    formulation_.addPressureForce
    (
        dem, K_, stencils_, p_rgh, particleFraction_, voidageMin_,
        grid_.resolvedInDepth(), nThreads
    );
    gasVelocitySeen_ = Uc;
}


void Foam::gasParticleExchange::depthGasInputs(scalarField& slip)
{
    dem::Simulation& dem = engine_.dem();
    const label n = engine_.size();
    const double* vx = dem.vx();
    const double* vy = dem.vy();
    const double* vz = dem.vz();
    const double* d = dem.diameter();
    double* uZ = dem.gasVelocityZ();
    double* fZ = dem.extraForceZ();
    const scalar pi = constant::mathematical::pi;
    const bool gasZ = grid_.resolvedInDepth();
    for (label i = 0; i < n; ++i)
    {
        // A gas one cell thick has no z velocity; a gas resolved in depth has
        const vector& u = gasVelocityP_[i];
        const scalar uz = gasZ ? u.z() : 0;
        uZ[i] = uz;
        fZ[i] = gasZ ? -rhoGas_*pi*d[i]*d[i]*d[i]/6*g_.z() : 0;
        if (frozen_) continue;      // slip of particles at rest, as set
        const scalar sx = u.x() - vx[i];
        const scalar sy = u.y() - vy[i];
        const scalar sz = uz - vz[i];
        slip[i] = std::sqrt(sx*sx + sy*sy + sz*sz);
    }
}


void Foam::gasParticleExchange::holdFrozen()
{
    dem::Simulation& dem = engine_.dem();
    const label n = engine_.size();
    const bool gasZ = grid_.resolvedInDepth();
    frozenForce_.setSize(n);
    for (label i = 0; i < n; ++i)
    {
        frozenForce_[i] = vector
        (
            K_[i]*dem.gasVelocityX()[i] + dem.extraForceX()[i],
            K_[i]*dem.gasVelocityY()[i] + dem.extraForceY()[i],
            gasZ
          ? K_[i]*dem.gasVelocityZ()[i] + dem.extraForceZ()[i]
          : 0
        );
    }
}


void Foam::gasParticleExchange::exchangeToGas()
{
    // The reaction on the gas, shared by the cells as the particle was at
    // the start of the step, where the gas was interpolated
    const label n = engine_.size();
    const scalarField& Vc = grid_.cellVolumes();
    scalarField& Kc = Kc_.primitiveFieldRef();
    vectorField& Fp = Fp_.primitiveFieldRef();
    Kc = 0;
    Fp = Zero;
    vectorField exchanged;
    exchangedForces(exchanged);
    const labelList& counts = particleModel_.voidage().counts();
    const labelList& cells = particleModel_.voidage().cells();
    const scalarList& fractions = particleModel_.voidage().fractions();
    const label S = particleModel_.voidage().stride();
    for (label i = 0; i < n; ++i)
    {
        const vector& F = exchanged[i];
        for (label k = S*i; k < S*i + counts[i]; ++k)
        {
            const label c = cells[k];
            const scalar f = fractions[k]/Vc[c];
            Kc[c] += f*K_[i];
            Fp[c] += f*F;
        }
    }
    // Smoothed as the voidage the particles saw; the sums, hence the
    // momentum handed over, are kept
    const coarseGraining& smoothing = particleModel_.smoothing();
    if (smoothing.active())
    {
        smoothing.smooth(Kc);
        smoothing.smooth(Fp);
    }
    Kc_.correctBoundaryConditions();
    Fp_.correctBoundaryConditions();
    // The boundary values too: the pressure equation takes the explicit
    // force Kc U* - Fp on the distributor face (constrainPressure); with U*
    // left 0 there it counted half the bottom row's drag a second time in
    // the distributor's pressure (docs/theory/numerics.md, "The gas-side excess")
    Ustar_.primitiveFieldRef() = gasVelocitySeen_;
    Ustar_.correctBoundaryConditions();
    reactionReady_ = true;
}


void Foam::gasParticleExchange::updateOverlaps()
{
    const dem::Simulation& dem = engine_.dem();
    particleModel_.voidage().updateOverlaps
    (
        engine_.size(), dem.x(), dem.y(), engine_.z(), dem.diameter(),
        nThreads_
    );
}


void Foam::gasParticleExchange::updateVoidage()
{
    updateOverlaps();
    const dem::Simulation& dem = engine_.dem();
    particleModel_.voidage().updateFields
    (
        engine_.size(), dem.diameter(),
        voidage_.primitiveFieldRef(), particleFraction_.primitiveFieldRef()
    );
    const coarseGraining& smoothing = particleModel_.smoothing();
    if (smoothing.active())
    {
        // The voidage of the smoothed fraction, bounded as the voidage
        // model bounds it (the smoothing needs a voidage 1 - phiP)
        scalarField& phiP = particleFraction_.primitiveFieldRef();
        smoothing.smooth(phiP);
        scalarField& eps = voidage_.primitiveFieldRef();
        forAll(eps, c)
        {
            eps[c] = max(1 - phiP[c], voidageMin_);
        }
    }
    particleFraction_.correctBoundaryConditions();
    voidage_.correctBoundaryConditions();

    if (mixtureNeeded_)
    {
        updateMixture();
    }
}


void Foam::gasParticleExchange::exchangedForces(vectorField& F) const
{
    formulation_.exchangedForces
    (
        engine_.dem(), K_, frozen_, frozenForce_, grid_.resolvedInDepth(), F
    );
}


// ************************************************************************* //
