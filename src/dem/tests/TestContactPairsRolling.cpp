// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Rolling resistance per pair of classes and per class on the walls (ContactSettings::pairs,
// walls), in both engines, with the global rollingFriction and rollingFrictionWall 0: the
// rolling loops run because a pair or a wall has its own. Expected values from rigid-body
// mechanics as in TestRollingResistance.cpp (the constant-torque model, Ai et al. 2011
// type A; the 2D engine's discs have a sphere's I = m d^2/10):
//   a sphere rolling on the floor without slip decelerates at mu_r g/(1 + I/(m r^2)) and
//   stops at v0/a, having gone v0^2/(2 a);
//   a stack of class a on a frictionless floor under class b, frictionless between them and
//   their spins opposed, carries F_n = m_b g and the torques -+M, M = mu_r R* F_n
//   (R* = r_a r_b/(r_a + r_b)), on the spins only: the relative rolling w_a - w_b falls at
//   M (1/I_a + 1/I_b) to rest at (w_a - w_b)(0) I_eff/M.
// Tolerances 1 % (the step's error on the stop and the distance, TestRollingResistance).

#include "TestHelpers.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

using namespace dem;
using namespace dem::test;

namespace {

constexpr double g = 9.81;
constexpr double inertiaRatio = 0.4;   // I/(m r^2) of a solid sphere

const char* engineName(int dimension) { return dimension == 2 ? "2D" : "slab"; }
const char* className(int a) { return a == 0 ? "small" : "large"; }
double diameterOf(int a) { return a == 0 ? dSmall : dLarge; }

/// The rolling friction of each pair: small-small and large-small (so written) their own,
/// large-large the global 0. The stops last 6-10 ms, 600-1000 steps: the clamp's tail, a few
/// steps, stays within the 1 %.
double pairRolling(int a, int b)
{
    if (a == 0 && b == 0) return 0.1;
    return a != b ? 0.02 : 0.0;
}
/// Each class's on the walls, both their own.
double wallRolling(int a) { return a == 0 ? 0.1 : 0.04; }

Settings rollingSettings(int dimension)
{
    Settings s = paperSettings({0.0, 0.1, 0.0, 0.02});
    s.gravity[1] = -g;
    s.dimension = dimension;
    s.slabDepth = dimension == 3 ? 0.01 : 0.0;
    ContactSettings& c = s.contact;
    c.rollingFriction = 0.0;
    c.rollingFrictionWall = 0.0;
    PairContactSettings smallSmall;
    smallSmall.rollingFriction = pairRolling(0, 0);
    PairContactSettings largeSmall;
    largeSmall.classA = 1;
    largeSmall.rollingFriction = pairRolling(1, 0);
    c.pairs = {smallSmall, largeSmall};
    WallContactSettings smallWall;
    smallWall.rollingFrictionWall = wallRolling(0);
    WallContactSettings largeWall;
    largeWall.classIndex = 1;
    largeWall.rollingFrictionWall = wallRolling(1);
    c.walls = {smallWall, largeWall};
    return s;
}

void add(Simulation& sim, int cls, double x, double y, double vx, double w)
{
    if (sim.settings().dimension == 3) {
        sim.addParticle(cls, {x, y, 0.005}, {vx, 0.0, 0.0}, {0.0, 0.0, w});
    } else {
        sim.addParticle(cls, x, y, vx, 0.0, w);
    }
}

} // namespace

TEST(ContactPairsRolling, EachClassRollingOnTheFloorStopsWithItsOwnCoefficient)
{
    const double v0 = 0.1;
    for (int dimension : {2, 3}) {
        for (int a : {0, 1}) {
            Settings s = rollingSettings(dimension);
            s.contact.frictionWall = 0.5;   // no slip
            Simulation sim(s);
            const double r = 0.5 * diameterOf(a);
            add(sim, a, 0.01, r, v0, -v0 / r);
            const double decel = wallRolling(a) * g / (1.0 + inertiaRatio);
            const double tStop = v0 / decel, distance = v0 * v0 / (2.0 * decel);
            double stopped = -1.0;
            while (sim.time() < 1.5 * tStop) {
                sim.advance(s.dt);
                if (stopped < 0.0 && sim.vx()[0] <= 1e-3 * v0) stopped = sim.time();
            }
            const std::string what = std::string(engineName(dimension)) + " " + className(a);
            EXPECT_NEAR(stopped, tStop, 0.01 * tStop) << what;
            EXPECT_NEAR(sim.x()[0] - 0.01, distance, 0.01 * distance) << what;
        }
    }
}

TEST(ContactPairsRolling, EachPairOfClassesStopsItsRelativeRollingWithItsOwnCoefficient)
{
    const double w0 = 10.0;
    for (int dimension : {2, 3}) {
        for (int a : {0, 1}) {
            for (int b : {0, 1}) {
                Settings s = rollingSettings(dimension);
                s.contact.frictionParticle = 0.0;
                s.contact.frictionWall = 0.0;
                s.contact.walls.clear();   // the lower sphere spins freely on the floor
                Simulation sim(s);
                const double ra = 0.5 * diameterOf(a), rb = 0.5 * diameterOf(b);
                const double ma = sphereMass(diameterOf(a)), mb = sphereMass(diameterOf(b));
                const double ia = inertiaRatio * ma * ra * ra, ib = inertiaRatio * mb * rb * rb;
                const double kn = s.contact.kn;
                // At the static overlaps: the floor carries both, the pair the upper one
                const double y0 = ra - (ma + mb) * g / kn, y1 = y0 + ra + rb - mb * g / kn;
                add(sim, a, 0.05, y0, 0.0, w0);
                add(sim, b, 0.05, y1, 0.0, -w0);
                const double muR = pairRolling(a, b);
                const double torque = muR * ra * rb / (ra + rb) * mb * g;
                const double rate = torque * (1.0 / ia + 1.0 / ib);
                const double tStop = muR > 0.0 ? 2.0 * w0 / rate : 0.05;
                double atHalf = NAN, stopped = -1.0;
                while (sim.time() < 1.5 * tStop) {
                    sim.advance(s.dt);
                    const double relative = sim.omegaZ()[0] - sim.omegaZ()[1];
                    if (std::abs(sim.time() - 0.5 * tStop) < 0.5 * s.dt) atHalf = relative;
                    if (stopped < 0.0 && relative <= 1e-3 * 2.0 * w0) stopped = sim.time();
                }
                const std::string what = std::string(engineName(dimension)) + " " + className(a)
                                         + " under " + className(b);
                if (muR > 0.0) {
                    EXPECT_NEAR(atHalf, w0, 0.01 * w0) << what;
                    EXPECT_NEAR(stopped, tStop, 0.01 * tStop) << what;
                } else {   // no rolling resistance: the spins are kept
                    EXPECT_NEAR(sim.omegaZ()[0] - sim.omegaZ()[1], 2.0 * w0, 1e-9 * w0) << what;
                }
            }
        }
    }
}
