// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// MFIX's DEM verification case DEM06 (a sphere settling to its terminal velocity) as far as
// the DEM library alone represents it: the drag enters the library as a linear coefficient K
// (force K (u - v), the coupling's input), so with Stokes' K = 3 pi mu d in gas at rest the
// velocity approaches v_t = (m - m_gas) g/K as v_t (1 - exp(-t K/m)) (analytic). The drag of
// the solver's closures at the voidage the particle sees is covered by the solver's tests
// solver.terminalVelocity (2D, formulation A, slab).

#include "verification/VerificationHelpers.hpp"

using namespace dem;
using namespace dem::verification;

TEST(MfixDem06, SettlingSphereApproachesStokesTerminalVelocity)
{
    // A 50 um glass sphere in air (rho_p 2500, rho_g 1.2 kg/m^3, mu 1.8e-5 Pa s), buoyancy as
    // the extra force m_gas g; the velocity every 0.01 s up to 0.1 s (0.5 to 5 relaxation times)
    // within 0.1 % of v_t, at CFD steps of 1e-3 s of 10 DEM steps (the drag is implicit,
    // trapezoidal: its error is of order (dt K/m)^2, 2e-6 here).
    constexpr double d = 5e-5, rhoP = 2500.0, rhoG = 1.2, muG = 1.8e-5, g = 9.80665;
    const double m = sphereMass(d, rhoP), mGas = sphereMass(d, rhoG);
    const double K = 3.0 * pi * muG * d;
    const double vt = (m - mGas) * g / K, tau = m / K;
    for (int dimension : {2, 3}) {
        Settings s = oneClass(d, rhoP, {0.0, 5e-4, 0.0, 0.05}, dimension, 0.01, 1e-4);
        s.gravity[1] = -g;
        s.contact.kn = 1e-3;   // no contact here; a soft spring allows the long step
        Simulation sim(s);
        place(sim, 0, {2.5e-4, 0.045, 0.005}, Vec3::Zero(), Vec3::Zero());
        double worst = 0.0;
        for (int k = 1; k <= 100; ++k) {
            sim.dragCoefficient()[0] = K;
            sim.extraForceY()[0] = mGas * g;
            sim.advance(1e-3);
            if (k % 10 != 0) continue;
            const double expected = -vt * (1.0 - std::exp(-sim.time() / tau));
            EXPECT_NEAR(sim.vy()[0], expected, 1e-3 * vt) << engineName(dimension) << " t " << sim.time();
            worst = std::max(worst, std::abs(sim.vy()[0] - expected) / vt);
        }
        std::printf("  DEM06 %-4s v_t = %.5f m/s, tau = %.4f s: largest error %.2g of v_t\n",
                    engineName(dimension), vt, tau, worst);
    }
}
