// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// A bed in a cylinder of the slab mode (Settings::walls: a floor and a vertical cylinder,
// without the slab's six): packed and laid at random inside it over its whole cross-section,
// settled, at rest its weight on the walls (Newton: the walls carry the weight, and a
// frictionless cylinder, pushing towards its axis, none of it), a restart bit for bit and
// refused with other walls, an added plane that keeps the cylinder's contacts, and bad walls
// refused naming the entry.

#include "Placement.hpp"
#include "TestHelpers.hpp"
#include "dem/SlabSystem.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

using namespace dem;
using namespace dem::test;
using Vec3 = Eigen::Vector3d;

namespace {

constexpr double radius = 7.5e-3;      // m, three large diameters
constexpr double xAxis = radius, zAxis = radius;

/// A column of 2R x 0.06 m x 2R: the floor y = 0 and the cylinder around the vertical
/// axis through (R, 0, R), touching the box's sides and the slab's front and back.
Settings columnSettings(double frictionWall, int threads)
{
    Settings s = paperSettings({0.0, 2.0 * radius, 0.0, 0.06});
    s.dimension = 3;
    s.slabDepth = 2.0 * radius;
    s.gravity[1] = -9.81;
    s.nThreads = threads;
    s.contact.frictionWall = frictionWall;
    s.walls = {WallSettings::plane({0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}),
               WallSettings::cylinder({xAxis, 0.0, zAxis}, {0.0, 1.0, 0.0}, radius)};
    return s;
}

/// 150 small and 50 large spheres packed in the column and settled.
std::unique_ptr<SlabSystem> settledColumn(const Settings& s, double time, double keTolerance = 0.0)
{
    auto sim = std::make_unique<SlabSystem>(s);
    sim->packRandom({150, 50}, {0.0, 2.0 * radius, 0.0, 0.02}, 11);
    sim->settle(time, keTolerance);
    return sim;
}

/// The largest distance of a sphere's surface beyond the cylinder and below the floor, m,
/// by the geometry of the column.
double deepestOutside(const SlabParticles& p)
{
    double worst = -INFINITY;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double fromAxis = std::hypot(p.x[i] - xAxis, p.z[i] - zAxis);
        worst = std::max({worst, fromAxis + p.radius[i] - radius, p.radius[i] - p.y[i]});
    }
    return worst;
}

void expectSameBits(const SlabSystem& a, const SlabSystem& b, const char* what)
{
    ASSERT_EQ(a.stepCount(), b.stepCount()) << what;
    std::vector<std::pair<const void*, std::size_t>> da;
    std::vector<const void*> db;
    a.particles().forEachArray([&](const auto& v) { da.push_back({v.data(), v.size() * sizeof(v[0])}); });
    b.particles().forEachArray([&](const auto& v) { db.push_back(v.data()); });
    int differing = 0;
    for (std::size_t k = 0; k < da.size(); ++k) differing += std::memcmp(da[k].first, db[k], da[k].second) != 0;
    EXPECT_EQ(differing, 0) << what << ": " << differing << " particle arrays differ";
    const auto& pa = a.pairList();
    const auto& pb = b.pairList();
    ASSERT_EQ(pa.size(), pb.size()) << what;
    EXPECT_EQ(std::memcmp(pa.xi.data(), pb.xi.data(), pa.size() * sizeof(pa.xi[0])), 0) << what;
    for (int w = 0; w < a.wallCount(); ++w) {   // the walls' contacts, histories included
        EXPECT_TRUE(a.wallForce(w) == b.wallForce(w)) << what << ": wall " << w;
    }
}

} // namespace

TEST(CylinderBed, PackingFillsTheCylinderClearOfItsWall)
{
    // The packing draws in the box through the depth and keeps what clears the walls: no
    // sphere of 150 small and 50 large closer to the cylinder than its radius (round-off:
    // 1e-9 r), and each class reaches the wall: its farthest centre within a quarter
    // diameter of R - r. Draws uniform over the disc of radius R - r miss that ring with
    // probability 0.81^50 = 3e-5 (large) and 0.89^150 = 4e-8 (small); a packing kept a
    // radius further in, or to a square inside the disc, misses it.
    SlabSystem sim(columnSettings(0.1, 1));
    sim.packRandom({150, 50}, {0.0, 2.0 * radius, 0.0, 0.02}, 11);
    const SlabParticles& p = sim.particles();
    ASSERT_EQ(p.size(), 200u);
    double reach[2] = {-INFINITY, -INFINITY};
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double fromAxis = std::hypot(p.x[i] - xAxis, p.z[i] - zAxis);
        const double r = p.radius[i];
        EXPECT_GE(radius - fromAxis, r * (1.0 - 1e-9)) << "sphere " << i;
        reach[p.classIndex[i]] = std::max(reach[p.classIndex[i]], fromAxis - (radius - r));
    }
    std::printf("  farthest centres %.3g (small) and %.3g (large) m inside R - r\n",
                -reach[0], -reach[1]);
    EXPECT_GT(reach[0], -0.25 * dSmall);
    EXPECT_GT(reach[1], -0.25 * dLarge);
}

TEST(CylinderBed, ARandomPlacedParticleIsUniformOverTheCylindersFloor)
{
    // A particle laid at random on the floor (PlacedParticle::random) in the column, over
    // 2000 seeds: clear of the cylinder by its radius, and uniform over the disc its centre
    // may reach, of radius R - r: the squared distance from the axis uniform on
    // [0, (R - r)^2] and the angle around it on [-pi, pi] (Kolmogorov-Smirnov, the 0.1 %
    // critical value 1.95/sqrt(n), as PlacementUniform's).
    const Settings s = columnSettings(0.1, 1);
    const double r = 0.5 * dLarge;
    const double reach = radius - r;
    constexpr int draws = 2000;
    std::vector<double> rho2, angle;
    for (int seed = 1; seed <= draws; ++seed) {
        BedRecipe recipe;
        recipe.countPerClass = {10, 1};
        recipe.region = {0.0, 2.0 * radius, 0.0, 0.05};
        recipe.seed = static_cast<std::uint64_t>(seed);
        PlacedParticle placed;
        placed.classIndex = 1;
        placed.random = true;
        recipe.placed = {placed};
        std::vector<int> drawn;
        const std::vector<LaidParticle> laid = layPlacedParticles(s, recipe, drawn);
        ASSERT_EQ(laid.size(), 1u);
        const Vector3& c = laid[0].position;
        const double dx = c.x - xAxis, dz = c.z - zAxis;
        ASSERT_LE(std::hypot(dx, dz), reach * (1.0 + 1e-9)) << "seed " << seed;
        rho2.push_back(dx * dx + dz * dz);
        angle.push_back(std::atan2(dz, dx));
    }
    const double critical = 1.95 / std::sqrt(static_cast<double>(draws));
    EXPECT_LT(ksUniform(rho2, 0.0, reach * reach), critical);
    EXPECT_LT(ksUniform(angle, -M_PI, M_PI), critical);
}

TEST(CylinderBed, SettledColumnStaysInsideAndCarriesItsWeight)
{
    // At rest (translational energy < 1e-12 J each) the walls carry the weight; the bed's
    // momentum over the 0.05 s the forces are averaged on bounds what they may miss, 0.2 %
    // of it, as SlabBed.SettledSlabCarriesItsWeightOnTheFloor. A frictionless cylinder
    // pushes towards its axis only: none of the weight (round-off of the sum, 1e-9 of it)
    // and, the frictionless floor pushing up only, no net sideways force either (0.2 %);
    // with friction the walls' sideways forces balance (0.2 %). No sphere ends outside:
    // beyond the walls by at most the overlap under the bed's weight, 1 % of d.
    for (double muWall : {0.0, 0.1}) {
        auto sim = settledColumn(columnSettings(muWall, 1), 1.0, 1e-12);
        const SlabParticles& p = sim->particles();
        double ke = 0.0, weight = 0.0;
        for (std::size_t i = 0; i < p.size(); ++i) {
            ke += 0.5 * p.mass[i] * p.velocity(i).squaredNorm();
            weight += 9.81 * p.mass[i];
        }
        ke /= static_cast<double>(p.size());
        EXPECT_LT(ke, 1e-12) << "muWall " << muWall;
        EXPECT_LT(deepestOutside(p), 0.01 * dSmall) << "muWall " << muWall;

        const double settled = sim->time();
        Vec3 floor = Vec3::Zero(), cylinder = Vec3::Zero();
        constexpr int averageSteps = 5000;
        for (int k = 0; k < averageSteps; ++k) {
            sim->step(false);
            floor += sim->wallForce(0);
            cylinder += sim->wallForce(1);
        }
        floor /= averageSteps;
        cylinder /= averageSteps;
        const Vec3 sum = floor + cylinder;
        std::printf("  muWall %.1f: settled in %.3g s, floor %.6g N, cylinder (%.3g, %.3g, %.3g) N, "
                    "weight %.6g N, deepest outside %.3g m\n", muWall, settled,
                    -floor.y(), cylinder.x(), cylinder.y(), cylinder.z(), weight, deepestOutside(p));
        EXPECT_NEAR(-sum.y(), weight, 0.002 * weight) << "muWall " << muWall;
        EXPECT_LT(std::hypot(sum.x(), sum.z()), 0.002 * weight) << "muWall " << muWall;
        if (muWall == 0.0) {
            EXPECT_NEAR(-floor.y(), weight, 0.002 * weight);
            EXPECT_LT(std::abs(cylinder.y()), 1e-9 * weight);
            EXPECT_LT(std::hypot(cylinder.x(), cylinder.z()), 0.002 * weight);
        }
        EXPECT_LT(deepestOutside(p), 0.01 * dSmall) << "muWall " << muWall << " after";
    }
}

TEST(CylinderRestart, SaveAndLoadContinueBitForBitAndOtherWallsAreRefused)
{
    const Settings s = columnSettings(0.1, 2);
    auto sim = settledColumn(s, 0.06);
    // Pressed on the cylinder, its springs stretched along the wall
    ASSERT_GT(std::abs(sim->wallForce(1).y()), 0.0);
    const std::string path = tempPath("cylinderColumn.state");
    sim->save(path);
    SlabSystem copy(s);
    copy.load(path);
    expectSameBits(*sim, copy, "after load");
    for (int k = 0; k < 2000; ++k) {   // through several neighbour-list builds
        sim->step(false);
        copy.step(false);
    }
    expectSameBits(*sim, copy, "2000 steps after load");
    EXPECT_GT(sim->neighbourListBuilds(), 1);

    // Another radius, and the slab's six walls, are refused naming the walls
    Settings wider = s;
    wider.walls[1].radius = 8e-3;
    EXPECT_TRUE(errorOf([&] { SlabSystem(wider).load(path); }).find(
                    "walls[1] radius = 0.0075 m in the file, 0.008 m here") != std::string::npos)
        << errorOf([&] { SlabSystem(wider).load(path); });
    Settings six = s;
    six.walls.clear();
    const std::string e = errorOf([&] { SlabSystem(six).load(path); });
    EXPECT_NE(e.find("walls = 2 (plane, cylinder) in the file, none (the slab's six) here"),
              std::string::npos) << e;
}

TEST(CylinderSettings, AnAddedPlaneKeepsTheCylindersContacts)
{
    // addWall puts a plane after the settings' planes, before the cylinder: the cylinder's
    // contacts, their tangential springs included, follow it to its new index.
    auto sim = settledColumn(columnSettings(0.1, 1), 0.06);
    const Vec3 before = sim->wallForce(1);
    ASSERT_GT(std::abs(before.y()), 0.0);
    sim->addWall({0.0, 0.059, 0.0}, {0.0, -1.0, 0.0});   // a ceiling nothing touches
    ASSERT_EQ(sim->wallCount(), 3);
    EXPECT_TRUE(sim->wallForce(2) == before);
    EXPECT_TRUE(sim->wallForce(1) == Vec3::Zero());
    sim->step(false);
    EXPECT_GT(sim->wallForce(2).norm(), 0.0);
}

TEST(CylinderSettings, BadWallsAreRefusedNamingTheEntryAndTheRange)
{
    auto refused = [](const Settings& s) { return errorOf([&] { SlabSystem sim(s); }); };
    auto has = [](const std::string& e, const std::string& part) {
        return e.find(part) != std::string::npos;
    };
    Settings s = columnSettings(0.1, 1);
    s.walls[1].radius = 0.0;
    std::string e = refused(s);
    EXPECT_TRUE(has(e, "walls[1] (cylinder) radius = 0 m is outside [0.0025, inf)")) << e;
    s.walls[1].radius = 2e-3;   // below the large diameter
    e = refused(s);
    EXPECT_TRUE(has(e, "walls[1] (cylinder) radius = 0.002 m is outside [0.0025, inf)")) << e;
    s = columnSettings(0.1, 1);
    s.walls[1].axis = {};
    e = refused(s);
    EXPECT_TRUE(has(e, "walls[1] (cylinder) axis = (0, 0, 0) is outside the finite vectors of "
                       "length > 0")) << e;
    s.walls[1].axis = {0.0, 2.0, 0.0};
    e = refused(s);
    EXPECT_TRUE(has(e, "walls[1] (cylinder) axis = (0, 2, 0) of length 2 is outside the unit "
                       "vectors (length 1 within 1e-06)")) << e;
    s.walls[1].axis = {0.0, 1.0 + 2e-6, 0.0};
    e = refused(s);
    EXPECT_TRUE(has(e, "walls[1] (cylinder) axis = (0, 1.000002, 0) of length 1.000002 is "
                       "outside the unit vectors")) << e;
    s.walls[1].axis = {0.0, 0.6, 0.8};   // unit to round-off: accepted
    EXPECT_EQ(refused(s), "");
    s = columnSettings(0.1, 1);
    s.walls[0].normal = {0.0, NAN, 0.0};
    e = refused(s);
    EXPECT_TRUE(has(e, "walls[0] (plane) normal = (0, nan, 0) is outside")) << e;
    s = columnSettings(0.1, 1);
    s.dimension = 2;
    e = errorOf([&] { Simulation sim(s); });
    EXPECT_TRUE(has(e, "walls has 2 entries, outside [0, 0] in 2D")) << e;

    // A sphere outside the cylinder, through the facade; a placed particle of a recipe
    const Settings good = columnSettings(0.1, 1);
    Simulation sim(good);
    e = errorOf([&] { sim.addParticle(0, Vector3{xAxis + 7e-3, 0.01, zAxis}); });
    EXPECT_TRUE(has(e, "m pokes through walls[1] (cylinder) by more than 1 % of its diameter: "
                       "allowed a distance from its axis of at most 0.006765 m")) << e;
    BedRecipe recipe;
    recipe.countPerClass = {10, 0};
    recipe.region = {0.0, 2.0 * radius, 0.0, 0.05};
    recipe.placed = {{0, false, {0.0135, 0.005, 0.0015}}};
    e = errorOf([&] { checkPlacements(good, recipe); });
    EXPECT_TRUE(has(e, "placed particle 1 (class 'small') at (0.0135, 0.005, 0.0015) m is not "
                       "clear of walls[1] (cylinder) by its radius 0.00075 m: allowed a "
                       "distance from its axis of at most 0.00675 m")) << e;
}
