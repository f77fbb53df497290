// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// A bed settled with a chosen sliding friction (BedRecipe::settleFriction): spheres poured
// with frictionless settling reach random close packing, with their own friction 0.5 a
// looser packing; settling with it is settling with that friction on every contact (pairs,
// the pairs' and walls' own included; rolling friction kept), in both engines; after packBed
// the contacts slide and roll with their own friction.

#include "TestHelpers.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

using namespace dem;
using namespace dem::test;

namespace {

// The pour: monodisperse glass spheres, 1 mm, in a square box 8 diameters wide and deep
// (the slab's depth), restitution 0.5 (a pour comes to rest sooner), kn = 300 N/m: under the
// bed's weight the overlaps stay below 0.3 % of d, which adds less than 0.003 to the
// solid fraction.
constexpr double dPour = 1e-3;          // m
constexpr double rhoPour = 2500.0;      // kg/m^3
constexpr double widthPour = 8 * dPour; // m, and the depth
constexpr int nPour = 1000;

Settings pourSettings(double friction, double height)
{
    Settings s;
    s.classes = {{"glass", dPour, rhoPour}};
    s.box = {0.0, widthPour, 0.0, height};
    s.dimension = 3;
    s.slabDepth = widthPour;
    s.dt = 1e-5;
    s.nThreads = 1;
    s.contact.kn = 300.0;
    s.contact.restitution = 0.5;
    s.contact.restitutionWall = 0.5;
    s.contact.frictionParticle = friction;
    s.contact.frictionWall = friction;
    return s;
}

/// The solid fraction of the spheres in the box x, z in [lo, hi], y in [yLo, yHi]: the
/// fraction of the points of a grid of spacing d/20 there that lie in a sphere (the spheres
/// overlap by less than 0.3 % of d: counted once each).
double solidFraction(const Simulation& sim, double lo, double hi, double yLo, double yHi)
{
    const double h = dPour / 20.0;
    const int n = static_cast<int>((hi - lo) / h);
    const int ny = static_cast<int>((yHi - yLo) / h);
    long inside = 0;
    auto index = [h](double v, double from) { return static_cast<int>(std::floor((v - from) / h)); };
    for (std::size_t i = 0; i < sim.size(); ++i) {
        const double r = 0.5 * sim.diameter()[i];
        const double c[3] = {sim.x()[i], sim.y()[i], sim.z()[i]};
        const double from[3] = {lo, yLo, lo};
        const int last[3] = {n - 1, ny - 1, n - 1};
        int first[3], end[3];
        for (int a = 0; a < 3; ++a) {
            first[a] = std::max(0, index(c[a] - r, from[a]));
            end[a] = std::min(last[a], index(c[a] + r, from[a]));
        }
        for (int a = first[0]; a <= end[0]; ++a) {
            for (int b = first[1]; b <= end[1]; ++b) {
                for (int q = first[2]; q <= end[2]; ++q) {
                    const double px = lo + (a + 0.5) * h - c[0];
                    const double py = yLo + (b + 0.5) * h - c[1];
                    const double pz = lo + (q + 0.5) * h - c[2];
                    if (px * px + py * py + pz * pz < r * r) ++inside;
                }
            }
        }
    }
    return static_cast<double>(inside) / (static_cast<double>(n) * n * ny);
}

/// The bed of `seed` poured and settled with the contacts' friction `friction`, settled with
/// `settleFriction` if given; its solid fraction in the bulk: two diameters from the side
/// walls, the front and back walls and the floor, three below the highest centre (the
/// surface is about a diameter rough).
double pouredBulkFraction(double friction, std::optional<double> settleFriction,
                          std::uint64_t seed)
{
    // Packed at random at a solid fraction of 0.3 (random sequential addition jams near
    // 0.38), then poured: it falls about 30 diameters
    const double volume = nPour * pi * dPour * dPour * dPour / 6.0;
    const double packHeight = volume / (0.3 * widthPour * widthPour);
    Settings s = pourSettings(friction, packHeight + dPour);
    EXPECT_LE(s.dt, safeTimeStep(s));
    Simulation sim(s);
    BedRecipe r;
    r.countPerClass = {nPour};
    r.region = {0.0, widthPour, 0.0, packHeight};
    r.seed = seed;
    r.settleTime = 0.6;
    // At rest: below 1e-3 of m g d per sphere (1.3e-8 J), and falling
    r.keTolerance = 1e-11;
    r.settleFriction = settleFriction;
    const double spent = sim.packBed(r);
    double top = 0.0;
    for (std::size_t i = 0; i < sim.size(); ++i) top = std::max(top, sim.y()[i]);
    const double phi = solidFraction(sim, 2 * dPour, widthPour - 2 * dPour, 2 * dPour, top - 3 * dPour);
    std::printf("  friction %g, settled with %s, seed %llu: %.3f s, surface %.1f d, "
                "bulk solid fraction %.4f\n",
                friction, settleFriction ? formatValue(*settleFriction).c_str() : "its own",
                static_cast<unsigned long long>(seed), spent, top / dPour, phi);
    EXPECT_LT(sim.kineticEnergy() / nPour, r.keTolerance);
    EXPECT_GT(top - 3 * dPour, 8 * dPour);   // a bulk region at least 4 diameters high
    return phi;
}

} // namespace

// Frictionless spheres poured and settled under gravity jam at random close packing,
// 0.637 (Scott and Kilgour 1969, J. Phys. D 2:863) or 0.64 (O'Hern et al. 2003, PRE
// 68:011306; Silbert et al. 2002, PRE 65:031304, for frictionless spheres poured under
// gravity). The tolerance, 0.015: the bulk region holds about 170 spheres (over ten beds
// the fraction's standard deviation is 0.004, its mean 0.641), the overlaps add less than
// 0.003, and the published values differ by protocol by a few thousandths. The same spheres
// settled with their own friction 0.5 jam looser: towards random loose packing, 0.55 for
// large friction (Silbert 2010, Soft Matter 6:2918), and at least 0.03 below the
// frictionless fraction (measured here: 0.05; over ten beds 0.570-0.593).
TEST(SettleFriction, FrictionlessSettlingReachesRandomClosePacking)
{
    const std::uint64_t seeds[] = {1, 2};
    double frictionless = 0.0, frictional = 0.0;
    for (std::uint64_t seed : seeds) {
        frictionless += 0.5 * pouredBulkFraction(0.5, 0.0, seed);
        frictional += 0.5 * pouredBulkFraction(0.5, std::nullopt, seed);
    }
    std::printf("  mean bulk solid fraction: settled without friction %.4f, with its own 0.5 "
                "%.4f\n", frictionless, frictional);
    EXPECT_NEAR(frictionless, 0.64, 0.015);
    EXPECT_LT(frictional, frictionless - 0.03);
    EXPECT_GT(frictional, 0.55 - 0.01);
}

namespace {

/// Settings of the record tests' bed under gravity with friction of their own for the pair
/// small-large and the large class on the walls, and rolling resistance, in 2D or 3D; the
/// restitutions low enough for the bed to come to rest in a tenth of a second.
Settings ownFrictionSettings(int dimension, double friction, double pairFriction,
                             double wallFriction)
{
    Settings s = paperSettings({0.0, 0.03, 0.0, 0.06});
    s.gravity[1] = -9.81;
    s.contact.restitution = 0.6;
    s.contact.restitutionWall = 0.6;
    s.contact.frictionParticle = friction;
    s.contact.frictionWall = friction;
    s.contact.rollingFriction = 0.02;
    s.contact.rollingFrictionWall = 0.02;
    PairContactSettings pair;
    pair.classA = 0;
    pair.classB = 1;
    pair.restitution = 0.5;
    pair.frictionParticle = pairFriction;
    s.contact.pairs = {pair};
    WallContactSettings wall;
    wall.classIndex = 1;
    wall.restitutionWall = 0.4;
    wall.frictionWall = wallFriction;
    s.contact.walls = {wall};
    if (dimension == 3) {
        s.dimension = 3;
        s.slabDepth = 0.0075;
    }
    return s;
}

/// The record tests' bed, fallen and packed on the floor
BedRecipe settledBedRecipe()
{
    BedRecipe r = smallBedRecipe();
    r.settleTime = 0.15;
    return r;
}

bool sameBits(const double* a, const double* b, std::size_t n)
{
    return std::memcmp(a, b, n * sizeof(double)) == 0;
}

/// The particles' positions and spins of two simulations, bit for bit.
void expectSameState(const Simulation& a, const Simulation& b)
{
    ASSERT_EQ(a.size(), b.size());
    const std::size_t n = a.size();
    EXPECT_TRUE(sameBits(a.x(), b.x(), n));
    EXPECT_TRUE(sameBits(a.y(), b.y(), n));
    EXPECT_TRUE(sameBits(a.vx(), b.vx(), n));
    EXPECT_TRUE(sameBits(a.omegaZ(), b.omegaZ(), n));
    if (a.settings().dimension == 3) {
        EXPECT_TRUE(sameBits(a.z(), b.z(), n));
        EXPECT_TRUE(sameBits(a.omegaX(), b.omegaX(), n));
    }
}

} // namespace

// A bed settled with settleFriction f is the bed of contacts whose sliding friction is f
// everywhere (global, the pair's own, the walls' own) and whose rolling friction is their
// own: the same bits, in both engines, for f = 0 and for f = 0.25.
TEST(SettleFriction, SettlingWithItIsSettlingWithThatFrictionOnEveryContact)
{
    for (int dimension : {2, 3}) {
        for (double f : {0.0, 0.25}) {
            SCOPED_TRACE("dimension " + std::to_string(dimension) + ", settle friction "
                         + std::to_string(f));
            Simulation own(ownFrictionSettings(dimension, 0.3, 0.5, 0.4));
            BedRecipe r = settledBedRecipe();
            r.settleFriction = f;
            own.packBed(r);
            Simulation everywhere(ownFrictionSettings(dimension, f, f, f));
            everywhere.packBed(settledBedRecipe());
            expectSameState(own, everywhere);
            EXPECT_GT(own.contactCount(), own.size());   // a packed bed
        }
        // and the contacts' own friction otherwise: another bed
        SCOPED_TRACE("dimension " + std::to_string(dimension));
        Simulation own(ownFrictionSettings(dimension, 0.3, 0.5, 0.4));
        own.packBed(settledBedRecipe());
        Simulation frictionless(ownFrictionSettings(dimension, 0.0, 0.0, 0.0));
        frictionless.packBed(settledBedRecipe());
        EXPECT_FALSE(sameBits(own.y(), frictionless.y(), own.size()));
    }
}

// After packBed the contacts have their own friction back. A sphere at rest on the floor,
// pushed at its centre by F = m g/2, rolls without slipping where its wall friction mu
// exceeds 2F/(7 m g) = 1/7: a = 5F/(7m), omega r = v (a solid sphere, I = 2/5 m r^2; the 2D
// discs have the spheres' mass and inertia). Its class's own wall friction, 0.3, holds it;
// the global 0.1 would let it slide (a = F/m - mu g, 12 % more), the settle friction 0
// too (a = F/m). To 2 % after 50 ms (the tangential spring's oscillation, ~1 ms, damped).
TEST(SettleFriction, TheContactsOwnFrictionIsBackAfterPackBed)
{
    for (int dimension : {2, 3}) {
        SCOPED_TRACE("dimension " + std::to_string(dimension));
        Settings s = paperSettings({0.0, 0.06, 0.0, 0.02});
        s.classes = {{"large", dLarge, rho}};
        s.gravity[1] = -9.81;
        s.contact.frictionWall = 0.1;
        WallContactSettings wall;
        wall.classIndex = 0;
        wall.restitutionWall = 0.5;   // at rest on the floor sooner
        wall.frictionWall = 0.3;
        s.contact.walls = {wall};
        if (dimension == 3) {
            s.dimension = 3;
            s.slabDepth = 0.0075;
        }
        Simulation sim(s);
        BedRecipe r;
        r.countPerClass = {1};
        r.region = {0.0, 0.01, 0.0, 0.005};
        r.placed = {PlacedParticle{0, true, {}}};   // on the floor
        r.settleTime = 0.1;
        r.settleFriction = 0.0;
        sim.packBed(r);
        ASSERT_EQ(sim.size(), 1u);
        ASSERT_LT(std::abs(sim.vx()[0]), 1e-6);
        const double m = sim.mass()[0], radius = 0.5 * sim.diameter()[0], g = 9.81;
        const double force = 0.5 * m * g;
        const double x0 = sim.x()[0];
        const double t = 0.05, dtOuter = 1e-3;
        for (int k = 0; k < static_cast<int>(std::lround(t / dtOuter)); ++k) {
            sim.extraForceX()[0] = force;
            sim.advance(dtOuter);
        }
        const double a = 5.0 / 7.0 * force / m;
        std::printf("  %dD: v = %.5f m/s (rolling %.5f, sliding on 0.1 %.5f, on 0 %.5f), "
                    "omega r = %.5f m/s\n",
                    dimension, sim.vx()[0], a * t, (force / m - 0.1 * g) * t, force / m * t,
                    -sim.omegaZ()[0] * radius);
        EXPECT_NEAR(sim.vx()[0], a * t, 0.02 * a * t);
        EXPECT_NEAR(sim.x()[0] - x0, 0.5 * a * t * t, 0.02 * 0.5 * a * t * t);
        EXPECT_NEAR(-sim.omegaZ()[0] * radius, sim.vx()[0], 0.02 * a * t);
    }
}

// The bed packed with a settle friction goes on as the same bed read into a simulation of
// the case's settings, pushed sideways (every contact loaded, some sliding): the same bits,
// pairs and walls alike, in both engines.
TEST(SettleFriction, APackedBedGoesOnAsTheSavedOne)
{
    for (int dimension : {2, 3}) {
        SCOPED_TRACE("dimension " + std::to_string(dimension));
        const Settings s = ownFrictionSettings(dimension, 0.3, 0.5, 0.4);
        const std::string path = tempPath("settleFriction" + std::to_string(dimension) + ".state");
        Simulation packed(s);
        BedRecipe r = settledBedRecipe();
        r.settleFriction = 0.0;
        packed.packBed(r);
        packed.save(path);
        Simulation read(s);
        ASSERT_TRUE(read.loadBed(path, r));
        for (int k = 0; k < 20; ++k) {
            for (Simulation* sim : {&packed, &read}) {
                for (std::size_t i = 0; i < sim->size(); ++i) {
                    sim->extraForceX()[i] = 0.3 * sim->mass()[i] * 9.81;
                }
                sim->advance(5e-4);
            }
        }
        expectSameState(packed, read);
        std::remove(path.c_str());
    }
}

namespace {

/// The linear law's normal springs' energy, sum of kn delta^2/2 over the touching pairs and
/// the particles touching a wall (the box's, and in 3D the front and back walls), J.
double normalSpringEnergy(const Simulation& sim)
{
    const Settings& s = sim.settings();
    const bool slab = s.dimension == 3;
    const double kn = s.contact.kn;
    const std::size_t n = sim.size();
    auto z = [&](std::size_t i) { return slab ? sim.z()[i] : 0.0; };
    double energy = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double r = 0.5 * sim.diameter()[i];
        for (std::size_t j = i + 1; j < n; ++j) {
            const double dx = sim.x()[j] - sim.x()[i], dy = sim.y()[j] - sim.y()[i];
            const double dz = z(j) - z(i);
            const double overlap = r + 0.5 * sim.diameter()[j] - std::sqrt(dx * dx + dy * dy + dz * dz);
            if (overlap > 0.0) energy += 0.5 * kn * overlap * overlap;
        }
        std::vector<double> gaps = {sim.x()[i] - s.box.xMin, s.box.xMax - sim.x()[i],
                                    sim.y()[i] - s.box.yMin, s.box.yMax - sim.y()[i]};
        if (slab) gaps.insert(gaps.end(), {z(i), s.slabDepth - z(i)});
        for (double gap : gaps) {
            if (r - gap > 0.0) energy += 0.5 * kn * (r - gap) * (r - gap);
        }
    }
    return energy;
}

} // namespace

// After packBed the tangential springs hold what the contacts' own friction allows: a bed of
// frictionless contacts settled with friction 0.5 holds none (its elastic energy is its
// normal springs' alone), as the run's first step and a saved bed take it; the same bed
// settled with its own friction 0.5 holds some (the check's teeth).
TEST(SettleFriction, TheSpringsAfterPackBedHoldWhatTheOwnFrictionAllows)
{
    for (int dimension : {2, 3}) {
        SCOPED_TRACE("dimension " + std::to_string(dimension));
        Simulation frictionless(ownFrictionSettings(dimension, 0.0, 0.0, 0.0));
        BedRecipe r = settledBedRecipe();
        r.settleFriction = 0.5;
        frictionless.packBed(r);
        const double normal = normalSpringEnergy(frictionless);
        ASSERT_GT(normal, 0.0);
        EXPECT_NEAR(frictionless.elasticEnergy(), normal, 1e-9 * normal);

        Simulation frictional(ownFrictionSettings(dimension, 0.5, 0.5, 0.5));
        frictional.packBed(settledBedRecipe());
        const double tangential = frictional.elasticEnergy() - normalSpringEnergy(frictional);
        std::printf("  %dD: tangential springs' energy %.3g J settled with friction 0.5, %.3g J "
                    "after it for frictionless contacts\n",
                    dimension, tangential, frictionless.elasticEnergy() - normal);
        EXPECT_GT(tangential, 1e-3 * normalSpringEnergy(frictional));
    }
}
