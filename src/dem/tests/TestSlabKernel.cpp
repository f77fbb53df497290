// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The slab mode's contact kernel: head-on restitution of every pair and of the
// walls along directions not aligned with the axes, an oblique impact on a tilted wall
// against the rigid-body impulse result, and energy conservation with e = 1, mu = 0.
// Expected numbers as in TestRestitution and TestObliqueImpact (Maw, Barber & Fawcett 1976;
// Walton 1993; Schaefer, Dippel & Wolf 1996), written here from the literature. The head-on
// case runs also through the facade dem::Simulation.

#include "TestHelpers.hpp"
#include "dem/Random.hpp"
#include "dem/SlabSystem.hpp"

#include <gtest/gtest.h>

#include <cstdio>

using namespace dem;
using namespace dem::test;
using Vec3 = Eigen::Vector3d;

namespace {

constexpr double depth = 0.03;   // m, deep enough that the front and back walls stay away

Settings slabSettings(double dt)
{
    Settings s = paperSettings({-0.05, 0.05, -0.05, 0.05}, dt);
    s.dimension = 3;
    s.slabDepth = depth;
    return s;
}

double effectiveMass(int a, int b)
{
    const double d[2] = {dSmall, dLarge};
    const double ma = sphereMass(d[a]);
    if (b < 0) return ma;
    const double mb = sphereMass(d[b]);
    return ma * mb / (ma + mb);
}

struct Collision {
    double e, duration;
};

/// The slab engine driven directly, and through the facade (the coupling's way in).
struct Direct {
    SlabSystem sim;
    explicit Direct(const Settings& s) : sim(s) {}
    void add(int cls, const Vec3& x, const Vec3& v) { sim.addParticle(cls, x, v); }
    Vec3 position(int i) const { return sim.particles().position(i); }
    Vec3 velocity(int i) const { return sim.particles().velocity(i); }
    void advance(double dt) { sim.advance(dt); }
    double time() const { return sim.time(); }
};
struct ViaFacade {
    Simulation sim;
    explicit ViaFacade(const Settings& s) : sim(s) {}
    void add(int cls, const Vec3& x, const Vec3& v)
    {
        sim.addParticle(cls, {x.x(), x.y(), x.z()}, {v.x(), v.y(), v.z()});
    }
    Vec3 position(int i) const { return {sim.x()[i], sim.y()[i], sim.z()[i]}; }
    Vec3 velocity(int i) const { return {sim.vx()[i], sim.vy()[i], sim.vz()[i]}; }
    void advance(double dt) { sim.advance(dt); }
    double time() const { return sim.time(); }
};

/// Head-on collision of class a with class b along u, or (b < 0) of a with wall `wall` of
/// the slab, at 0.5 m/s, one step per advance().
template <class Engine = Direct>
Collision headOn(int a, int b, int wall, const Vec3& u, double dt)
{
    const Settings s = slabSettings(dt);
    Engine sim(s);
    const std::vector<PlaneWall3> walls = slabWalls(s.box, s.slabDepth);
    const double ra = 0.5 * s.classes[a].diameter;
    const double rb = b < 0 ? 0.0 : 0.5 * s.classes[b].diameter;
    const double v0 = 0.5;
    const double gap = 20.0 * v0 * dt + 1e-7;   // touch after ~20 steps, off the step grid
    const Vec3 centre(0.0, 0.0, 0.5 * depth);
    Vec3 dir = u;   // unit vector from a towards its partner
    if (b < 0) {
        const PlaneWall3& w = walls[wall];
        dir = -w.nHat;
        const Vec3 onWall = centre - w.distance(centre) * w.nHat;
        sim.add(a, onWall + (ra + gap) * w.nHat, v0 * dir);
    } else {
        sim.add(a, centre - (ra + 0.5 * gap) * u, 0.5 * v0 * u);
        sim.add(b, centre + (rb + 0.5 * gap) * u, -0.5 * v0 * u);
    }
    auto overlap = [&]() {
        if (b < 0) return ra - walls[wall].distance(sim.position(0));
        return ra + rb - (sim.position(1) - sim.position(0)).norm();
    };
    double start = -1.0, end = -1.0, previous = overlap();
    for (int k = 0; k < 100000 && end < 0.0; ++k) {
        sim.advance(dt);
        const double now = overlap();
        const double t = sim.time();
        if (previous <= 0.0 && now > 0.0 && start < 0.0) start = t - dt * now / (now - previous);
        if (previous > 0.0 && now <= 0.0 && start >= 0.0) end = t - dt * now / (now - previous);
        previous = now;
    }
    Collision c;
    c.duration = end - start;
    c.e = b < 0 ? -sim.velocity(0).dot(dir) / v0
                : (sim.velocity(1) - sim.velocity(0)).dot(dir) / v0;
    return c;
}

} // namespace

TEST(SlabKernel, HeadOnRestitutionOfEveryPairAndWallAtTcOver50)
{
    // As in 2D: e within 0.2 % and t_c within 1 % at dt = t_c/50.
    const Vec3 u = Vec3(1.0, -2.0, 2.0).normalized();   // along no axis
    const struct {
        const char* name;
        int a, b, wall;
    } cases[] = {{"small-small", 0, 0, 0}, {"small-large", 0, 1, 0}, {"large-large", 1, 1, 0},
                 {"small-floor", 0, -1, 0}, {"large-right", 1, -1, 1}, {"small-front", 0, -1, 4},
                 {"large-back", 1, -1, 5}};
    for (const auto& c : cases) {
        const double tc = contactTime(effectiveMass(c.a, c.b), 800.0, 0.97);
        const Collision got = headOn(c.a, c.b, c.wall, u, tc / 50.0);
        EXPECT_NEAR(got.e, 0.97, 0.002 * 0.97) << c.name;
        EXPECT_NEAR(got.duration, tc, 0.01 * tc) << c.name;
    }
}

TEST(SlabKernel, HeadOnRestitutionThroughTheFacade)
{
    // As above, with the particles placed, advanced and read through dem::Simulation.
    const Vec3 u = Vec3(1.0, -2.0, 2.0).normalized();
    const struct {
        const char* name;
        int a, b, wall;
    } cases[] = {{"small-large", 0, 1, 0}, {"large-back", 1, -1, 5}};
    for (const auto& c : cases) {
        const double tc = contactTime(effectiveMass(c.a, c.b), 800.0, 0.97);
        const Collision got = headOn<ViaFacade>(c.a, c.b, c.wall, u, tc / 50.0);
        EXPECT_NEAR(got.e, 0.97, 0.002 * 0.97) << c.name;
        EXPECT_NEAR(got.duration, tc, 0.01 * tc) << c.name;
    }
}

namespace {

struct Rebound {
    double vt, vn, vb;      // along t, the wall normal n, and b = n x t
    double wa, wt, wn;      // spin along a = n x t, along t, along n
};

/// A small sphere hits a wall with normal n (not aligned with the axes) at normal speed vn
/// and tangential speed vt along t, spinning at w0 about a = n x t (in the wall's plane).
Rebound tiltedImpact(double vt, double vn, double w0, double mu, double dt)
{
    Settings s = slabSettings(dt);
    s.contact.frictionWall = mu;
    SlabSystem sim(s);
    const Vec3 n = Vec3(0.3, 1.0, 0.4).normalized();
    const Vec3 t = n.cross(Vec3(0.0, 0.0, 1.0)).normalized();
    const Vec3 a = n.cross(t);
    const Vec3 onWall(0.0, -0.02, 0.5 * depth);
    sim.addWall(onWall, n);
    const double r = 0.5 * dSmall;
    const Vec3 start = onWall + (r + 10.0 * vn * dt + 1e-7) * n - 10.0 * vt * dt * t;
    sim.addParticle(0, start, vt * t - vn * n, w0 * a);
    const PlaneWall3& wall = sim.walls().back();
    bool touched = false;
    for (int k = 0; k < 100000; ++k) {
        sim.advance(dt);
        const bool inContact = wall.distance(sim.particles().position(0)) < r;
        if (inContact) touched = true;
        if (touched && !inContact) break;
    }
    const Vec3 v = sim.particles().velocity(0);
    const Vec3 w = sim.particles().spin(0);
    return {v.dot(t), v.dot(n), v.dot(a), w.dot(a), w.dot(t), w.dot(n)};
}

} // namespace

TEST(SlabKernel, ObliqueSlidingOnTiltedWallMatchesCoulombImpulse)
{
    // Sliding throughout: tangential impulse mu (1 + e) m vn, so v_t' = v_t - mu (1 + e) v_n
    // and the spin about a = n x t grows by 2.5 mu (1 + e) v_n / R (I = 0.4 m R^2), while the
    // contact point's slip v_t - R w_a exceeds 3.5 mu (1 + e) v_n. Without and with spin.
    const double mu = 0.10, e = 0.97, vn = 0.5, vt = 1.0;
    const double R = 0.5 * dSmall;
    const double tc = contactTime(sphereMass(dSmall), 800.0, e);
    for (double w0 : {0.0, -200.0, 400.0}) {   // slip 1, 1.15, 0.7 m/s > 0.69 m/s
        const Rebound got = tiltedImpact(vt, vn, w0, mu, tc / 50.0);
        const double vtExpected = vt - mu * (1.0 + e) * vn;
        const double waExpected = w0 + 2.5 * mu * (1.0 + e) * vn / R;
        EXPECT_NEAR(got.vt, vtExpected, 0.02 * vtExpected) << "w0 " << w0;
        EXPECT_NEAR(got.wa, waExpected, 0.02 * std::abs(waExpected - w0)) << "w0 " << w0;
        EXPECT_NEAR(got.vn, e * vn, 0.002 * e * vn) << "w0 " << w0;
        // Nothing out of the plane of incidence (round-off of m/s and rad/s sizes).
        EXPECT_NEAR(got.vb, 0.0, 1e-12) << "w0 " << w0;
        EXPECT_NEAR(got.wt, 0.0, 1e-9) << "w0 " << w0;
        EXPECT_NEAR(got.wn, 0.0, 1e-9) << "w0 " << w0;
    }
}

TEST(SlabKernel, ObliqueStickingOnTiltedWallReversesContactPointVelocity)
{
    // As ObliqueImpact.StickingReversesContactPointVelocity, on the tilted wall: the
    // contact point's tangential motion is a damped oscillator of mass 2/7 m and stiffness
    // 2/7 kn, so over t_c its velocity is multiplied by the oscillator's ratio.
    const double mu = 0.5, e = 0.97, vn = 0.5, vt = 0.05;
    const double R = 0.5 * dSmall;
    const double m = sphereMass(dSmall);
    const double kn = 800.0;
    const double tc = contactTime(m, kn, e);
    const Rebound got = tiltedImpact(vt, vn, 0.0, mu, tc / 50.0);

    // Angular momentum about the contact point: -w_a R = 2.5 (vt' - vt), any regime.
    EXPECT_NEAR(-got.wa * R, 2.5 * (got.vt - vt), 1e-9);
    EXPECT_LT(std::abs(got.vt - vt), 0.5 * mu * (1.0 + e) * vn);

    const double mt = 2.0 / 7.0 * m;
    const double kt = 2.0 / 7.0 * kn;
    const double eta = etaFor(m, kn, e);
    const double w0 = std::sqrt(kt / mt);
    const double zeta = eta / (2.0 * std::sqrt(kt * mt));
    const double wd = w0 * std::sqrt(1.0 - zeta * zeta);
    const double ratio = std::exp(-zeta * w0 * tc) * (std::cos(wd * tc) - zeta * w0 / wd * std::sin(wd * tc));
    const double vcExpected = ratio * vt;
    const double vc = got.vt - got.wa * R;   // contact point: v.t + (w x (-R n)).t
    std::printf("  slab sticking: contact-point velocity %.5g -> %.5g m/s (oscillator %.5g)\n", vt, vc,
                vcExpected);
    EXPECT_LT(vc, 0.0);
    EXPECT_NEAR(vc, vcExpected, 0.05 * std::abs(vcExpected));
}

TEST(SlabKernel, EnergyConservedWithoutDampingOrFriction)
{
    // e = 1 and mu = 0 leave only springs: kinetic + elastic energy is conserved by the
    // dynamics exactly; velocity Verlet keeps it to O((omega dt)^2) per contact, which at
    // dt = t_c/100 is ~1e-4 of a contact's energy. 200 spheres in a gas-like state (many
    // collisions among themselves and with all six walls), no gravity, 0.2 s.
    const double tc = contactTime(effectiveMass(0, 0), 800.0, 1.0);
    Settings s = paperSettings({0.0, 0.02, 0.0, 0.02}, tc / 100.0);
    s.dimension = 3;
    s.slabDepth = 0.006;
    s.contact.restitution = 1.0;
    s.contact.restitutionWall = 1.0;
    s.contact.frictionParticle = 0.0;
    s.contact.frictionWall = 0.0;
    SlabSystem sim(s);
    sim.packRandom({150, 50}, {0.0, 0.02, 0.0, 0.02}, 5);
    Random random(9);
    SlabParticles& p = sim.particles();
    for (std::size_t i = 0; i < p.size(); ++i) {
        p.vx[i] = random.uniform(-0.5, 0.5);
        p.vy[i] = random.uniform(-0.5, 0.5);
        p.vz[i] = random.uniform(-0.5, 0.5);
    }
    const double e0 = sim.kineticEnergy() + sim.elasticEnergy();
    std::int64_t contactsSeen = 0;
    double worst = 0.0;
    while (sim.time() < 0.2) {
        sim.step(false);
        contactsSeen += static_cast<std::int64_t>(sim.contactCount());
        const double energy = sim.kineticEnergy() + sim.elasticEnergy();
        worst = std::max(worst, std::abs(energy - e0) / e0);
    }
    std::printf("  energy: %lld contact-steps, largest relative change %.3g\n",
                static_cast<long long>(contactsSeen), worst);
    EXPECT_GT(contactsSeen, 10000);
    EXPECT_LT(worst, 1e-3);
}
