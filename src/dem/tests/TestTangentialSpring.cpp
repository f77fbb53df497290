// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The tangential spring-dashpot's stiffness (contact entry kt, default 2/7 kn) and damping
// (tangentialDampingRatio = eta_t/eta_n, default 1) in both engines. A sphere resting on the
// floor whose contact point is set moving at vt0 without sliding oscillates as
//   m_t xi'' + eta_t xi' + kt xi = 0,   m_t = m I/(I + m r^2) = 2/7 m   (I = m d^2/10),
// since vx' = F/m and w' = r F/I move the contact point at vt = vx + w r: a damped period
// 2 pi/sqrt(kt/m_t - g^2) and a decay rate g = eta_t/(2 m_t). eta_n is computed from the restitution by
// TestHelpers' etaFor (the clamped dashpot's e(zeta), Schwager and Poeschel 2007).

#include "TestHelpers.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace dem;
using namespace dem::test;

namespace {

constexpr double kn = 800.0;
constexpr double eWall = 0.97;

double normalDamping(double m, double e) { return etaFor(m, kn, e); }

struct Oscillation {
    double period;   // s, mean over the peaks
    double decay;    // 1/s, from the first and last peaks
};

/// Peaks of vt = vx + w r of a small sphere on the floor, set turning at vt0 = 1e-4 m/s.
Oscillation tangentialOscillation(int dimension, double kt, double dampingRatio)
{
    const double dt = 2e-7;   // 2350 steps a period
    Settings s = paperSettings({0.0, 0.1, 0.0, 0.02}, dt);
    s.gravity[1] = -9.81;
    s.contact.kt = kt;
    s.contact.tangentialDampingRatio = dampingRatio;
    s.contact.frictionWall = 1.0;   // the spring's force stays far below mu m g
    s.dimension = dimension;
    s.slabDepth = dimension == 3 ? 0.01 : 0.0;
    Simulation sim(s);
    const double r = 0.5 * dSmall;
    const double y = r - sphereMass(dSmall) * 9.81 / kn;   // pressed by its weight
    const double w0 = 1e-4 / r;
    if (dimension == 2) {
        sim.addParticle(0, 0.01, y, 0.0, 0.0, w0);
    } else {
        sim.addParticle(0, {0.01, y, 0.005}, {}, {0.0, 0.0, w0});
    }
    std::vector<double> times, peaks;
    double previous = 0.0, before = 0.0;
    for (int k = 0; peaks.size() < 11 && k < 1000000; ++k) {
        sim.advance(dt);
        const double vt = sim.vx()[0] + sim.omegaZ()[0] * r;
        if (k > 10 && previous > before && previous >= vt) {
            times.push_back(sim.time() - dt);
            peaks.push_back(previous);
        }
        before = previous;
        previous = vt;
    }
    const double span = times.back() - times.front();
    return {span / (times.size() - 1), std::log(peaks.front() / peaks.back()) / span};
}

} // namespace

TEST(TangentialSpring, PeriodAndDecayFollowKtAndTangentialDamping)
{
    const double m = sphereMass(dSmall);
    const double mt = 2.0 / 7.0 * m;
    const double etaN = normalDamping(m, eWall);
    for (int dimension : {2, 3}) {
        for (double kt : {2.0 / 7.0 * kn, kn}) {
            for (double ratio : {0.0, 1.0, 2.0}) {
                const Oscillation got = tangentialOscillation(dimension, kt, ratio);
                const double g = ratio * etaN / (2.0 * mt);
                const double period = 2.0 * pi / std::sqrt(kt / mt - g * g);
                const char* name = dimension == 2 ? "2D" : "slab";
                // Period within 0.2 %, decay rate within 1 % (of the default's rate when 0)
                EXPECT_NEAR(got.period, period, 0.002 * period) << name << " kt " << kt << " ratio " << ratio;
                EXPECT_NEAR(got.decay, g, 0.01 * etaN / (2.0 * mt)) << name << " kt " << kt << " ratio " << ratio;
            }
        }
    }
}

TEST(TangentialSpring, DefaultsAreTwoSeventhsAndEqualDamping)
{
    const ContactSettings c;
    EXPECT_LT(c.kt, 0.0);   // 2/7 kn
    EXPECT_EQ(c.tangentialDampingRatio, 1.0);
}
