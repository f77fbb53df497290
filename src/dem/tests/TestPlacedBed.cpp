// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// A bed with placed particles (BedRecipe::placed), as NETL's segregating bed lays its HDPE
// intruders (9.43 mm, 941 kg/m3; LaMarche et al. 2022) on the distributor under glass beads:
// a placed particle is where it was asked before the bed settles, a random one lies on the
// floor within the column and clear of the others, the rest are packed clear of them, all
// reproducible for a seed; bad placements are named, and a bed placed otherwise is refused
// naming the placement.

#include "TestHelpers.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

using namespace dem;
using namespace dem::test;

namespace {

constexpr double dIntruder = 9.43e-3;   // m
constexpr double width = 0.038;         // m, the column's side
constexpr double depth = 0.038;         // m, the slab's depth (the column's other side)

/// Glass beads of one diameter (the brief's beds are packed fast) and the large intruders.
Settings netlSettings(int dimension)
{
    Settings s;
    s.classes = {{"glass", 3.1e-3, 2522.0}, {"large", dIntruder, 941.0}};
    s.box = {0.0, width, 0.0, 0.12};
    s.gravity[1] = -9.81;
    s.dt = 1e-5;
    s.dimension = dimension;
    s.slabDepth = dimension == 3 ? depth : 0.0;
    return s;
}

BedRecipe netlRecipe(int glass, int large)
{
    BedRecipe r;
    r.countPerClass = {glass, large};
    r.region = {0.0, width, 0.0, 0.12};
    r.seed = 3;
    r.settleTime = 0.0;   // as placed and packed
    return r;
}

PlacedParticle at(int cls, double x, double y, double z)
{
    PlacedParticle p;
    p.classIndex = cls;
    p.position = {x, y, z};
    return p;
}

PlacedParticle atRandom(int cls)
{
    PlacedParticle p;
    p.classIndex = cls;
    p.random = true;
    return p;
}

struct Sphere {
    double x, y, z, d;
    int cls;
};

std::vector<Sphere> spheres(const Simulation& sim, int dimension)
{
    std::vector<Sphere> out;
    for (std::size_t i = 0; i < sim.size(); ++i) {
        out.push_back({sim.x()[i], sim.y()[i], dimension == 3 ? sim.z()[i] : 0.0,
                       sim.diameter()[i], sim.classIndex()[i]});
    }
    return out;
}

/// No two particles overlap (to round-off).
void expectNoOverlap(const std::vector<Sphere>& p)
{
    int overlaps = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        for (std::size_t j = i + 1; j < p.size(); ++j) {
            const double dx = p[i].x - p[j].x, dy = p[i].y - p[j].y, dz = p[i].z - p[j].z;
            const double reach = 0.5 * (p[i].d + p[j].d);
            if (dx * dx + dy * dy + dz * dz < reach * reach * (1.0 - 1e-9)) ++overlaps;
        }
    }
    EXPECT_EQ(overlaps, 0);
}

std::vector<Sphere> ofClass(const std::vector<Sphere>& p, int cls)
{
    std::vector<Sphere> out;
    for (const Sphere& q : p) {
        if (q.cls == cls) out.push_back(q);
    }
    return out;
}

} // namespace

TEST(PlacedBed, APlacedIntruderIsWhereItWasAskedAndTheRestClearOfIt)
{
    for (int dimension : {2, 3}) {
        SCOPED_TRACE("dimension " + std::to_string(dimension));
        const Settings s = netlSettings(dimension);
        BedRecipe r = netlRecipe(dimension == 3 ? 600 : 150, 1);
        r.placed = {at(1, 0.019, 0.005, 0.019)};
        Simulation sim(s);
        sim.packBed(r);
        const std::vector<Sphere> p = spheres(sim, dimension);
        ASSERT_EQ(p.size(), r.countPerClass[0] + 1u);   // the placed one counts toward its class
        const std::vector<Sphere> large = ofClass(p, 1);
        ASSERT_EQ(large.size(), 1u);
        EXPECT_EQ(large[0].x, 0.019);
        EXPECT_EQ(large[0].y, 0.005);
        if (dimension == 3) {
            EXPECT_EQ(large[0].z, 0.019);
        }
        EXPECT_EQ(large[0].d, dIntruder);
        expectNoOverlap(p);
    }
}

TEST(PlacedBed, RandomIntrudersLieOnTheDistributorApartAndReproducibly)
{
    for (int dimension : {2, 3}) {
        SCOPED_TRACE("dimension " + std::to_string(dimension));
        // Four in the square column; two across the discs' 38 mm floor (four of 9.43 mm
        // would need 37.7 mm of it, which random placement seldom leaves)
        const std::size_t n = dimension == 3 ? 4 : 2;
        const Settings s = netlSettings(dimension);
        BedRecipe r = netlRecipe(dimension == 3 ? 600 : 150, static_cast<int>(n));
        r.placed.assign(n, atRandom(1));
        Simulation sim(s);
        sim.packBed(r);
        const std::vector<Sphere> p = spheres(sim, dimension);
        const std::vector<Sphere> large = ofClass(p, 1);
        ASSERT_EQ(large.size(), n);
        const double radius = 0.5 * dIntruder;
        for (const Sphere& q : large) {
            EXPECT_EQ(q.y, radius);   // on the distributor
            EXPECT_GE(q.x, radius);
            EXPECT_LE(q.x, width - radius);
            if (dimension == 3) {
                EXPECT_GE(q.z, radius);
                EXPECT_LE(q.z, depth - radius);
            }
        }
        expectNoOverlap(p);   // the intruders apart, the glass clear of them

        Simulation again(s);
        again.packBed(r);
        const std::vector<Sphere> same = ofClass(spheres(again, dimension), 1);
        BedRecipe other = r;
        other.seed = 4;
        Simulation another(s);
        another.packBed(other);
        const std::vector<Sphere> moved = ofClass(spheres(another, dimension), 1);
        for (std::size_t q = 0; q < n; ++q) {
            EXPECT_EQ(same[q].x, large[q].x);
            EXPECT_EQ(same[q].z, large[q].z);
        }
        EXPECT_NE(moved[0].x, large[0].x);
    }
}

TEST(PlacedBed, BadPlacementsAreNamed)
{
    const Settings s = netlSettings(3);
    auto message = [&](const BedRecipe& r) {
        Simulation sim(s);
        return errorOf([&] { sim.packBed(r); });
    };
    BedRecipe outside = netlRecipe(100, 1);
    outside.placed = {at(1, 0.036, 0.005, 0.019)};
    const std::string o = message(outside);
    EXPECT_NE(o.find("placed particle 1 (class 'large') at (0.036, 0.005, 0.019) m is outside the "
                     "packing region clear of its walls by its radius 0.004715 m: allowed x in "
                     "[0.004715, 0.033285]"),
              std::string::npos)
        << o;

    BedRecipe overlapping = netlRecipe(100, 2);
    overlapping.placed = {at(1, 0.010, 0.005, 0.019), at(1, 0.015, 0.005, 0.019)};
    const std::string v = message(overlapping);
    EXPECT_NE(v.find("placed particle 2 (class 'large') at (0.015, 0.005, 0.019) m overlaps the "
                     "one at (0.01, 0.005, 0.019) m: allowed a centre distance of at least 0.00943 m"),
              std::string::npos)
        << v;

    BedRecipe tooMany = netlRecipe(100, 1);
    tooMany.placed = {at(1, 0.010, 0.005, 0.019), atRandom(1)};
    const std::string m = message(tooMany);
    EXPECT_NE(m.find("class 'large' has 2 placed particles, outside [0, 1] (its count"),
              std::string::npos)
        << m;
}

TEST(PlacedBed, ABedPlacedOtherwiseIsRefusedNamingThePlacement)
{
    for (int dimension : {2, 3}) {
        SCOPED_TRACE("dimension " + std::to_string(dimension));
        const Settings s = netlSettings(dimension);
        BedRecipe r = netlRecipe(100, 1);
        r.placed = {at(1, 0.019, 0.005, 0.019)};
        const std::string path = tempPath("placed" + std::to_string(dimension) + ".state");
        {
            Simulation sim(s);
            sim.packBed(r);
            sim.save(path);
        }
        Simulation same(s);
        EXPECT_TRUE(same.loadBed(path, r));
        ASSERT_NE(same.recipe(), nullptr);
        ASSERT_EQ(same.recipe()->placed.size(), 1u);
        EXPECT_EQ(same.recipe()->placed[0].position.x, 0.019);

        BedRecipe random = r;
        random.placed = {atRandom(1)};
        Simulation refused(s);
        const std::string e = errorOf([&] { refused.loadBed(path, random); });
        const std::string where = dimension == 3 ? "(0.019, 0.005, 0.019) m" : "(0.019, 0.005) m";
        EXPECT_NE(e.find("placed particle 1 = 'large' at " + where + " in the file, 'large' at "
                         "random here"),
                  std::string::npos)
            << e;

        BedRecipe moved = r;
        moved.placed[0].position.x = 0.02;
        Simulation elsewhere(s);
        const std::string m = errorOf([&] { elsewhere.loadBed(path, moved); });
        const std::string there = dimension == 3 ? "(0.02, 0.005, 0.019) m" : "(0.02, 0.005) m";
        EXPECT_NE(m.find("placed particle 1 = 'large' at " + where + " in the file, 'large' at "
                         + there + " here"),
                  std::string::npos)
            << m;

        BedRecipe none = r;
        none.placed.clear();
        Simulation unplaced(s);
        const std::string n = errorOf([&] { unplaced.loadBed(path, none); });
        EXPECT_NE(n.find("placed particles = 1 in the file, 0 here"), std::string::npos) << n;
        std::remove(path.c_str());
    }
}
