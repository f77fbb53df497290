// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Head-on restitution and contact duration (docs/theory/paper-model.md, "Particles"), and the bouncing
// ball. Expected values: e = 0.97 is the input the damping is built from, and it is exact
// for the linear spring-dashpot in continuous time; t_c from the formula in TestHelpers.

#include "TestHelpers.hpp"

#include <gtest/gtest.h>

#include <cstdio>

using namespace dem;
using namespace dem::test;

namespace {

struct Collision {
    double e;         // measured restitution
    double duration;  // measured contact duration, s
};

const Box bigBox{-0.05, 0.05, -0.05, 0.05};

/// Head-on collision of class a with class b (b = -1: the floor y = -0.05) at approach
/// speed 0.5 m/s, stepping one DEM step per advance().
Collision headOn(int a, int b, double dt)
{
    Settings s = paperSettings(bigBox, dt);
    Simulation sim(s);
    const double ra = 0.5 * s.classes[a].diameter;
    const double v0 = 0.5;
    const double gap = 20.0 * v0 * dt + 1e-7;   // touch after ~20 steps, off the step grid
    if (b < 0) {
        sim.addParticle(a, 0.0, bigBox.yMin + ra + gap, 0.0, -v0);
    } else {
        const double rb = 0.5 * s.classes[b].diameter;
        sim.addParticle(a, -ra - 0.5 * gap, 0.0, 0.5 * v0);
        sim.addParticle(b, rb + 0.5 * gap, 0.0, -0.5 * v0);
    }
    auto overlap = [&]() {
        if (b < 0) return ra - (sim.y()[0] - bigBox.yMin);
        const double rb = 0.5 * s.classes[b].diameter;
        return ra + rb - (sim.x()[1] - sim.x()[0]);
    };
    double start = -1.0, end = -1.0;
    double previous = overlap();
    for (int k = 0; k < 100000 && end < 0.0; ++k) {
        sim.advance(dt);
        const double now = overlap();
        const double t = sim.time();
        // Linear interpolation of the zero crossings of the overlap between steps.
        if (previous <= 0.0 && now > 0.0 && start < 0.0) start = t - dt * now / (now - previous);
        if (previous > 0.0 && now <= 0.0 && start >= 0.0) end = t - dt * now / (now - previous);
        previous = now;
    }
    Collision c;
    c.duration = end - start;
    c.e = b < 0 ? sim.vy()[0] / v0 : (sim.vx()[1] - sim.vx()[0]) / v0;
    return c;
}

double effectiveMass(int a, int b)
{
    const double d[2] = {dSmall, dLarge};
    const double ma = sphereMass(d[a]);
    if (b < 0) return ma;   // wall: mEff = m_i
    const double mb = sphereMass(d[b]);
    return ma * mb / (ma + mb);
}

struct Case {
    const char* name;
    int a, b;
};
const Case cases[] = {{"small-small", 0, 0}, {"small-large", 0, 1}, {"large-large", 1, 1},
                      {"small-wall", 0, -1}, {"large-wall", 1, -1}};

} // namespace

TEST(Restitution, HeadOnConvergesToInputAtTcOver50)
{
    // Tolerances: e within 0.2 % and t_c within 1 % at dt = t_c/50.
    for (const Case& c : cases) {
        const double tc = contactTime(effectiveMass(c.a, c.b), 800.0, 0.97);
        const Collision got = headOn(c.a, c.b, tc / 50.0);
        EXPECT_NEAR(got.e, 0.97, 0.002 * 0.97) << c.name;
        EXPECT_NEAR(got.duration, tc, 0.01 * tc) << c.name;
    }
}

TEST(Restitution, AtThePaperTimeStepAndConverging)
{
    // The effective e at the paper's dt = 1e-5 s and as dt falls, printed and checked. At
    // 1e-5 s every pair's t_c/dt is 16.5 or more, inside the safe bound t_c/10, where e is
    // within 1 % (docs/theory/numerics.md, "The DEM step's bound"). At t_c/50 and t_c/100 the step's
    // error is first order, e_DEM - e = (A (1 - 2 phi) + L)/N with A = (w t_c) zeta e,
    // L = (w t_c) (zeta^2/2) de/dzeta, phi the contact's onset within a step (the
    // verification README; derived in TestRestitutionStepOrder): within (A + |L|)/N at any
    // onset, A and L computed here from the clamped oscillator.
    std::printf("\n  %-12s %10s %10s %8s | e at dt = tc/10, tc/25, tc/50, tc/100\n", "pair",
                "tc [s]", "tc/dt", "e(1e-5)");
    for (const Case& c : cases) {
        const double mEff = effectiveMass(c.a, c.b);
        const double tc = contactTime(mEff, 800.0, 0.97);
        const Collision paper = headOn(c.a, c.b, 1e-5);
        std::printf("  %-12s %10.4g %10.2f %8.5f |", c.name, tc, tc / 1e-5, paper.e);
        const double zeta = etaFor(mEff, 800.0, 0.97) / (2.0 * std::sqrt(mEff * 800.0));
        const ClampedContactEnd end = clampedContactEnd(zeta);
        const double h = 1e-6;
        const double dedz = (clampedContactEnd(zeta + h).restitution
                             - clampedContactEnd(zeta - h).restitution) / (2.0 * h);
        const double firstOrder = end.time * zeta * 0.97 + std::abs(end.time * 0.5 * zeta * zeta * dedz);
        for (double n : {10.0, 25.0, 50.0, 100.0}) {
            const double e = headOn(c.a, c.b, tc / n).e;
            std::printf(" %8.5f", e);
            if (n >= 50.0) {
                EXPECT_LT(std::abs(e - 0.97), firstOrder / n) << c.name << " tc/" << n;
            }
        }
        std::printf("\n");
        ASSERT_GE(tc / 1e-5, 10.0) << c.name;   // the paper's step inside the safe bound
        EXPECT_NEAR(paper.e, 0.97, 0.01 * 0.97) << c.name;
        RecordProperty(std::string("e_at_1e-5_") + c.name, std::to_string(paper.e));
    }
}

TEST(Restitution, BouncingBallHeightsFallAsESquared)
{
    // A small particle dropped on the floor without friction: between bounces the flight is
    // ballistic, so the apex is y + vy^2/(2g) measured anywhere in flight, and
    // (h_k - r) = (h0 - r) e^(2k), within 0.5 %.
    const double tc = contactTime(sphereMass(dSmall), 800.0, 0.97);
    Settings s = paperSettings({0.0, 0.02, 0.0, 0.1}, tc / 50.0);
    s.gravity[1] = -9.81;
    s.contact.frictionWall = 0.0;
    Simulation sim(s);
    const double r = 0.5 * dSmall;
    const double h0 = 0.05;
    sim.addParticle(0, 0.01, h0);
    bool wasInContact = false;
    int k = 0;
    const double g = 9.81;
    while (k < 5 && sim.time() < 2.0) {
        sim.advance(s.dt);
        const bool inContact = sim.y()[0] < r;
        if (wasInContact && !inContact) {
            ++k;
            const double h = sim.y()[0] + sim.vy()[0] * sim.vy()[0] / (2.0 * g);
            const double expected = (h0 - r) * std::pow(0.97, 2 * k);
            EXPECT_NEAR(h - r, expected, 0.005 * expected) << "bounce " << k;
        }
        wasInContact = inContact;
    }
    EXPECT_EQ(k, 5);
}
