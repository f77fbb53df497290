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

#include "ErgunWenYu.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"
#include "positiveEntry.H"

namespace Foam
{
namespace dragModels
{
    defineTypeNameAndDebug(ErgunWenYu, 0);
    addToRunTimeSelectionTable(dragModel, ErgunWenYu, dictionary);
}
}


Foam::dragModels::ErgunWenYu::ErgunWenYu
(
    const dictionary& coeffs,
    const scalar rho,
    const scalar mu
)
:
    dragModel(rho, mu),
    switchVoidage_
    (
        boundedEntryOrDefault(coeffs, "switchVoidage", 0.8, 0, 1, true)
    )
{}


void Foam::dragModels::ErgunWenYu::dragCoefficient
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

        K[i] =
            eps < switchVoidage_
          ? ergunK(rho_, mu_, Vp, eps, d, slip[i])
          : wenYuK(rho_, mu_, Vp, eps, d, slip[i]);
    }
}
