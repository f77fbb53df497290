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

#include "GidaspowBlend.H"
#include "ErgunWenYu.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{
namespace dragModels
{
    defineTypeNameAndDebug(GidaspowBlend, 0);
    addToRunTimeSelectionTable(dragModel, GidaspowBlend, dictionary);
}
}


Foam::dragModels::GidaspowBlend::GidaspowBlend
(
    const dictionary&,
    const scalar rho,
    const scalar mu
)
:
    dragModel(rho, mu)
{}


void Foam::dragModels::GidaspowBlend::dragCoefficient
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
        const scalar Vp = pi*d*d*d/6;

        // Weight of Ergun: 1 in the dense bed, 0 in the dilute gas
        const scalar phi = 0.5 + std::atan(262.5*(0.8 - eps))/pi;

        K[i] =
            (1 - phi)*ErgunWenYu::wenYuK(rho_, mu_, Vp, eps, d, slip[i])
          + phi*ErgunWenYu::ergunK(rho_, mu_, Vp, eps, d, slip[i]);
    }
}
