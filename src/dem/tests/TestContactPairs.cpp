// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Coefficients per pair of classes and per class on the walls (ContactSettings::pairs,
// walls), in both engines and under both laws: in a two-class set-up whose pairs and walls
// have restitutions and frictions of their own (one pair and one wall left on the global
// entries), every head-on impact rebounds at its own e and every sliding impact takes its
// own Coulomb impulse. The references are the inputs through analytic results: the laws
// build their damping to give e in continuous time (Chung & Ooi 2011, test 3; the suite's
// tolerance |e_DEM - e| < 1e-3 at dt = t_c/1000); a contact that slides throughout has
// J_t = mu J_n (Chung & Ooi tests 5 and 7-8; 1 % at dt = t_c/500). A pair slides by its
// spins (as in tests 7-8, so that the centres stay head-on): J_t = I_0 |dw_0|/r_0, the
// torque of the tangential force on particle 0 (I = 0.4 m r^2, a solid sphere). The contact times that set the
// steps come from TestHelpers.hpp (linear) and Johnson's Hertz formula, not the library.

#include "TestHelpers.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace dem;
using namespace dem::test;

namespace {

const Box bigBox{-0.05, 0.05, -0.05, 0.05};
constexpr double depth = 0.01;         // slab, m
constexpr double youngs = 1e7;         // Pa, HertzMindlin's particles and walls
constexpr double poisson = 0.3;
constexpr double vn = 0.5;             // normal approach speed, m/s

/// The coefficients each kind of contact is given: pairs small-small and large-small (so
/// written) and the small class on the walls their own, large-large the global ones, the
/// large class on the walls its own friction and the global restitution.
struct Expected {
    double e, mu;
};
Expected pairExpected(int a, int b)
{
    if (a == 0 && b == 0) return {0.9, 0.3};
    if (a != b) return {0.6, 0.1};
    return {0.97, 0.2};
}
Expected wallExpected(int a) { return a == 0 ? Expected{0.8, 0.25} : Expected{0.97, 0.4}; }

Settings ownSettings(int dimension, bool hertz, double dt)
{
    Settings s = paperSettings(bigBox, dt);
    s.dimension = dimension;
    s.slabDepth = dimension == 3 ? depth : 0.0;
    ContactSettings& c = s.contact;
    c.restitution = 0.97;
    c.frictionParticle = 0.2;
    c.restitutionWall = 0.97;
    c.frictionWall = 0.1;
    PairContactSettings smallSmall;
    smallSmall.restitution = 0.9;
    smallSmall.frictionParticle = 0.3;
    PairContactSettings largeSmall;
    largeSmall.classA = 1;
    largeSmall.restitution = 0.6;
    largeSmall.frictionParticle = 0.1;
    c.pairs = {smallSmall, largeSmall};
    WallContactSettings smallWall;
    smallWall.restitutionWall = 0.8;
    smallWall.frictionWall = 0.25;
    WallContactSettings largeWall;
    largeWall.classIndex = 1;
    largeWall.frictionWall = 0.4;
    c.walls = {smallWall, largeWall};
    if (hertz) {
        c.law = ContactLawType::hertzMindlin;
        for (ParticleClass& k : s.classes) {
            k.youngsModulus = youngs;
            k.poissonRatio = poisson;
        }
        c.wallYoungsModulus = youngs;
        c.wallPoissonRatio = poisson;
    }
    return s;
}

double diameterOf(int a) { return a == 0 ? dSmall : dLarge; }

/// The duration of a head-on contact of classes a and b (b < 0: a wall of the particles'
/// modulus) at restitution e and normal speed vn: the clamped linear law's (TestHelpers), or
/// Hertz's elastic 2.9432 delta_max/vn (Johnson 1985, section 11.4), s.
double contactDuration(int a, int b, double e, bool hertz)
{
    const double ma = sphereMass(diameterOf(a)), ra = 0.5 * diameterOf(a);
    const double mb = b < 0 ? INFINITY : sphereMass(diameterOf(b));
    const double rb = b < 0 ? INFINITY : 0.5 * diameterOf(b);
    const double mEff = b < 0 ? ma : ma * mb / (ma + mb);
    if (!hertz) return contactTime(mEff, 800.0, e);
    const double rEff = b < 0 ? ra : ra * rb / (ra + rb);
    const double eStar = youngs / (2.0 * (1.0 - poisson * poisson));   // two equal materials
    const double deltaMax = std::pow(15.0 * mEff * vn * vn / (16.0 * eStar * std::sqrt(rEff)), 0.4);
    return 2.9432 * deltaMax / vn;
}

/// A particle of class cls at x with velocity v and spin w about z.
void add(Simulation& sim, int cls, const Vector3& x, const Vector3& v, double w = 0.0)
{
    if (sim.settings().dimension == 3) {
        sim.addParticle(cls, x, v, {0.0, 0.0, w});
    } else {
        sim.addParticle(cls, x.x, x.y, v.x, v.y, w);
    }
}

struct PairRebound {
    double e;           // relative normal rebound speed over the approach speed
    double impulseN;    // |J_n| on particle 0, N s
    double impulseT;    // |J_t| on particle 0, N s
};

/// Class a from the left and class b from the right, approaching along x at vn, their
/// contact points sliding past each other at vc along y by their spins, at dt = t_c/steps;
/// until they part.
PairRebound pairImpact(int dimension, bool hertz, int a, int b, double vc, double steps)
{
    const double dt = contactDuration(a, b, pairExpected(a, b).e, hertz) / steps;
    Simulation sim(ownSettings(dimension, hertz, dt));
    const double ra = 0.5 * diameterOf(a), rb = 0.5 * diameterOf(b);
    const double gap = 10.0 * vn * dt + 1e-9;
    const double z = 0.5 * depth;
    add(sim, a, {-ra - 0.5 * gap, 0.0, z}, {0.5 * vn, 0.0, 0.0}, 0.5 * vc / ra);
    add(sim, b, {rb + 0.5 * gap, 0.0, z}, {-0.5 * vn, 0.0, 0.0}, 0.5 * vc / rb);
    bool touched = false;
    for (int k = 0; k < 100.0 * steps; ++k) {
        sim.advance(dt);
        const double dx = sim.x()[1] - sim.x()[0], dy = sim.y()[1] - sim.y()[0];
        const bool inContact = std::hypot(dx, dy) < ra + rb;
        touched = touched || inContact;
        if (touched && !inContact) break;
    }
    const double m = sim.mass()[0];
    return {(sim.vx()[1] - sim.vx()[0]) / vn, m * std::abs(sim.vx()[0] - 0.5 * vn),
            0.4 * m * ra * std::abs(sim.omegaZ()[0] - 0.5 * vc / ra)};
}

/// A wall of the engine's box: the axis of its normal, its coordinate, and the sense that
/// points into the box.
struct BoxWall {
    const char* name;
    int axis;
    double at;
    double inward;
};
std::vector<BoxWall> boxWalls(int dimension)
{
    std::vector<BoxWall> w{{"floor", 1, bigBox.yMin, 1.0}, {"ceiling", 1, bigBox.yMax, -1.0},
                           {"left", 0, bigBox.xMin, 1.0}, {"right", 0, bigBox.xMax, -1.0}};
    if (dimension == 3) {
        w.push_back({"front", 2, 0.0, 1.0});
        w.push_back({"back", 2, depth, -1.0});
    }
    return w;
}

double component(const Vector3& v, int axis) { return axis == 0 ? v.x : axis == 1 ? v.y : v.z; }
void setComponent(Vector3& v, int axis, double value)
{
    (axis == 0 ? v.x : axis == 1 ? v.y : v.z) = value;
}

/// Class a onto `wall` at vn along its normal and vt along the next axis in the plane, at
/// dt = t_c/steps; returns the rebound (e, J_n, J_t as for a pair).
PairRebound wallImpact(int dimension, bool hertz, int a, const BoxWall& wall, double vt,
                       double steps)
{
    const double dt = contactDuration(a, -1, wallExpected(a).e, hertz) / steps;
    Simulation sim(ownSettings(dimension, hertz, dt));
    const double r = 0.5 * diameterOf(a);
    const double gap = 10.0 * vn * dt + 1e-9;
    const int along = wall.axis == 0 ? 1 : 0;   // the tangent, in the x-y plane
    Vector3 x{0.0, 0.0, 0.5 * depth}, v;
    setComponent(x, wall.axis, wall.at + wall.inward * (r + gap));
    setComponent(v, wall.axis, -wall.inward * vn);
    setComponent(v, along, vt);
    add(sim, a, x, v);
    auto position = [&] {
        return Vector3{sim.x()[0], sim.y()[0], dimension == 3 ? sim.z()[0] : 0.0};
    };
    auto velocity = [&] {
        return Vector3{sim.vx()[0], sim.vy()[0], dimension == 3 ? sim.vz()[0] : 0.0};
    };
    bool touched = false;
    for (int k = 0; k < 100.0 * steps; ++k) {
        sim.advance(dt);
        const bool inContact = std::abs(component(position(), wall.axis) - wall.at) < r;
        touched = touched || inContact;
        if (touched && !inContact) break;
    }
    const double m = sim.mass()[0];
    const double vnAfter = wall.inward * component(velocity(), wall.axis);
    return {vnAfter / vn, m * (vnAfter + vn), m * std::abs(component(velocity(), along) - vt)};
}

std::string what(int dimension, bool hertz, const std::string& contact)
{
    return std::string(dimension == 2 ? "2D " : "slab ") + (hertz ? "HertzMindlin " : "linear ")
           + contact;
}

const char* className(int a) { return a == 0 ? "small" : "large"; }

} // namespace

TEST(ContactPairs, EachPairOfClassesReboundsAtItsOwnRestitution)
{
    // Both orders of each pair: the pair's law is the same whichever particle is first
    double worst = 0.0;
    for (int dimension : {2, 3}) {
        for (bool hertz : {false, true}) {
            for (int a : {0, 1}) {
                for (int b : {0, 1}) {
                    const double e = pairExpected(a, b).e;
                    const PairRebound r = pairImpact(dimension, hertz, a, b, 0.0, 1000.0);
                    worst = std::max(worst, std::abs(r.e - e));
                    EXPECT_NEAR(r.e, e, 1e-3)
                        << what(dimension, hertz, std::string(className(a)) + "-" + className(b));
                }
            }
        }
    }
    std::printf("  pairs: largest |e_DEM - e| %.2g at dt = t_c/1000\n", worst);
}

TEST(ContactPairs, EachClassReboundsFromEveryWallAtItsOwnRestitution)
{
    double worst = 0.0;
    for (int dimension : {2, 3}) {
        for (bool hertz : {false, true}) {
            for (int a : {0, 1}) {
                for (const BoxWall& wall : boxWalls(dimension)) {
                    const PairRebound r = wallImpact(dimension, hertz, a, wall, 0.0, 1000.0);
                    worst = std::max(worst, std::abs(r.e - wallExpected(a).e));
                    EXPECT_NEAR(r.e, wallExpected(a).e, 1e-3)
                        << what(dimension, hertz, std::string(className(a)) + " on the " + wall.name);
                }
            }
        }
    }
    std::printf("  walls: largest |e_DEM - e| %.2g at dt = t_c/1000\n", worst);
}

TEST(ContactPairs, EachSlidingImpactTakesItsOwnCoulombImpulse)
{
    // Sliding at 5 vn, above the limit 3.5 mu (1 + e) vn (2.8 vn at mu = 0.4, e = 0.97): the
    // contact slides throughout and J_t = mu J_n whatever the normal law
    const double vt = 5.0 * vn;
    double worst = 0.0;
    for (int dimension : {2, 3}) {
        for (bool hertz : {false, true}) {
            for (int a : {0, 1}) {
                for (int b : {0, 1}) {
                    const PairRebound r = pairImpact(dimension, hertz, a, b, vt, 500.0);
                    const double ratio = r.impulseT / (pairExpected(a, b).mu * r.impulseN);
                    worst = std::max(worst, std::abs(ratio - 1.0));
                    EXPECT_NEAR(ratio, 1.0, 0.01)
                        << what(dimension, hertz, std::string(className(a)) + "-" + className(b));
                }
                const PairRebound w = wallImpact(dimension, hertz, a, boxWalls(dimension)[0], vt, 500.0);
                const double ratio = w.impulseT / (wallExpected(a).mu * w.impulseN);
                worst = std::max(worst, std::abs(ratio - 1.0));
                EXPECT_NEAR(ratio, 1.0, 0.01)
                    << what(dimension, hertz, std::string(className(a)) + " on the floor");
            }
        }
    }
    std::printf("  sliding: largest |J_t/(mu J_n) - 1| %.2g at dt = t_c/500\n", worst);
}
