// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The normal force clamped at zero (docs/theory/dem.md, "Particles"): friction is limited by the
// compressive normal force only, so a contact that slides throughout takes a tangential
// impulse of exactly mu times its normal impulse (Coulomb's law of impact, e.g. Brach 1991;
// Chung and Ooi 2011, test 6's sliding regime); and the damping built for the clamped law
// gives the asked restitution of a head-on impact (Schwager and Poeschel 2007: the
// particles part when the force vanishes), including the overdamped range e < exp(-2).

#include "TestHelpers.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

using namespace dem;
using namespace dem::test;

namespace {

struct Impact {
    double normalImpulse;       // m (vy after - vy before), N s
    double tangentialImpulse;   // m (vx before - vx after), N s
    double restitution;         // -vy after / vy before
};

/// A small sphere hitting the floor y = 0 at (vx, -vy0) without spin or gravity, in the engine
/// of `dimension`, until it has left the floor.
Impact wallImpact(int dimension, double e, double mu, double vx, double vy0, double dt)
{
    Settings s = paperSettings({0.0, 0.1, 0.0, 0.02}, dt);
    s.contact.restitutionWall = e;
    s.contact.frictionWall = mu;
    s.dimension = dimension;
    s.slabDepth = dimension == 3 ? 0.01 : 0.0;
    Simulation sim(s);
    const double r = 0.5 * dSmall;
    const double y0 = r + 20.0 * vy0 * dt + 1e-9;   // touches after ~20 steps
    if (dimension == 2) {
        sim.addParticle(0, 0.01, y0, vx, -vy0);
    } else {
        sim.addParticle(0, {0.01, y0, 0.005}, {vx, -vy0, 0.0});
    }
    bool touched = false;
    for (int k = 0; k < 10000000; ++k) {
        sim.advance(dt);
        const bool inContact = sim.y()[0] < r;
        if (touched && !inContact && sim.vy()[0] > 0.0) break;
        touched = touched || inContact;
    }
    const double m = sim.mass()[0];
    return {m * (sim.vy()[0] + vy0), m * (vx - sim.vx()[0]), sim.vy()[0] / vy0};
}

const char* engineName(int dimension) { return dimension == 2 ? "2D" : "slab"; }

} // namespace

TEST(NormalForceClamp, SlidingImpulseIsMuTimesNormalImpulseAtHalfRestitution)
{
    // Tangential speed 5 x the normal one, mu = 0.3: the contact point slides throughout
    // (friction changes it by mu (1 + e)(1 + m r^2/I) vy0 = 1.6 vy0 at most). Within 1e-3.
    const double mu = 0.3;
    for (int dimension : {2, 3}) {
        const Impact got = wallImpact(dimension, 0.5, mu, 2.5, 0.5, 1e-6);
        EXPECT_NEAR(got.tangentialImpulse / got.normalImpulse, mu, 1e-3 * mu)
            << engineName(dimension);
    }
}

TEST(NormalForceClamp, HeadOnRestitutionIsTheInputWithTheClamp)
{
    // e from 0.97 to the overdamped 0.05, at dt = sqrt(m/kn)/500: within 0.5 % of the input
    const double dt = std::sqrt(sphereMass(dSmall) / 800.0) / 500.0;
    for (int dimension : {2, 3}) {
        for (double e : {0.97, 0.9, 0.5, 0.2, 0.05}) {
            const Impact got = wallImpact(dimension, e, 0.0, 0.0, 0.5, dt);
            EXPECT_NEAR(got.restitution, e, 0.005 * e) << engineName(dimension) << " e = " << e;
        }
    }
}

TEST(NormalForceClamp, ZeroRestitutionRefusedWithTheReason)
{
    Settings s = paperSettings({0.0, 0.1, 0.0, 0.02});
    s.contact.restitution = 0.0;
    try {
        Simulation sim(s);
        ADD_FAILURE() << "restitution 0 was accepted";
    } catch (const Error& err) {
        EXPECT_NE(std::string(err.what()).find("restitution = 0 is outside (0, 1]: e = 0 would "
                                               "need an infinite damping"),
                  std::string::npos)
            << err.what();
    }
}
