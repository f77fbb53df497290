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
    gasParticleExchange: the log's exchange balance, and the reaction a
    concurrent run saved for its gas's next step, read at a restart.
\*---------------------------------------------------------------------------*/

#include "gasParticleExchange.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// The values of a field (internal, then its boundary conditions) as a time
// directory holds them under the field's name
template<class FieldType>
void readSavedValues(FieldType& field, const Foam::fvMesh& mesh)
{
    using namespace Foam;
    const FieldType saved
    (
        IOobject
        (
            field.name(),
            mesh.time().timeName(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false               // the field itself is registered
        ),
        mesh
    );
    field.primitiveFieldRef() = saved.primitiveField();
    field.correctBoundaryConditions();
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::gasParticleExchange::balanceSums
Foam::gasParticleExchange::balance() const
{
    balanceSums b;
    b.particleForce = Zero;
    b.particleDrag = 0;
    if (K_.size() == engine_.size())
    {
        vectorField F;
        exchangedForces(F);
        for (const vector& Fi : F) b.particleForce += Fi;
        b.particleDrag = sum(K_);
    }
    b.gasForce = gSum(Fp_.primitiveField()*grid_.cellVolumes());
    b.gasDrag = gSum(Kc_.primitiveField()*grid_.cellVolumes());
    const voidageModel& voidage = particleModel_.voidage();
    const Pair<scalar> amounts = voidage.amounts
    (
        engine_.size(), engine_.dem().diameter(),
        particleFraction_.primitiveField()
    );
    b.particleAmount = amounts.first();
    b.mappedAmount = amounts.second();
    b.amountName = voidage.amountName();
    return b;
}


void Foam::gasParticleExchange::reportBalance(Ostream& os) const
{
    const balanceSums b = balance();
    const vector& particleForce = b.particleForce;
    const vector& gasForce = b.gasForce;

    os  << "Exchange: force on particles " << particleForce
        << " N, reaction mapped to the gas " << gasForce << " N" << nl;
    const vector excess = gasForce - particleForce;
    os  << "Exchange: reaction less the force on the particles " << excess
        << " N, relative " << mag(excess)/max(mag(particleForce), VSMALL)
        << nl;
    os  << "Exchange: drag coefficients of the particles " << b.particleDrag
        << " kg/s, the gas's implicit share " << b.gasDrag << " kg/s" << nl;

    // A fixed bed: the fluid force on each class of the held particles
    // (with one particle in a class, that particle's)
    if (frozen_ && frozenForce_.size() == engine_.size())
    {
        const dem::Simulation& dem = engine_.dem();
        const auto& classes = dem.settings().classes;
        const int* cls = dem.classIndex();
        List<vector> byClass(label(classes.size()), Zero);
        forAll(frozenForce_, i)
        {
            byClass[cls[i]] += frozenForce_[i];
        }
        forAll(byClass, k)
        {
            os  << "Exchange: fluid force on the held class "
                << classes[k].name.c_str() << " " << byClass[k] << " N" << nl;
        }
    }
    os  << "Exchange: particle " << b.amountName.c_str() << " "
        << b.particleAmount << " " << b.unit() << ", mapped to cells "
        << b.mappedAmount << " " << b.unit() << endl;
}


void Foam::gasParticleExchange::readSavedReaction()
{
    // Kc, Fp and U* are written only by a concurrent run; with them, the
    // voidage of the time is the one its gas took (a step behind the
    // particles), the old-time level of the next step
    IOobject probe
    (
        Kc_.name(),
        mesh_.time().timeName(),
        mesh_,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    if (!probe.typeHeaderOk<volScalarField>(true))
    {
        Info<< "Coupling: no reaction saved at time "
            << mesh_.time().timeName() << "; the first step is sequential"
            << endl;
        return;
    }
    readSavedValues(Kc_, mesh_);
    readSavedValues(Fp_, mesh_);
    readSavedValues(Ustar_, mesh_);
    readSavedValues(voidage_, mesh_);
    reactionReady_ = true;
    Info<< "Coupling: the reaction and the gas's voidage of time "
        << mesh_.time().timeName() << " read (Kc, Fp, Ustar, voidage); the"
        << " concurrent schedule continues from them" << endl;
}


// ************************************************************************* //
