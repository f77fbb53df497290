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

#include "A.H"
#include "fvcGrad.H"
#include "fvcSnGrad.H"
#include "surfaceInterpolate.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace couplingFormulations
{
    defineTypeNameAndDebug(A, 0);
    addToRunTimeSelectionTable(couplingFormulation, A, dictionary);
}
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::string Foam::couplingFormulations::A::description() const
{
    return
        "formulation A (Zhou et al. 2010 set II): particles feel the"
        " drag eps_g K_B (u - v) and the pressure-gradient force"
        " -V_p grad p; the gas carries eps_g grad p and the drag only";
}


void Foam::couplingFormulations::A::checkBedDepth
(
    const IOdictionary& dict,
    const scalar depth,
    const scalar dMax,
    const scalar phiPMax,
    const scalar voidageMin
) const
{
    if (phiPMax > 1 - voidageMin)
    {
        WarningInFunction
            << "Formulation A in " << dict.instance()/dict.name()
            << ": the bed depth "
            << depth << " m is thin for particles of " << dMax
            << " m: packed densely they fill phiP = " << phiPMax
            << " of a cell, more than 1 - voidageMin = " << 1 - voidageMin
            << "; there eps_g = 1 - phiP is held at voidageMin and A no"
            << " longer matches B's pressure drop (docs/theory/coupling.md,"
            << " formulations A and B)" << endl;
    }
}


void Foam::couplingFormulations::A::addPressureForce
(
    dem::Simulation& particles,
    scalarField& K,
    const cellWeights& stencils,
    const volScalarField& p_rgh,
    const volScalarField& particleFraction,
    const scalar voidageMin,
    const bool withZ,
    const label nThreads
) const
{
    // -V_p grad p = -V_p grad p_rgh - rho_g V_p g, interpolated like the gas
    // velocity. The drag scales with the same eps_g as the gas's share of
    // grad p, so that A and B give the same fixed-bed pressure drop and Umf
    const volVectorField gradP(fvc::grad(p_rgh));
    const vectorField& gp = gradP.primitiveField();
    const scalarField& phiP = particleFraction.primitiveField();
    const scalar pi = constant::mathematical::pi;
    const label n = label(particles.size());
    const double* d = particles.diameter();
    double* Kd = particles.dragCoefficient();
    double* fX = particles.extraForceX();
    double* fY = particles.extraForceY();
    double* fZ = withZ ? particles.extraForceZ() : nullptr;
    const label S = stencils.stride;
    const labelList& cells = stencils.cells;
    const scalarList& w = stencils.weights;

    #pragma omp parallel for num_threads(nThreads) schedule(static)
    for (label i = 0; i < n; ++i)
    {
        scalar epsG = 0;
        vector gradPi = Zero;
        for (label k = S*i; k < S*i + stencils.counts[i]; ++k)
        {
            epsG += w[k]*max(1 - phiP[cells[k]], voidageMin);
            gradPi += w[k]*gp[cells[k]];
        }
        const scalar Vp = pi*d[i]*d[i]*d[i]/6;
        K[i] *= epsG;
        Kd[i] = K[i];
        fX[i] -= Vp*gradPi.x();
        fY[i] -= Vp*gradPi.y();
        if (fZ) fZ[i] -= Vp*gradPi.z();
    }
}


void Foam::couplingFormulations::A::exchangedForces
(
    dem::Simulation& particles,
    const scalarField& K,
    const bool frozen,
    const vectorField&,
    const bool withZ,
    vectorField& F
) const
{
    // The drag K_i (u_i - mean v_i), as the DEM sums it into the mean force
    const label n = label(particles.size());
    F.setSize(n);
    for (label i = 0; i < n; ++i)
    {
        const scalar vx = frozen ? 0 : particles.meanVelocityX()[i];
        const scalar vy = frozen ? 0 : particles.meanVelocityY()[i];
        const scalar vz =
            (frozen || !withZ) ? 0 : particles.meanVelocityZ()[i];
        F[i] = K[i]*vector
        (
            particles.gasVelocityX()[i] - vx,
            particles.gasVelocityY()[i] - vy,
            withZ ? particles.gasVelocityZ()[i] - vz : 0
        );
    }
}


void Foam::couplingFormulations::A::interpolateGasFraction
(
    const volScalarField& particleFraction,
    const scalar voidageMin,
    surfaceScalarField& gasFractionf
) const
{
    gasFractionf = fvc::interpolate(gasFraction(particleFraction, voidageMin));
}


Foam::tmp<Foam::surfaceScalarField>
Foam::couplingFormulations::A::pressureCoefficient
(
    const surfaceScalarField& rAUf,
    const surfaceScalarField& gasFractionf
) const
{
    return rAUf*gasFractionf;
}


Foam::tmp<Foam::surfaceScalarField>
Foam::couplingFormulations::A::pressureGradient
(
    const volScalarField& p_rgh,
    const surfaceScalarField& gasFractionf
) const
{
    return gasFractionf*fvc::snGrad(p_rgh);
}


Foam::tmp<Foam::volVectorField> Foam::couplingFormulations::A::explicitForce
(
    const tmp<volVectorField>& reaction,
    const dimensionedScalar&,
    const volScalarField&,
    const dimensionedVector&
) const
{
    return reaction;
}


void Foam::couplingFormulations::A::umfBalanceNote
(
    Ostream& os,
    const scalarList& densities
) const
{
    if (max(densities) > min(densities))
    {
        os  << nl << "Note: formulation A with classes of different densities:"
            << " their shares of the bed's pressure gradient differ, which"
            << " these balances (formulation B's) leave out" << nl;
    }
}


// ************************************************************************* //
