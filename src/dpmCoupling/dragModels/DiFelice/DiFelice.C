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

#include "DiFelice.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{
namespace dragModels
{
    defineTypeNameAndDebug(DiFelice, 0);
    addToRunTimeSelectionTable(dragModel, DiFelice, dictionary);
}
}


Foam::dragModels::DiFelice::DiFelice
(
    const dictionary&,
    const scalar rho,
    const scalar mu
)
:
    dragModel(rho, mu)
{}


void Foam::dragModels::DiFelice::dragCoefficient
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
        const scalar d = diameter[i];
        const scalar Re = max(rho_*d*eps*slip[i]/mu_, 1e-12);

        // C_D |u-v| = (0.63 sqrt|u-v| + 4.8 sqrt(mu/(rho d eps)))^2
        const scalar CdSlip =
            sqr(0.63*std::sqrt(slip[i]) + 4.8*std::sqrt(mu_/(rho_*d*eps)));
        const scalar chi =
            3.7 - 0.65*std::exp(-0.5*sqr(1.5 - std::log10(Re)));

        K[i] = 0.5*CdSlip*rho_*0.25*pi*d*d*std::pow(eps, 1 - chi);
    }
}
