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

#include "fluidizationVelocities.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fluidizationVelocities::fluidizationVelocities
(
    const particleEngine& engine,
    const dragModel& drag,
    const scalar rhoGas
)
:
    engine_(engine),
    drag_(drag),
    rhoGas_(rhoGas)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::fluidizationVelocities::restingDrag
(
    const scalar eps,
    const scalar d,
    const scalar dMean,
    const scalar U
) const
{
    const scalarField voidage(1, eps), diameter(1, d);
    particleMixture mixture;
    mixture.sauterDiameter = scalarField(1, dMean);
    scalarField K(1);
    // The particle rests: the slip is the interstitial velocity U/eps
    drag_.dragCoefficient(voidage, diameter, scalarField(1, U/eps), mixture, K);
    return K[0]*U/eps;
}


Foam::scalar Foam::fluidizationVelocities::velocityCarrying
(
    const scalar eps,
    const scalarList& weights,
    const scalar dMean,
    const scalar load
) const
{
    if (!(load > 0)) return 0;

    const scalarList d(engine_.classDiameters());
    auto drag = [&](const scalar U)
    {
        scalar F = 0;
        forAll(weights, k)
        {
            if (weights[k] > 0) F += weights[k]*restingDrag(eps, d[k], dMean, U);
        }
        return F;
    };
    scalar lower = 0, upper = 1;
    while (drag(upper) < load && upper < 1e6) upper *= 2;
    for (int i = 0; i < 200 && upper - lower > 1e-12*upper; ++i)
    {
        const scalar mid = 0.5*(lower + upper);
        (drag(mid) < load ? lower : upper) = mid;
    }
    return 0.5*(lower + upper);
}


Foam::scalar Foam::fluidizationVelocities::buoyantWeight
(
    const label classi,
    const scalar g
) const
{
    const scalar d = engine_.classDiameters()[classi];
    return
        constant::mathematical::pi*pow3(d)/6
       *(engine_.classDensities()[classi] - rhoGas_)*g;
}


Foam::scalarList Foam::fluidizationVelocities::unitWeight(const label classi) const
{
    scalarList w(engine_.classDiameters().size(), Zero);
    w[classi] = 1;
    return w;
}


Foam::scalar Foam::fluidizationVelocities::recipeSauterDiameter() const
{
    // Sum n_k E[d^3] over sum n_k E[d^2]: a distribution's own moments
    const std::vector<int> n(engine_.classCounts());
    const scalarList d3
    (
        particleEngine::classDiameterMoments(engine_.dem().settings(), 3)
    );
    const scalarList d2
    (
        particleEngine::classDiameterMoments(engine_.dem().settings(), 2)
    );
    scalar sum3 = 0, sum2 = 0;
    forAll(d3, k)
    {
        sum3 += n[k]*d3[k];
        sum2 += n[k]*d2[k];
    }
    return sum3/sum2;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::fluidizationVelocities::terminalVelocity
(
    const label classi,
    const scalar g
) const
{
    // A bed of voidage 1 of its own class
    return carryingVelocity(classi, 1, g, true);
}


Foam::scalar Foam::fluidizationVelocities::carryingVelocity
(
    const label classi,
    const scalar eps,
    const scalar g,
    const bool alone
) const
{
    return velocityCarrying
    (
        eps, unitWeight(classi),
        alone ? engine_.classDiameters()[classi] : recipeSauterDiameter(),
        buoyantWeight(classi, g)
    );
}


Foam::scalar Foam::fluidizationVelocities::mixtureUmf
(
    const scalar eps,
    const scalar g
) const
{
    const std::vector<int> n(engine_.classCounts());
    scalarList counts(n.size());
    scalar load = 0;
    forAll(counts, k)
    {
        counts[k] = n[k];
        load += n[k]*buoyantWeight(k, g);
    }
    return velocityCarrying(eps, counts, recipeSauterDiameter(), load);
}


// ************************************************************************* //
