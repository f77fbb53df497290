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

// Formulation A (Zhou et al. 2010 set I) of dpmCloud: the pressure-gradient
// force on the particles, the drag K_A = eps_g K_B, the gas's share eps_g of
// the pressure gradient and the drag-only reaction (docs/model.md,
// "Formulations A and B"). Model B uses none of it.

#include "dpmCloud.H"
#include "fvcGrad.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * * //

void Foam::dpmCloud::warnThinSlab() const
{
    if (formulation_ != couplingFormulation::A) return;

    // The densest packing of the largest particles fills phiP =
    // pi/(2 sqrt 3) (2/3) d/depth of a cell's volume (hexagonal discs), at
    // most pi/(3 sqrt 2) (spheres in the slab mode)
    scalar dMax = 0;
    for (const scalar d : classDiameters()) dMax = max(dMax, d);
    const scalar pi = constant::mathematical::pi;
    const scalar phiPMax =
        slab_ ? pi/(3*sqrt(2.0)) : pi/(3*sqrt(3.0))*dMax/grid_.depth();
    if (phiPMax > 1 - voidageMin_)
    {
        WarningInFunction
            << "Formulation A in " << dict_.instance()/dict_.name()
            << ": the bed depth "
            << grid_.depth() << " m is thin for particles of " << dMax
            << " m: packed densely they fill phiP = " << phiPMax
            << " of a cell, more than 1 - voidageMin = " << 1 - voidageMin_
            << "; there eps_g = 1 - phiP is held at voidageMin and A no"
            << " longer matches B's pressure drop (docs/model.md,"
            << " formulations A and B)" << endl;
    }
}


void Foam::dpmCloud::addPressureGradientForce(const volScalarField& p_rgh)
{
    // -V_p grad p = -V_p grad p_rgh - rho_g V_p g, interpolated like the gas
    // velocity. The drag scales with the same eps_g as the gas's share of
    // grad p, so that A and B give the same fixed-bed pressure drop and Umf
    const volVectorField gradP(fvc::grad(p_rgh));
    const vectorField& gp = gradP.primitiveField();
    const scalarField& phiP = particleFraction_.primitiveField();
    const scalar pi = constant::mathematical::pi;
    const label n = size();
    const double* x = dem_->x();
    const double* y = dem_->y();
    const double* d = dem_->diameter();
    double* Kd = dem_->dragCoefficient();
    double* fX = dem_->extraForceX();
    double* fY = dem_->extraForceY();
    #pragma omp parallel for num_threads(couplingThreads_) schedule(static)
    for (label i = 0; i < n; ++i)
    {
        label cells[4];
        scalar w[4];
        grid_.interpolationStencil(x[i], y[i], cells, w);
        scalar epsG = 0;
        vector gradPi = Zero;
        for (int k = 0; k < 4; ++k)
        {
            epsG += w[k]*max(1 - phiP[cells[k]], voidageMin_);
            gradPi += w[k]*gp[cells[k]];
        }
        const scalar Vp = pi*d[i]*d[i]*d[i]/6;
        K_[i] *= epsG;
        Kd[i] = K_[i];
        fX[i] -= Vp*gradPi.x();
        fY[i] -= Vp*gradPi.y();
    }
}


Foam::tmp<Foam::volScalarField> Foam::dpmCloud::gasFraction() const
{
    return tmp<volScalarField>::New
    (
        "gasFraction",
        max
        (
            1 - particleFraction_,
            dimensionedScalar("voidageMin", dimless, voidageMin_)
        )
    );
}


Foam::vector Foam::dpmCloud::exchangedForce(const label i) const
{
    if (formulation_ == couplingFormulation::B)
    {
        return fluidForce(i);
    }
    // The drag K_i (u_i - mean v_i), as the DEM sums it into the mean force
    const scalar vx = frozen_ ? 0 : dem_->meanVelocityX()[i];
    const scalar vy = frozen_ ? 0 : dem_->meanVelocityY()[i];
    return K_[i]*vector
    (
        dem_->gasVelocityX()[i] - vx, dem_->gasVelocityY()[i] - vy, 0
    );
}


// ************************************************************************* //
