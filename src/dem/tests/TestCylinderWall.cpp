// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// A sphere against the cylinder wall of the slab mode, on a cylinder whose axis lies along
// no coordinate axis, the sphere moving in a plane across the axis away from the axis's
// point: the geometry against hand values; a frictionless elastic sphere bouncing across
// chords keeps its energy and its angular momentum about the axis (a frictionless cylinder
// pushes towards its axis only) and stays inside; a radial impact rebounds at the law's
// restitution in the contact time of a plane's (as TestSlabKernel's head-on cases); a
// sliding impact takes the Coulomb impulse of the rigid-body result (Maw, Barber & Fawcett
// 1976; Walton 1993) as the tilted plane of TestSlabKernel; a sphere rolling round the inside
// under gravity, its contact sticking, loops in the time of a rolling sphere's energy.
// Expected numbers are written here from the geometry and the literature, not taken from
// the library.

#include "TestHelpers.hpp"
#include "dem/SlabSystem.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cfenv>
#include <cmath>
#include <cstdio>

using namespace dem;
using namespace dem::test;
using Vec3 = Eigen::Vector3d;

namespace {

constexpr double depth = 0.1;   // m: the slab and the box hold the cylinder's part in use

/// The cylinder of the tests: its axis through `centre` along `axis` (no coordinate axis).
struct Cylinder {
    Vec3 centre{0.0, 0.0, 0.5 * depth};
    Vec3 axis = Vec3(0.2, 1.0, -0.3).normalized();
    double radius;

    /// The offset of p from the axis, perpendicular to it, by the geometry of a line.
    Vec3 offset(const Vec3& p) const
    {
        const Vec3 d = p - centre;
        return d - d.dot(axis) * axis;
    }
    /// Two unit vectors across the axis: u, and t = axis x u.
    Vec3 u() const { return axis.cross(Vec3(0.0, 0.0, 1.0)).normalized(); }
    Vec3 t() const { return axis.cross(u()); }
    /// The point of the axis where the tests' sphere moves across it: two radii from the
    /// centre, so that a wall measured from the centre and not from the axis is another one.
    Vec3 plane() const { return centre + 2.0 * radius * axis; }
};

Settings cylinderSettings(const Cylinder& c, double dt)
{
    Settings s = paperSettings({-0.05, 0.05, -0.05, 0.05}, dt);
    s.dimension = 3;
    s.slabDepth = depth;
    s.walls = {WallSettings::cylinder({c.centre.x(), c.centre.y(), c.centre.z()},
                                      {c.axis.x(), c.axis.y(), c.axis.z()}, c.radius)};
    return s;
}

} // namespace

TEST(CylinderWall, GeometryOfAPointInsideIsTheLinesOwn)
{
    // The axis along y through (1, 0, 2) (an axis of any length), radius 3: the point
    // (1 + 1.2, 5, 2 - 1.6) lies 2 from the axis (a 3-4-5 triangle), so 1 inside the wall,
    // whose normal there points back to the axis and whose nearest point is 3 from it.
    const CylinderWall wall{Vec3(1.0, 0.0, 2.0), Vec3(0.0, 1.0, 0.0), 3.0};
    const Vec3 p(2.2, 5.0, 0.4);
    const WallSide side = wall.side(p);
    EXPECT_NEAR(wall.distance(p), 1.0, 1e-15);
    EXPECT_EQ(side.distance, wall.distance(p));
    EXPECT_NEAR((side.nHat - Vec3(-0.6, 0.0, 0.8)).norm(), 0.0, 1e-15);
    EXPECT_NEAR((side.nearestPoint(p) - Vec3(1.0 + 1.8, 5.0, 2.0 - 2.4)).norm(), 0.0, 1e-15);

    // Through the settings, the axis in the other sense: the same cylinder, after the planes.
    Settings s = paperSettings({-5.0, 5.0, -5.0, 5.0});
    s.dimension = 3;
    s.slabDepth = 8.0;
    s.walls = {WallSettings::cylinder({1.0, 0.0, 2.0}, {0.0, -1.0, 0.0}, 3.0),
               WallSettings::plane({0.0, -5.0, 0.0}, {0.0, 2.0, 0.0})};
    SlabSystem sim(s);
    ASSERT_EQ(sim.wallCount(), 2);
    EXPECT_EQ(sim.walls().size(), 1u);
    EXPECT_NEAR(sim.wallSide(0, p).distance, 10.0, 1e-15);   // the floor y = -5
    EXPECT_NEAR(sim.wallSide(1, p).distance, 1.0, 1e-15);
    EXPECT_NEAR((sim.wallSide(1, p).nHat - Vec3(-0.6, 0.0, 0.8)).norm(), 0.0, 1e-15);
}

TEST(CylinderWall, FrictionlessElasticSphereKeepsItsEnergyAndStaysInside)
{
    // e = 1 and mu = 0, no gravity: a small sphere bounces across chords of a cylinder 3.3
    // small diameters in radius, some 150 impacts in 1.2 s. Outside numbers: its kinetic
    // energy between impacts is the launch's, to 1e-3 over all impacts (as
    // SlabKernel.EnergyConservedWithoutDampingOrFriction): velocity Verlet keeps the energy
    // of an impact that crosses the curved wall obliquely to 2e-5 per impact at
    // dt = t_c/200 (the bare integrator on the potential k/2 max(rho - R + r, 0)^2 gives the
    // same), 3e-4 over the impacts were they to add up as a random walk; a wall that pushes
    // towards its axis exerts no torque about it, and Verlet's kicks and drifts keep such an
    // angular momentum exactly (round-off: 1e-9); nothing moves the sphere along the axis
    // (1e-12 m); its centre stays within R - r of the axis plus the peak overlap of a head-on
    // impact at the full speed, v sqrt(m/kn) (1 % for the step).
    Cylinder c;
    c.radius = 5e-3;
    const double r = 0.5 * dSmall, m = sphereMass(dSmall), kn = 800.0;
    const double tc = contactTime(m, kn, 1.0);
    Settings s = cylinderSettings(c, tc / 200.0);
    s.contact.restitution = s.contact.restitutionWall = 1.0;
    s.contact.frictionParticle = s.contact.frictionWall = 0.0;
    SlabSystem sim(s);
    const double v0 = 1.0;
    const Vec3 start = c.plane() + 0.4 * c.radius * c.u();
    const Vec3 v = v0 * (std::cos(1.0) * c.u() + std::sin(1.0) * c.t());
    sim.addParticle(0, start, v);
    auto angularMomentum = [&](const Vec3& p, const Vec3& w) { return c.offset(p).cross(w).dot(c.axis); };
    const double l0 = angularMomentum(start, v);
    const double e0 = 0.5 * m * v0 * v0;
    const double reach = c.radius - r + v0 * std::sqrt(m / kn) * 1.01;

    int impacts = 0;
    bool touching = false;
    double worstEnergy = 0.0, worstMomentum = 0.0, worstAxial = 0.0, farthest = 0.0;
    while (sim.time() < 1.2) {
        sim.step(false);
        const Vec3 p = sim.particles().position(0);
        const Vec3 w = sim.particles().velocity(0);
        const double fromAxis = c.offset(p).norm();
        farthest = std::max(farthest, fromAxis);
        const bool now = fromAxis > c.radius - r;
        if (now && !touching) ++impacts;
        if (!now) {
            worstEnergy = std::max(worstEnergy, std::abs(0.5 * m * w.squaredNorm() - e0) / e0);
        }
        touching = now;
        worstMomentum = std::max(worstMomentum, std::abs(angularMomentum(p, w) - l0) / std::abs(l0));
        worstAxial = std::max(worstAxial, std::abs((p - c.plane()).dot(c.axis)));
    }
    std::printf("  %d impacts: energy within %.3g, angular momentum within %.3g, axial drift "
                "%.3g m, farthest %.6g m of %.6g m allowed\n",
                impacts, worstEnergy, worstMomentum, worstAxial, farthest, reach);
    EXPECT_GT(impacts, 120);
    EXPECT_LT(worstEnergy, 1e-3);
    EXPECT_LT(worstMomentum, 1e-9);
    EXPECT_LT(worstAxial, 1e-12);
    EXPECT_LT(farthest, reach);
    EXPECT_GT(farthest, c.radius - r);
}

namespace {

struct Rebound {
    double e;             // the normal speed out over the normal speed in
    double impulseRatio;  // the tangential impulse over the normal one
    double wa;            // spin about the axis after the contact, rad/s
    double duration;      // s
    double across;        // the largest velocity along the axis and spin across it
    double vn;            // the normal speed in, in the contact's frame, m/s
};

/// A sphere of class `cls` hits the cylinder at rest moving at vn towards the wall and vt
/// along it, in the plane across the axis; the contact's normal u is the one at the deepest
/// overlap (the force's mean direction: the normal turns with the sphere by v_t t_c/R).
Rebound cylinderImpact(int cls, double vn, double vt, double mu, double dt)
{
    Cylinder c;
    c.radius = 0.02;
    Settings s = cylinderSettings(c, dt);
    s.contact.frictionWall = mu;
    SlabSystem sim(s);
    const double r = 0.5 * s.classes[cls].diameter;
    // Heading for the wall's point along u, 20 steps away, off the step grid
    const Vec3 v = vn * c.u() + vt * c.t();
    const Vec3 start = c.plane() + (c.radius - r) * c.u() - (20.0 * dt + 1e-7) * v;
    sim.addParticle(cls, start, v);
    auto overlap = [&]() { return r - (c.radius - c.offset(sim.particles().position(0)).norm()); };
    double begin = -1.0, end = -1.0, previous = overlap(), deepest = 0.0;
    Vec3 u = c.u();
    for (int k = 0; k < 100000 && end < 0.0; ++k) {
        sim.advance(dt);
        const double now = overlap();
        const double time = sim.time();
        if (previous <= 0.0 && now > 0.0 && begin < 0.0) begin = time - dt * now / (now - previous);
        if (previous > 0.0 && now <= 0.0 && begin >= 0.0) end = time - dt * now / (now - previous);
        if (now > deepest) {
            deepest = now;
            u = c.offset(sim.particles().position(0)).normalized();
        }
        previous = now;
    }
    const Vec3 t = c.axis.cross(u);
    const Vec3 out = sim.particles().velocity(0);
    const Vec3 w = sim.particles().spin(0);
    const double vnIn = v.dot(u), vtIn = v.dot(t);
    const double vnOut = -out.dot(u), vtOut = out.dot(t);
    std::printf("  class %d: in (%.6g, %.6g) out (%.6g, %.6g) m/s, spin %.6g rad/s, %.4g s\n",
                cls, vnIn, vtIn, vnOut, vtOut, w.dot(c.axis), end - begin);
    return {vnOut / vnIn, (vtIn - vtOut) / (vnIn + vnOut), w.dot(c.axis), end - begin,
            std::max({std::abs(out.dot(c.axis)), std::abs(w.dot(u)), std::abs(w.dot(t))}), vnIn};
}

} // namespace

TEST(CylinderWall, HeadOnRadialImpactReboundsAtTheRestitution)
{
    // Radially into the curved wall at 0.5 m/s, both classes: the contact is the plane's
    // head-on one (the normal stays on the line of motion), so e and t_c are the law's
    // within the tolerances of the plane walls' test at dt = t_c/50
    // (SlabKernel.HeadOnRestitutionOfEveryPairAndWallAtTcOver50): 0.2 % and 1 %; the sphere
    // leaves along the line it came (1e-12 m/s and rad/s of round-off across it).
    for (int cls : {0, 1}) {
        const double d = cls == 0 ? dSmall : dLarge;
        const double tc = contactTime(sphereMass(d), 800.0, 0.97);
        const Rebound got = cylinderImpact(cls, 0.5, 0.0, 0.1, tc / 50.0);
        EXPECT_NEAR(got.e, 0.97, 0.002 * 0.97) << "class " << cls;
        EXPECT_NEAR(got.duration, tc, 0.01 * tc) << "class " << cls;
        EXPECT_LT(got.across, 1e-12) << "class " << cls;
    }
}

TEST(CylinderWall, ObliqueSlidingImpactTakesMuTimesTheNormalImpulse)
{
    // v_n = 0.5, v_t = 1 m/s, mu = 0.1: the contact point slips throughout (1 m/s > 3.5 mu
    // (1 + e) v_n = 0.34 m/s), so the tangential impulse is mu times the normal one, the
    // sphere leaves at e v_n and its spin about the axis changes by -2.5 mu (1 + e) v_n / r
    // (I = 0.4 m r^2, the friction at r u against the slip along t = axis x u), v_n the
    // normal speed in that frame (0.506 m/s: the wall curves towards the sphere). The
    // tolerances of the tilted plane (SlabKernel.ObliqueSlidingOnTiltedWallMatchesCoulomb
    // Impulse): 2 % tangential, 0.2 % normal; the normal turns by 0.012 rad over the
    // contact, which moves these by 1e-3 of theirs at most in the frame of the deepest
    // overlap.
    const double mu = 0.1, e = 0.97, vn = 0.5, vt = 1.0;
    const double r = 0.5 * dSmall;
    const double tc = contactTime(sphereMass(dSmall), 800.0, e);
    const Rebound got = cylinderImpact(0, vn, vt, mu, tc / 50.0);
    EXPECT_NEAR(got.impulseRatio, mu, 0.02 * mu);
    EXPECT_NEAR(got.e, e, 0.002 * e);
    const double waExpected = -2.5 * mu * (1.0 + e) * got.vn / r;
    EXPECT_NEAR(got.wa, waExpected, 0.02 * std::abs(waExpected));
    EXPECT_LT(got.across, 1e-9);
}

TEST(CylinderWall, SphereRollingRoundTheInsideLoopsInTheRollingTime)
{
    // Under gravity, across a horizontal axis (along (1, 0, 1), normalised), a sphere rolls
    // without slipping round the inside of the cylinder, loop after loop: its contact sticks
    // (the friction it needs, (2/7) m g sin(theta) against the normal m v^2/L + m g cos(theta),
    // is at most 0.12 of the normal force, mu_w = 0.3), its tangential spring loaded along a
    // wall whose normal turns a whole turn per loop. Rolling keeps the energy
    // (7/10) m v^2 + m g h, so v^2 = v_b^2 - (10/7) g L (1 - cos(theta)) about the centre
    // line at L = R - r, and a loop takes the integral of L / v(theta) over a turn (a
    // frictionless sphere, v^2 = v_b^2 - 2 g L (1 - cos(theta)), takes 19 % longer here). Launched
    // rolling at the bottom with v_b^2 = (34/7) g L (the top's normal force m g). Tolerances:
    // the loop time 1e-3, the contact's overlap moving the centre line by 4e-5 of L; the energy
    // after five loops 1e-3, the dashpot taking the launch's small normal oscillation; the
    // contact point's slip along the wall below 1 % of v_b. With rolling resistance on the
    // pairs alone the wall contacts take the one-by-one loop instead of the batched kernel:
    // the same numbers.
    const double r = 0.5 * dSmall, m = sphereMass(dSmall), g = 9.81;
    const double tc = contactTime(m, 800.0, 0.97);
    Cylinder c;
    c.radius = 0.01;
    c.centre = Vec3(0.0, 0.0, 0.5 * depth);
    c.axis = Vec3(1.0, 0.0, 1.0).normalized();
    const double L = c.radius - r;
    const Vec3 down(0.0, -1.0, 0.0);
    const Vec3 across = c.axis.cross(down);
    const double vb2 = 34.0 / 7.0 * g * L;
    auto speed = [&](double theta, double kinetic) {
        return std::sqrt(vb2 - 2.0 * g * L * (1.0 - std::cos(theta)) / kinetic);
    };
    auto loopTime = [&](double kinetic) {   // midpoint rule, 20000 panels
        constexpr int n = 20000;
        double t = 0.0;
        for (int k = 0; k < n; ++k) t += L / speed(2.0 * pi * (k + 0.5) / n, kinetic);
        return t * 2.0 * pi / n;
    };
    const double rolling = loopTime(1.4), sliding = loopTime(1.0);
    EXPECT_GT(sliding / rolling, 1.15);

    for (double pairRolling : {0.0, 0.1}) {
        Settings s = cylinderSettings(c, tc / 50.0);
        s.gravity[1] = -g;
        s.contact.frictionWall = 0.3;
        s.contact.rollingFriction = pairRolling;
        SlabSystem sim(s);
        const Vec3 v = std::sqrt(vb2) * across;
        sim.addParticle(0, c.centre + L * down, v, v.cross(down) / r);   // v + w x (r down) = 0
        auto angle = [&](const Vec3& p) {
            const Vec3 o = c.offset(p);
            return std::atan2(o.dot(across), o.dot(down));
        };
        auto energy = [&]() {
            const SlabParticles& p = sim.particles();
            return 0.5 * m * p.velocity(0).squaredNorm()
                   + 0.5 * 0.4 * m * r * r * p.spin(0).squaredNorm()
                   + m * g * (p.position(0) - c.centre).y();
        };
        const double e0 = 0.7 * m * vb2 - m * g * L;
        double previous = 0.0, before = 0.0, first = -1.0, last = -1.0, worstSlip = 0.0;
        int loops = 0;
        while (loops < 5 && sim.time() < 10.0 * rolling) {
            sim.step(false);
            const Vec3 p = sim.particles().position(0);
            const double a = angle(p);
            if (previous < 0.0 && a >= 0.0) {   // past the bottom
                const double at = before + (sim.time() - before) * previous / (previous - a);
                if (first < 0.0) first = at; else { last = at; ++loops; }
            }
            previous = a;
            before = sim.time();
            const Vec3 out = -c.offset(p).normalized();   // the wall's normal into the domain
            const Vec3 slip = sim.particles().velocity(0) - (r * sim.particles().spin(0)).cross(out);
            worstSlip = std::max(worstSlip, (slip - slip.dot(out) * out).norm());
        }
        const double measured = (last - first) / loops;
        std::printf("  pair rolling %.1f: %d loops of %.6g s (rolling %.6g s, sliding %.6g s), "
                    "energy %.6g of the launch's, slip %.3g m/s\n",
                    pairRolling, loops, measured, rolling, sliding, energy() / e0, worstSlip);
        EXPECT_EQ(loops, 5) << "pair rolling " << pairRolling;
        EXPECT_NEAR(measured, rolling, 1e-3 * rolling) << "pair rolling " << pairRolling;
        EXPECT_NEAR(energy() / e0, 1.0, 1e-3) << "pair rolling " << pairRolling;
        EXPECT_LT(worstSlip, 0.01 * std::sqrt(vb2)) << "pair rolling " << pairRolling;
    }
}

TEST(CylinderContacts, ASphereOnTheAxisRaisesNoInvalidOperation)
{
    // The cylinder's normal is undefined on its axis (0/0). A sphere there does not touch the
    // wall (the radius is at least its diameter), but it is a candidate of the wall's
    // contacts when the radius is under its own plus the skin: a cylinder of radius d, the
    // skin 0.75 d. The loops that read a contact's normal read it of touching contacts alone,
    // so a step, with rolling resistance and without, and the wall's force raise no invalid
    // operation (which the solver traps), and the sphere feels no force from the wall. One
    // thread: the flags are the calling thread's.
    const double d = 2e-3;
    for (double rollingWall : {0.0, 0.1}) {
        Settings s = paperSettings({0.0, 2.0 * d, 0.0, 0.01});
        s.classes = {{"one", d, rho}};
        s.dimension = 3;
        s.slabDepth = 2.0 * d;
        s.gravity[1] = -9.81;
        s.nThreads = 1;
        s.neighbourSkin = 0.75 * d;
        s.contact.rollingFrictionWall = rollingWall;
        s.walls = {WallSettings::plane({0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}),
                   WallSettings::cylinder({d, 0.0, d}, {0.0, 1.0, 0.0}, d)};
        SlabSystem sim(s);
        sim.addParticle(0, Vec3(d, 0.005, d), Vec3::Zero());
        std::feclearexcept(FE_ALL_EXCEPT);
        sim.step(false);
        const Vec3 force = sim.wallForce(1);
        EXPECT_EQ(std::fetestexcept(FE_INVALID), 0) << "rolling resistance " << rollingWall;
        EXPECT_EQ(force, Vec3::Zero()) << "rolling resistance " << rollingWall;
        EXPECT_EQ(sim.particles().position(0).x(), d);
        EXPECT_EQ(sim.particles().position(0).z(), d);
    }
}
