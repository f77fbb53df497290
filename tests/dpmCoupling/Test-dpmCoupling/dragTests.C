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
Description
    Test-dpmCoupling: Wen-Yu's Umf of the paper's Table 3, and the
    single-particle drag laws against Stokes, Ergun and Dallavalle
    (GoogleTest suites Umf and DragLaws).

\*---------------------------------------------------------------------------*/

#include "couplingTest.H"
#include "fluidization.H"
#include "dragModel.H"
#include "mathematicalConstants.H"

using namespace Foam;

static const scalar pi = constant::mathematical::pi;


// Wen-Yu Umf of the paper's Table 3 within 7 % (docs/theory/paper-model.md, "Minimum fluidization velocity")
TEST(Umf, WenYuMatchesPaperTable3)
{
    const scalar wSmall[3] = {0.25, 0.5, 0.75};
    const scalar bar[4] = {1, 8, 32, 64};
    const scalar table3[3][4] =
    {
        {1.10, 0.45, 0.23, 0.17},
        {0.98, 0.41, 0.22, 0.15},
        {0.87, 0.38, 0.20, 0.14}
    };
    const scalarList d({1.5e-3, 2.5e-3});
    for (int i = 0; i < 3; ++i)
    {
        const scalarList w({wSmall[i], 1 - wSmall[i]});
        const scalar dMix = fluidization::harmonicMeanDiameter(w, d);
        for (int j = 0; j < 4; ++j)
        {
            const scalar Umf = fluidization::wenYuUmf
            (
                dMix, 2525, 1.204*bar[j], 1.75e-5, 9.81
            );
            check
            (
                "Umf w_small " + std::to_string(wSmall[i]).substr(0, 4)
              + " at " + std::to_string(int(bar[j])) + " bar (Table 3)",
                Umf, table3[i][j], 0.07
            );
        }
    }
    check
    (
        "harmonic mean diameter at w = 0.5",
        fluidization::harmonicMeanDiameter(scalarList({0.5, 0.5}), d),
        1.875e-3, 1e-12
    );
}


// Drag laws against textbook single-sphere and packed-bed results
namespace
{
    const scalar rho = 1.204, mu = 1.75e-5, d = 1.5e-3;
    const scalar Vp = pi*d*d*d/6;

    //- A drag model by name
    autoPtr<dragModel> model(const word& type)
    {
        dictionary dict;
        dict.add("dragModel", type);
        return dragModel::New(dict, rho, mu);
    }

    //- Its K of one particle of diameter d at eps and slip
    scalar K1(const dragModel& m, const scalar eps, const scalar slip)
    {
        scalarField K(1);
        const particleMixture noMixture;
        m.dragCoefficient(scalarField(1, eps), scalarField(1, d), scalarField(1, slip), noMixture, K);
        return K[0];
    }
}


// Stokes' law at eps = 1 and Re = 1e-6: K = 3 pi mu d
TEST(DragLaws, WenYuAtVoidageOneIsStokes)
{
    const scalar creep = 1e-6*mu/(rho*d);
    check("Wen-Yu at eps = 1, Re -> 0: Stokes", K1(*model("ErgunWenYu"), 1.0, creep), 3*pi*mu*d, 1e-3);
}


// Ergun: n K u = 150 (1-e)^2 mu Us/(e^3 d^2) + 1.75 (1-e) rho Us^2/(e^3 d)
TEST(DragLaws, ErgunWenYuGivesErgunPressureGradient)
{
    const scalar eps = 0.4, u = 1.0, Us = eps*u;
    const scalar K = K1(*model("ErgunWenYu"), eps, u);
    const scalar ergun =
        150*sqr(1 - eps)*mu*Us/(pow3(eps)*d*d)
      + 1.75*(1 - eps)*rho*Us*Us/(pow3(eps)*d);
    check("Ergun pressure gradient of a fixed bed", (1 - eps)/Vp*K*u, ergun, 1e-12);
}


// Di Felice at eps = 1: Dallavalle C_D = (0.63 + 4.8/sqrt(Re))^2
TEST(DragLaws, DiFeliceAtVoidageOneIsDallavalle)
{
    const scalar slip = 0.5, Re = rho*d*slip/mu;
    const scalar K = K1(*model("DiFelice"), 1.0, slip);
    const scalar Cd = sqr(0.63 + 4.8/std::sqrt(Re));
    check("Di Felice at eps = 1: Dallavalle drag", K*slip, 0.5*Cd*rho*0.25*pi*d*d*slip*slip, 1e-12);
}
