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

#include "B.H"
#include "fvcSnGrad.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace couplingFormulations
{
    defineTypeNameAndDebug(B, 0);
    addToRunTimeSelectionTable(couplingFormulation, B, dictionary);
}
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::string Foam::couplingFormulations::B::description() const
{
    return
        "formulation B (the paper's, Zhou et al. 2010 set III): the gas"
        " sees the whole pressure gradient; particles feel the drag"
        " K_B (u - v) and the buoyancy -rho_g V_p g";
}


void Foam::couplingFormulations::B::exchangedForces
(
    dem::Simulation& particles,
    const scalarField&,
    const bool frozen,
    const vectorField& frozenForce,
    const bool withZ,
    vectorField& F
) const
{
    const label n = label(particles.size());
    F.setSize(n);
    if (frozen)
    {
        F = frozenForce;
        return;
    }
    const double* FX = particles.meanFluidForceX();
    const double* FY = particles.meanFluidForceY();
    const double* FZ = withZ ? particles.meanFluidForceZ() : nullptr;
    for (label i = 0; i < n; ++i)
    {
        F[i] = vector(FX[i], FY[i], FZ ? FZ[i] : 0);
    }
}


Foam::tmp<Foam::surfaceScalarField>
Foam::couplingFormulations::B::pressureCoefficient
(
    const surfaceScalarField& rAUf,
    const surfaceScalarField&
) const
{
    return tmp<surfaceScalarField>(rAUf);
}


Foam::tmp<Foam::surfaceScalarField>
Foam::couplingFormulations::B::pressureGradient
(
    const volScalarField& p_rgh,
    const surfaceScalarField&
) const
{
    return fvc::snGrad(p_rgh);
}


Foam::tmp<Foam::volVectorField> Foam::couplingFormulations::B::explicitForce
(
    const tmp<volVectorField>& reaction,
    const dimensionedScalar& rho,
    const volScalarField& particleFraction,
    const dimensionedVector& g
) const
{
    return reaction - rho*particleFraction*g;
}


// ************************************************************************* //
