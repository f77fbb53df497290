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

#include "KochHill.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{
namespace dragModels
{
    defineTypeNameAndDebug(KochHill, 0);
    addToRunTimeSelectionTable(dragModel, KochHill, dictionary);
}
}


Foam::dragModels::KochHill::KochHill
(
    const dictionary&,
    const scalar rho,
    const scalar mu
)
:
    dragModel(rho, mu)
{}


Foam::scalar Foam::dragModels::KochHill::F0(const scalar a)
{
    if (a >= 0.4)
    {
        return 10*a/pow3(1 - a);
    }
    // a ln a -> 0 as a -> 0 (a particle alone in its cells)
    const scalar aLna = a > 0 ? a*std::log(a) : 0;
    return
        (1 + 3*std::sqrt(0.5*a) + 135.0/64.0*aLna + 16.14*a)
       /(1 + 0.681*a - 8.48*a*a + 8.16*a*a*a);
}


Foam::scalar Foam::dragModels::KochHill::F3(const scalar a)
{
    return 0.0673 + 0.212*a + 0.0232/pow5(1 - a);
}


void Foam::dragModels::KochHill::dragCoefficient
(
    const scalarField& voidage,
    const scalarField& diameter,
    const scalarField& slip,
    const particleMixture&,
    scalarField& K
) const
{
    const scalar pi = constant::mathematical::pi;

    #pragma omp parallel for num_threads(nThreads_) schedule(static)
    forAll(K, i)
    {
        const scalar eps = voidage[i];
        const scalar a = max(1 - eps, scalar(0));
        const scalar d = diameter[i];
        const scalar Re = rho_*d*eps*slip[i]/mu_;

        K[i] = 3*pi*mu_*d*eps*(F0(a) + 0.5*F3(a)*Re);
    }
}
