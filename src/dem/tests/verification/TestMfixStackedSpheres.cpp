// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// MFIX's DEM verification case DEM03: two stacked spheres compressed between the floor and
// the ceiling under gravity (tests/dem/DEM03/mfix.dat: d = 1 mm, rho = 2e4 kg/m^3 below and
// 1e4 above, kn = 1e3 N/m for pair and walls, no friction). Reference: the static equilibrium
// of the three springs in series, analytic (MFIX's AUTOTEST keeps only its own earlier
// output for this case): kn dw = kn dp + m1 g, kn dp = kn dc + m2 g, dw + dp + dc = 2 d - H
// (dw, dp, dc: the floor's, the pair's and the ceiling's overlaps). MFIX compresses by
// 0.2 mm (20 % of d); the library refuses a particle placed overlapping a wall or another by
// more than 1 % of d, so the box here is 3 x 0.9 % of d lower than 2 d.

#include "verification/VerificationHelpers.hpp"

using namespace dem;
using namespace dem::verification;

TEST(MfixDem03, CompressedStackSettlesToTheSpringEquilibrium)
{
    // Tolerance 1e-4 of the mean overlap (the overlaps' gravity parts m g/kn are 5e-3 and
    // 1e-2 of it), after 150 contact times of damping at e = 0.5 (dt = tc/50).
    constexpr double d = 1e-3, kn = 1e3, g = 9.80665, e = 0.5;
    constexpr double r = 0.5 * d, squeeze = 0.009 * d;
    const double H = 2.0 * d - 3.0 * squeeze;
    const double m1 = sphereMass(d, 2e4), m2 = sphereMass(d, 1e4);
    const double dp = (3.0 * squeeze - (m1 - m2) * g / kn) / 3.0;
    const double dw = dp + m1 * g / kn, dc = dp - m2 * g / kn;
    for (int dimension : {2, 3}) {
        Settings s = oneClass(d, 2e4, {0.0, 0.01, 0.0, H}, dimension, 2.0 * d, 1.0);
        s.classes.push_back({"light", d, 1e4});
        s.dt = contactTime(0.5 * m2, kn, e) / 50.0;
        s.gravity[1] = -g;
        s.contact.kn = kn;
        s.contact.restitution = e;
        s.contact.restitutionWall = e;
        Simulation sim(s);
        place(sim, 0, {0.005, r - squeeze, d}, Vec3::Zero(), Vec3::Zero());
        place(sim, 1, {0.005, r - squeeze + d - squeeze, d}, Vec3::Zero(), Vec3::Zero());
        const double tc = contactTime(m1, kn, e);
        sim.advance(std::round(150.0 * tc / s.dt) * s.dt);
        const double y1 = sim.y()[0], y2 = sim.y()[1];
        const double scale = squeeze;
        EXPECT_NEAR(r - y1, dw, 1e-4 * scale) << engineName(dimension) << " floor";
        EXPECT_NEAR(d - (y2 - y1), dp, 1e-4 * scale) << engineName(dimension) << " pair";
        EXPECT_NEAR(y2 + r - H, dc, 1e-4 * scale) << engineName(dimension) << " ceiling";
        std::printf("  DEM03 %-4s overlaps floor %.6e (analytic %.6e), pair %.6e (%.6e), "
                    "ceiling %.6e (%.6e) m\n", engineName(dimension), r - y1, dw, d - (y2 - y1),
                    dp, y2 + r - H, dc);
    }
}
