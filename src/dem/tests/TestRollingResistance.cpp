// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Constant-torque rolling resistance (Ai, Chen, Rotter and Ooi 2011, "type A"; docs/theory/dem.md,
// "Rolling resistance") in both engines: a sphere rolling on the floor decelerates at the
// model's rate and stops where and when it predicts; on a slope it holds below the angle the
// model allows and rolls above it at the predicted acceleration; a pressed pair with opposite
// spins keeps its angular momentum and stops rolling relative to each other at the model's
// rate, without reversing. Expected values are derived
// here from rigid-body mechanics (the 2D engine's discs have a sphere's I = m d^2/10):
//   rolling without slip, torque M = mu_r r m g cos(theta) against the spin, friction F:
//   m a = m g sin(theta) - F,  I a / r = F r - M   =>   a = g (sin - mu_r cos) / (1 + I/(m r^2)),
//   at rest while tan(theta) <= mu_r (the torque balance F r = M with F = m g sin(theta)).
// On a slope below that angle the clamped torque (at most I |w| / (n dt), n = 4 steps) lets the
// sphere creep at the speed where it balances F r: v = n dt g sin(theta) m r^2 / I, which
// vanishes with dt; the test checks that speed.

#include "TestHelpers.hpp"
#include "dem/ContactKernel.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <utility>
#include <algorithm>

using namespace dem;
using namespace dem::test;

namespace {

constexpr double g = 9.81;
constexpr double muR = 0.1;
constexpr double inertiaRatio = 0.4;   // I/(m r^2) of a solid sphere

/// One small sphere on the floor y = 0 of the engine of `dimension`, rolling along x at v0
/// without slip, under gravity tilted by theta (a slope), with rolling resistance muR.
std::unique_ptr<Simulation> roller(int dimension, double v0, double theta, double dt = 1e-5)
{
    Settings s = paperSettings({0.0, 0.1, 0.0, 0.02}, dt);
    s.gravity[0] = g * std::sin(theta);
    s.gravity[1] = -g * std::cos(theta);
    s.contact.frictionWall = 0.5;   // no slip at these angles and rates
    s.contact.rollingFrictionWall = muR;
    s.dimension = dimension;
    s.slabDepth = dimension == 3 ? 0.01 : 0.0;
    auto sim = std::make_unique<Simulation>(s);
    const double r = 0.5 * dSmall;
    if (dimension == 2) {
        sim->addParticle(0, 0.01, r, v0, 0.0, -v0 / r);
    } else {
        sim->addParticle(0, {0.01, r, 0.005}, {v0, 0.0, 0.0}, {0.0, 0.0, -v0 / r});
    }
    return sim;
}

const char* engineName(int dimension) { return dimension == 2 ? "2D" : "slab"; }

} // namespace

TEST(RollingResistance, RollingSphereStopsAtPredictedDistanceAndTime)
{
    const double v0 = 0.1;
    const double a = muR * g / (1.0 + inertiaRatio);   // deceleration, m/s^2
    const double tStop = v0 / a;
    const double distance = v0 * v0 / (2.0 * a);
    for (int dimension : {2, 3}) {
        auto sim = roller(dimension, v0, 0.0);
        const double x0 = sim->x()[0];
        double stopped = -1.0;
        double vHalf = 0.0;
        const double dt = sim->settings().dt;
        while (sim->time() < 1.5 * tStop) {
            sim->advance(dt);
            if (std::abs(sim->time() - 0.5 * tStop) < 0.5 * dt) vHalf = sim->vx()[0];
            if (stopped < 0.0 && sim->vx()[0] <= 1e-3 * v0) stopped = sim->time();
        }
        // Within 1 %: the rate at half time, the stop, the distance; then at rest
        EXPECT_NEAR(vHalf, 0.5 * v0, 0.01 * 0.5 * v0) << engineName(dimension);
        EXPECT_NEAR(stopped, tStop, 0.01 * tStop) << engineName(dimension);
        EXPECT_NEAR(sim->x()[0] - x0, distance, 0.01 * distance) << engineName(dimension);
        EXPECT_LT(std::abs(sim->vx()[0]), 1e-4 * v0) << engineName(dimension);
        EXPECT_LT(std::abs(sim->omegaZ()[0]), 1e-4 * v0 / (0.5 * dSmall)) << engineName(dimension);
    }
}

TEST(RollingResistance, SphereOnSlopeHoldsBelowTheBoundAndRollsAbove)
{
    for (int dimension : {2, 3}) {
        // Below: tan(theta) = mu_r / 2, the creep speed of the clamp and no more
        const double below = std::atan(0.5 * muR);
        auto held = roller(dimension, 0.0, below);
        const double dt = held->settings().dt;
        held->advance(0.3);
        const double creep = dem::rollingStopSteps * dt * g * std::sin(below) / inertiaRatio;
        EXPECT_NEAR(held->vx()[0], creep, 0.05 * creep) << engineName(dimension);
        const double x1 = held->x()[0];
        held->advance(0.2);
        EXPECT_NEAR(held->x()[0] - x1, 0.2 * creep, 0.05 * 0.2 * creep) << engineName(dimension);
        // Halving the step halves the creep: at rest as dt -> 0
        auto finer = roller(dimension, 0.0, below, 0.5 * dt);
        finer->advance(0.3);
        EXPECT_NEAR(finer->vx()[0], 0.5 * creep, 0.05 * 0.5 * creep) << engineName(dimension);

        // Above: tan(theta) = 2 mu_r, rolling at a = g (sin - mu_r cos) / (1 + I/(m r^2))
        const double above = std::atan(2.0 * muR);
        auto rolls = roller(dimension, 0.0, above);
        const double a = g * (std::sin(above) - muR * std::cos(above)) / (1.0 + inertiaRatio);
        rolls->advance(0.1);
        const double v1 = rolls->vx()[0];
        rolls->advance(0.2);
        const double v2 = rolls->vx()[0];
        EXPECT_NEAR((v2 - v1) / 0.2, a, 0.01 * a) << engineName(dimension);
        const double r = 0.5 * dSmall;
        EXPECT_NEAR(rolls->omegaZ()[0], -v2 / r, 0.01 * v2 / r) << engineName(dimension);
    }
}

TEST(RollingResistance, OffByDefaultAndNegativeRefused)
{
    const Settings s = paperSettings({0.0, 0.1, 0.0, 0.02});
    EXPECT_EQ(s.contact.rollingFriction, 0.0);
    EXPECT_EQ(s.contact.rollingFrictionWall, 0.0);
    for (int which : {0, 1}) {
        Settings bad = s;
        (which == 0 ? bad.contact.rollingFriction : bad.contact.rollingFrictionWall) = -0.1;
        try {
            Simulation sim(bad);
            ADD_FAILURE() << "a negative rolling friction was accepted";
        } catch (const Error& e) {
            const std::string expected =
                std::string(which == 0 ? "rollingFriction" : "rollingFrictionWall")
                + " = -0.1 is outside [0, inf)";
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
        }
    }
}

TEST(RollingResistance, PairTorqueIsMuRTimesRollingRadiusTimesNormalForceAndOpposite)
{
    // Two spheres of radii 1 and 2 mm pressed together, turning relative to each other: the
    // torque on i is mu_r R_r Fn against w_i - w_j (R_r = r_i r_j/(r_i + r_j)), on j its
    // opposite; a relative rolling too slow for the full torque gets I_eff |w|/(n dt).
    const double ri = 1e-3, rj = 2e-3, dt = 1e-5;
    const double mi = sphereMass(2 * ri), mj = sphereMass(2 * rj);
    const double ii = 0.4 * mi * ri * ri, ij = 0.4 * mj * rj * rj;
    ContactLaw law = makeContactLaw(mi * mj / (mi + mj), 800.0, -1.0, 0.9, 0.3);
    addRollingResistance(law, muR, ri * rj / (ri + rj), ii * ij / (ii + ij), dt);
    const double overlap = 1e-6;
    const double fn = 800.0 * overlap;   // at rest: the spring alone
    const double full = muR * ri * rj / (ri + rj) * fn;

    PairGeometry g2{overlap, {1.0, 0.0}, {0.0, 0.0}, ri, rj, 0.0, 5.0};
    const PairForce f2 = contactForce<2, LinearSpringDashpot, true>(g2, law, dt);
    EXPECT_NEAR(f2.rollingTorque, -full, 1e-12 * full);
    EXPECT_NEAR(f2.torqueI - ri * f2.ft, -full, 1e-12 * full);
    EXPECT_NEAR(f2.torqueJ - rj * f2.ft, full, 1e-12 * full);

    const double slow = 1e-3 * full * rollingStopSteps * dt * (1 / ii + 1 / ij);
    g2.omegaRel = -slow;
    const double clamped = contactForce<2, LinearSpringDashpot, true>(g2, law, dt).rollingTorque;
    EXPECT_NEAR(clamped, slow / (rollingStopSteps * dt * (1 / ii + 1 / ij)), 1e-9 * full);

    // 3D: the twist about nHat is not rolling; the rolling part (0, 3, 4) gets the torque
    PairGeometry3 g3;
    g3.overlap = overlap;
    g3.nHat = Eigen::Vector3d(1.0, 0.0, 0.0);
    g3.vRel.setZero();
    g3.rI = ri;
    g3.rJ = rj;
    g3.xiT.setZero();
    g3.omegaRel = Eigen::Vector3d(7.0, 3.0, 4.0);
    const PairForce3 f3 = contactForce<3, LinearSpringDashpot, true>(g3, law, dt);
    const Eigen::Vector3d expected = -full * Eigen::Vector3d(0.0, 0.6, 0.8);
    EXPECT_LT((f3.rollingTorque - expected).norm(), 1e-12 * full);
    EXPECT_LT((f3.torqueI + f3.torqueJ).norm(), 1e-12 * full);   // no tangential force here
}

namespace {

/// Two equal spheres stacked on the floor of the engine of `dimension` at their static
/// overlaps (floor 2 m g/kn, pair m g/kn), the lower spinning at +w0 and the upper at -w0
/// about z: their contact points move together (w r - w r = 0), so the pair's only torque is
/// the rolling resistance (frictionless floor, none on it). Particle 0 below, 1 above.
std::unique_ptr<Simulation> spinningStack(int dimension, double w0)
{
    Settings s = paperSettings({0.0, 0.02, 0.0, 0.02});
    s.gravity[1] = -g;
    s.contact.frictionWall = 0.0;
    s.contact.rollingFriction = muR;
    s.dimension = dimension;
    s.slabDepth = dimension == 3 ? 0.01 : 0.0;
    auto sim = std::make_unique<Simulation>(s);
    const double r = 0.5 * dSmall, weight = sphereMass(dSmall) * g, kn = s.contact.kn;
    const double y0 = r - 2.0 * weight / kn, y1 = y0 + 2.0 * r - weight / kn;
    if (dimension == 2) {
        sim->addParticle(0, 0.01, y0, 0.0, 0.0, w0);
        sim->addParticle(0, 0.01, y1, 0.0, 0.0, -w0);
    } else {
        sim->addParticle(0, {0.01, y0, 0.005}, {}, {0.0, 0.0, w0});
        sim->addParticle(0, {0.01, y1, 0.005}, {}, {0.0, 0.0, -w0});
    }
    return sim;
}

} // namespace

TEST(RollingResistance, PressedPairWithOppositeSpinsStopsRollingAtTheModelsRate)
{
    // Rigid-body mechanics of the stack: the pair carries the upper sphere's weight,
    // F_n = m g, and the torques -+M, M = mu_r R* F_n (R* = r/2), act on the two spins
    // only, so I (w_0 + w_1) = 0 is kept and the relative rolling w_r = w_0 - w_1 falls
    // at M/I_eff (I_eff = I/2) from 2 w0 to 0 at t_stop, where the clamp (at most
    // I_eff |w_r|/(n dt)) stops it without reversing it. Tolerances: 1 % on the rate and
    // the stop (the normal force settles within a fraction of a percent of m g at the
    // placed overlaps), 1e-9 of I w0 on the angular momentum (round-off of the torque sums).
    const double w0 = 10.0;
    const double m = sphereMass(dSmall), r = 0.5 * dSmall, inertia = 0.1 * m * dSmall * dSmall;
    const double rate = muR * 0.5 * r * m * g / (0.5 * inertia);
    const double tStop = 2.0 * w0 / rate;
    for (int dimension : {2, 3}) {
        auto sim = spinningStack(dimension, w0);
        const double dt = sim->settings().dt;
        double atHalf = NAN, stopped = -1.0, worstMomentum = 0.0, lowest = INFINITY;
        while (sim->time() < 1.5 * tStop) {
            sim->advance(dt);
            const double w0Now = sim->omegaZ()[0], w1Now = sim->omegaZ()[1];
            const double relative = w0Now - w1Now;
            worstMomentum = std::max(worstMomentum, std::abs(w0Now + w1Now) / w0);
            lowest = std::min(lowest, relative);
            if (std::abs(sim->time() - 0.5 * tStop) < 0.5 * dt) atHalf = relative;
            if (stopped < 0.0 && relative <= 1e-3 * 2.0 * w0) stopped = sim->time();
        }
        const char* engine = engineName(dimension);
        EXPECT_LT(worstMomentum, 1e-9) << engine;
        EXPECT_NEAR(atHalf, w0, 0.01 * w0) << engine;
        EXPECT_NEAR(stopped, tStop, 0.01 * tStop) << engine;
        // Stopped, not reversed: the relative rolling never changes sign and ends at rest
        EXPECT_GE(lowest, 0.0) << engine;
        EXPECT_LT(std::abs(sim->omegaZ()[0] - sim->omegaZ()[1]), 1e-6 * w0) << engine;
        EXPECT_NEAR(sim->x()[1], sim->x()[0], 1e-9 * r) << engine;   // the stack stays upright
    }
}

namespace {

/// A triangular lattice of 7 x 7 small spheres pressed 5 um into each other (no gravity, no
/// friction, far from the walls), spinning about z in the lattice's mixed-phase mode: +w0 on
/// one of its three sublattices, -w0/2 on the other two (a sphere's six neighbours are three
/// of each other sublattice). Every contact rolls at 1.5 w0 within the clamp. Returns the
/// engine and the index of the middle sphere (on the +w0 sublattice).
std::pair<std::unique_ptr<Simulation>, int> spinningLattice(int dimension, double w0)
{
    Settings s = paperSettings({0.0, 0.03, 0.0, 0.03});
    s.gravity[1] = 0.0;
    s.contact.frictionParticle = 0.0;
    s.contact.frictionWall = 0.0;
    s.contact.rollingFriction = 1.0;   // mu_r R* F_n = 1.5e-6 N m: above the clamp's 2e-7
    s.dimension = dimension;
    s.slabDepth = dimension == 3 ? 0.01 : 0.0;
    auto sim = std::make_unique<Simulation>(s);
    const double a = dSmall - 5e-6;
    int middle = -1;
    for (int j = 0; j < 7; ++j) {
        for (int i = 0; i < 7; ++i) {
            const double x = 0.008 + a * (i + 0.5 * j), y = 0.01 + a * 0.5 * std::sqrt(3.0) * j;
            const double w = ((i - j) % 3 + 3) % 3 == 0 ? w0 : -0.5 * w0;
            if (i == 3 && j == 3) middle = static_cast<int>(sim->size());
            if (dimension == 2) {
                sim->addParticle(0, x, y, 0.0, 0.0, w);
            } else {
                sim->addParticle(0, {x, y, 0.005}, {}, {0.0, 0.0, w});
            }
        }
    }
    return {std::move(sim), middle};
}

} // namespace

TEST(RollingResistance, ManyClampedContactsStopTheRollingWithoutReversing)
{
    // Each clamped contact takes I_eff/(n I) = 1/8 of its relative rolling from each sphere
    // in a step; in the mixed-phase mode the middle sphere's six contacts would take
    // 6 x 1.5/8 = 9/8 of its spin, reversing it every step. With the limit of
    // RollingLimit.hpp (each sphere's shares summing to at most 1/2, here 2/3 of them kept)
    // the mode decays without changing sign: the middle sphere's spin stays positive and
    // falls below 1 % of w0 in 5 steps ((1 - 3/4)^5 = 1e-3 in the linear estimate), while
    // the torques, equal and opposite, keep the angular momentum (round-off, 1e-9 of I w0).
    const double w0 = 10.0;
    for (int dimension : {2, 3}) {
        auto [sim, middle] = spinningLattice(dimension, w0);
        const double dt = sim->settings().dt;
        auto momentum = [&] {
            double sum = 0.0;
            for (std::size_t k = 0; k < sim->size(); ++k) sum += sim->omegaZ()[k];
            return sum;   // equal spheres: I times it is the angular momentum
        };
        const double start = momentum();
        double lowest = w0, worstMomentum = 0.0;
        for (int step = 0; step < 5; ++step) {
            sim->advance(dt);
            lowest = std::min(lowest, sim->omegaZ()[middle]);
            worstMomentum = std::max(worstMomentum, std::abs(momentum() - start) / w0);
        }
        const char* engine = engineName(dimension);
        EXPECT_GE(lowest, 0.0) << engine << ": the middle sphere's spin reversed";
        EXPECT_LT(sim->omegaZ()[middle], 0.01 * w0) << engine;
        EXPECT_LT(worstMomentum, 1e-9) << engine;
    }
}

TEST(RollingResistance, SphereHeldByFourWallsKeepsTheLimitsShareOfItsSpin)
{
    // A sphere pressed 5 um into the four sides of a tight box, spinning about z: each wall
    // contact is clamped and would take 1/n = 1/4 of the spin in a step, 1 in all; the
    // limit (D = 1, scale 1/2) lets the four take 1/2. Velocity Verlet applies half of it
    // at the start spin and half at the half-step spin: w(dt) = (1 - 1/4)^2 w0 = 0.5625 w0
    // (without the limit (1 - 1/2)^2 = 0.25). Tolerance 1e-9: the torques are linear in the
    // spin within the clamp and the sphere does not move.
    const double w0 = 10.0;
    const double side = dSmall - 1e-5;
    for (int dimension : {2, 3}) {
        Settings s = paperSettings({0.0, side, 0.0, side});
        s.gravity[1] = 0.0;
        s.contact.frictionWall = 0.0;
        s.contact.rollingFrictionWall = 1.0;
        s.dimension = dimension;
        s.slabDepth = dimension == 3 ? 0.01 : 0.0;
        Simulation sim(s);
        if (dimension == 2) {
            sim.addParticle(0, 0.5 * side, 0.5 * side, 0.0, 0.0, w0);
        } else {
            sim.addParticle(0, {0.5 * side, 0.5 * side, 0.005}, {}, {0.0, 0.0, w0});
        }
        const double dt = sim.settings().dt;
        sim.advance(dt);
        const char* engine = engineName(dimension);
        EXPECT_NEAR(sim.omegaZ()[0], 0.5625 * w0, 1e-9 * w0) << engine;
        for (int step = 0; step < 40; ++step) {
            sim.advance(dt);
            EXPECT_GE(sim.omegaZ()[0], 0.0) << engine << ", step " << step;
        }
    }
}

TEST(RollingResistance, ObliqueSpinningImpactKeepsTheAngularMomentum)
{
    // Two small spheres in free space, one moving at 0.5 m/s at 30 degrees to the line of
    // centres, the other spinning at 200 rad/s about z: the pair slides, rolls and parts,
    // with friction 0.3 and rolling friction 0.1. The total angular momentum about z,
    // sum I w + m (x v_y - y v_x), is kept up to the lever arm's offset: the contact's
    // torques act at r_i, the contact point lies at r_i - delta/2, so the pair's torques
    // miss delta n x F_t: 1.3e-3 of m v0 r at these overlaps (tolerance 1e-2 of it).
    // A torque of wrong sign on either sphere moves it by about 2 r J_t, half of m v0 r.
    const double v0 = 0.5, spin = 200.0;
    const double m = sphereMass(dSmall), r = 0.5 * dSmall, inertia = 0.1 * m * dSmall * dSmall;
    for (int dimension : {2, 3}) {
        Settings s = paperSettings({0.0, 0.03, 0.0, 0.03});
        s.gravity[1] = 0.0;
        s.contact.frictionParticle = 0.3;
        s.contact.rollingFriction = 0.1;
        s.dimension = dimension;
        s.slabDepth = dimension == 3 ? 0.01 : 0.0;
        Simulation sim(s);
        const double gap = 2.0 * r + 1e-6, angle = pi / 6.0;
        const double x1 = 0.015 + gap * std::cos(angle), y1 = 0.015 + gap * std::sin(angle);
        if (dimension == 2) {
            sim.addParticle(0, 0.015, 0.015, v0, 0.0, 0.0);
            sim.addParticle(0, x1, y1, 0.0, 0.0, spin);
        } else {
            sim.addParticle(0, {0.015, 0.015, 0.005}, {v0, 0.0, 0.0});
            sim.addParticle(0, {x1, y1, 0.005}, {}, {0.0, 0.0, spin});
        }
        auto angularMomentum = [&] {
            double l = 0.0;
            for (int k = 0; k < 2; ++k) {
                l += inertia * sim.omegaZ()[k]
                     + m * (sim.x()[k] * sim.vy()[k] - sim.y()[k] * sim.vx()[k]);
            }
            return l;
        };
        const double start = angularMomentum(), scale = m * v0 * r;
        double worst = 0.0;
        bool touched = false;
        for (int step = 0; step < 400; ++step) {
            sim.advance(sim.settings().dt);
            touched = touched || sim.contactCount() > 0;
            worst = std::max(worst, std::abs(angularMomentum() - start) / scale);
        }
        const char* engine = engineName(dimension);
        ASSERT_TRUE(touched) << engine;
        EXPECT_GT(std::abs(sim.omegaZ()[0]), 1.0) << engine << ": the impact turned sphere 0";
        EXPECT_LT(worst, 1e-2) << engine;
    }
}
