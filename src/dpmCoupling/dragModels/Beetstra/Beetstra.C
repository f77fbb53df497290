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

#include "Beetstra.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{
namespace dragModels
{
    defineTypeNameAndDebug(Beetstra, 0);
    addToRunTimeSelectionTable(dragModel, Beetstra, dictionary);
}
}


Foam::dragModels::Beetstra::Beetstra
(
    const dictionary&,
    const scalar rho,
    const scalar mu
)
:
    dragModel(rho, mu)
{}


Foam::scalar Foam::dragModels::Beetstra::F(const scalar a, const scalar Re)
{
    const scalar eps = 1 - a;
    const scalar eps2 = eps*eps;

    // The inertial term with numerator and denominator multiplied by
    // Re^((1 + 4a)/2): finite, and zero, at Re = 0
    const scalar s = std::pow(Re, 0.5 + 2*a);
    const scalar inertial =
        0.413/(24*eps2)
       *(Re/eps + 3*eps*a*Re + 8.4*std::pow(Re, 0.657))*s
       /(s + std::pow(10.0, 3*a));

    return 10*a/eps2 + eps2*(1 + 1.5*std::sqrt(a)) + inertial;
}


Foam::scalar Foam::dragModels::Beetstra::correction
(
    const scalar eps,
    const scalar y
)
{
    return eps*y + (1 - eps)*y*y + 0.064*eps*y*y*y;
}


void Foam::dragModels::Beetstra::dragCoefficient
(
    const scalarField& voidage,
    const scalarField& diameter,
    const scalarField& slip,
    const particleMixture& mixture,
    scalarField& K
) const
{
    const scalarField& dMean = mixture.sauterDiameter;
    if (dMean.size() != K.size())
    {
        FatalErrorInFunction
            << "The Beetstra drag needs the Sauter mean diameter at each of"
            << " the " << K.size() << " particles, got " << dMean.size()
            << abort(FatalError);
    }

    const scalar pi = constant::mathematical::pi;

    #pragma omp parallel for num_threads(nThreads_) schedule(static)
    forAll(K, i)
    {
        const scalar eps = voidage[i];
        const scalar a = max(1 - eps, scalar(0));
        const scalar d = diameter[i];
        const scalar Re = rho_*eps*slip[i]*dMean[i]/mu_;

        K[i] = 3*pi*mu_*d*F(a, Re)*correction(eps, d/dMean[i]);
    }
}
