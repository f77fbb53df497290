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
    Test-dpmCoupling: the drag closures for mixtures (GidaspowBlend,
    KochHill, Beetstra) against their limits and values worked by hand from
    the published formulas (GoogleTest suites MixtureClosures, GidaspowBlend,
    KochHill and Beetstra).

\*---------------------------------------------------------------------------*/

#include "couplingTest.H"
#include "dragModel.H"
#include "KochHill.H"
#include "Beetstra.H"
#include "mathematicalConstants.H"

using namespace Foam;

// The closures for mixtures. Hand values: the published formulas worked
// with Python's math module (not this code) for rho = 1.204 kg/m3,
// mu = 1.75e-5 Pa s, d = 1.5 mm; K = beta V_p/(1 - eps), beta the
// two-fluid coefficient divided by eps (the gas sees the whole grad p)
namespace
{
    const scalar pi = constant::mathematical::pi;
    const scalar rho = 1.204, mu = 1.75e-5, d = 1.5e-3;
    const scalar Vp = pi*d*d*d/6;
    const scalar stokes = 3*pi*mu*d;
    const scalar creep = 1e-6*mu/(rho*d);

    //- A drag model by name
    autoPtr<dragModel> model(const word& type)
    {
        dictionary dict;
        dict.add("dragModel", type);
        return dragModel::New(dict, rho, mu);
    }

    //- Its K of one particle of diameter d at eps and slip, in a mixture
    //  of Sauter mean diameter dMean when dMean > 0
    scalar K1(const dragModel& m, const scalar eps, const scalar slip, const scalar dMean = 0)
    {
        scalarField K(1);
        const particleMixture noMixture;
        particleMixture mix;
        if (dMean > 0) mix.sauterDiameter = scalarField(1, dMean);
        m.dragCoefficient(scalarField(1, eps), scalarField(1, d), scalarField(1, slip), dMean > 0 ? mix : noMixture, K);
        return K[0];
    }
}


TEST(MixtureClosures, OnlyBeetstraNeedsTheMixture)
{
    autoPtr<dragModel> blend(model("GidaspowBlend"));
    autoPtr<dragModel> kochHill(model("KochHill"));
    autoPtr<dragModel> beetstra(model("Beetstra"));
    check("only Beetstra needs the mixture", blend->needsMixture() + kochHill->needsMixture() + 10*beetstra->needsMixture(), 10, 0);
}


// Huilin and Gidaspow (2003): beta = (1 - phi) beta_WenYu + phi beta_Ergun,
// phi = 1/2 + arctan(262.5 (alpha_s - 0.2))/pi
TEST(GidaspowBlend, LimitsHandValuesAndContinuity)
{
    autoPtr<dragModel> blend(model("GidaspowBlend"));
    // At eps = 1 the Ergun weight is 1/2 + arctan(-52.5)/pi = 0.0060623
    // (hand), and Ergun's drag vanishes there as Re -> 0: Stokes x 0.99394
    check("GidaspowBlend at eps = 1, Re -> 0: Stokes x (1 - 0.0060623)", K1(*blend, 1, creep), stokes*(1 - 0.006062312362569933), 1e-3);
    // eps = 1, slip 0.5 m/s (Re 51.6): Schiller-Naumann K = C_D rho pi d^2 |u-v|/8
    // = 8.0469e-7; the blend keeps an Ergun weight 0.0061 there: 8.07337e-7
    {
        const scalar Re = rho*d*0.5/mu;
        const scalar Cd = 24/Re*(1 + 0.15*std::pow(Re, 0.687));
        check("GidaspowBlend at eps = 1: Schiller-Naumann (Ergun weight 0.006)", K1(*blend, 1, 0.5), Cd*rho*pi*d*d*0.5/8, 0.005);
        check("GidaspowBlend at eps = 1, 0.5 m/s (hand)", K1(*blend, 1, 0.5), 8.073372333338735e-07, 1e-12);
    }
    check("GidaspowBlend eps 0.6, 1 m/s (hand)", K1(*blend, 0.6, 1), 6.423249587474494e-06, 1e-12);
    check("GidaspowBlend eps 0.8, 1 m/s: mean of Ergun and Wen-Yu (hand)", K1(*blend, 0.8, 1), 3.0218247847649264e-06, 1e-12);
    check("GidaspowBlend eps 0.95, 0.5 m/s (hand)", K1(*blend, 0.95, 0.5), 9.509303663485336e-07, 1e-12);
    // Continuous across alpha_s = 0.2, where ErgunWenYu jumps by 1.6 x
    for (const scalar slip : {0.2, 2.0})
    {
        const scalar below = K1(*blend, 0.8 - 1e-9, slip), above = K1(*blend, 0.8 + 1e-9, slip);
        check("GidaspowBlend continuous at eps = 0.8, " + std::to_string(slip).substr(0, 3) + " m/s", above, below, 1e-6);
    }
}


// Hill, Koch and Ladd (2001) as Bokkers et al. (2004):
// beta_A = 18 mu eps^2 alpha_s/d^2 (F0 + F3 Re/2), Re = rho d eps |u-v|/mu
TEST(KochHill, LimitsAndHandValues)
{
    autoPtr<dragModel> kochHill(model("KochHill"));
    check("KochHill at eps = 1, Re -> 0: Stokes", K1(*kochHill, 1, creep), stokes, 1e-3);
    // Dense, Re -> 0: F0 = 10 alpha_s/eps^3 is Carman-Kozeny,
    // -dp/dx = 180 alpha_s^2 mu Us/(eps^3 d^2) at the superficial Us = eps u
    {
        const scalar eps = 0.4, Us = eps*creep;
        check("KochHill fixed bed at eps 0.4: Carman-Kozeny", (1 - eps)/Vp*K1(*kochHill, eps, creep)*creep, 180*sqr(1 - eps)*mu*Us/(pow3(eps)*d*d), 1e-5);
    }
    check("KochHill eps 0.7, 1 m/s (Re 72.2, hand)", K1(*kochHill, 0.7, 1), 3.3166296673548563e-06, 1e-12);
    check("KochHill eps 0.5, 0.3 m/s (Re 15.5, hand)", K1(*kochHill, 0.5, 0.3), 5.824735899592724e-06, 1e-12);
    check("KochHill F0 at alpha_s = 0.4: jump to Carman-Kozeny (hand 1.04 %)", dragModels::KochHill::F0(0.4)/dragModels::KochHill::F0(0.4 - 1e-12) - 1, 0.010421515760360656, 1e-8);
}


// Beetstra, van der Hoef and Kuipers (2007): F(a, Re), Re on <d> and
// the superficial slip; f_i = eps y + a y^2 + 0.064 eps y^3
TEST(Beetstra, FAgainstLimitsAndHandValues)
{
    using dragModels::Beetstra;
    check("Beetstra F at a = 0, Re = 0: Stokes", Beetstra::F(0, 0), 1, 1e-15);
    check("Beetstra F(0.5, 0) = 10 a/eps^2 + eps^2 (1 + 1.5 sqrt a) (hand)", Beetstra::F(0.5, 0), 20.515165042944954, 1e-14);
    check("Beetstra F(0.4, 100) (hand)", Beetstra::F(0.4, 100), 30.741552554327278, 1e-12);
    check("Beetstra F(0.2, 10) (hand)", Beetstra::F(0.2, 10), 5.187160872063553, 1e-12);
    // Single sphere: a fit, within 6 % of Schiller-Naumann 1 + 0.15 Re^0.687 at Re 10
    check("Beetstra F(0, 10) near Schiller-Naumann", Beetstra::F(0, 10), 1 + 0.15*std::pow(10.0, 0.687), 0.06);
    check("Beetstra F(0, Re -> 0) continuous", Beetstra::F(0, 1e-12), 1, 1e-6);
}


// Equal sizes: y = 1, f = 1 + 0.064 eps (the published f_i), so K is
// the monodisperse 3 pi mu d F (1 + 0.064 eps)
TEST(Beetstra, EqualSizesAreMonodisperseTimesF)
{
    using dragModels::Beetstra;
    autoPtr<dragModel> beetstra(model("Beetstra"));
    const scalar eps = 0.6, slip = 0.5;
    const scalar Re = rho*eps*slip*d/mu;
    check("Beetstra equal sizes: monodisperse F times f(y = 1)", K1(*beetstra, eps, slip, d), stokes*Beetstra::F(1 - eps, Re)*(1 + 0.064*eps), 1e-14);
    check("Beetstra at eps = 1, Re -> 0: Stokes times f(y = 1) = 1.064", K1(*beetstra, 1, creep, d)/stokes, 1.064, 1e-3);
}


// Binary at equal volumes of 1.5 and 2.5 mm: <d> = 1.875 mm, y = 0.8
// and 4/3, eps 0.6, slip 0.5 m/s (<Re> 38.7), hand: small 3.66377e-6,
// large 1.29464e-5 N s/m
TEST(Beetstra, BinaryAgainstHandValues)
{
    autoPtr<dragModel> beetstra(model("Beetstra"));
    const scalar dMean = 1/(0.5/1.5e-3 + 0.5/2.5e-3);
    check("Beetstra small in a binary (hand)", K1(*beetstra, 0.6, 0.5, dMean), 3.663767146745189e-06, 1e-12);
    scalarField Kl(1);
    particleMixture mix;
    mix.sauterDiameter = scalarField(1, dMean);
    beetstra->dragCoefficient(scalarField(1, 0.6), scalarField(1, 2.5e-3), scalarField(1, 0.5), mix, Kl);
    check("Beetstra large in a binary (hand)", Kl[0], 1.294638077333998e-05, 1e-12);
}
