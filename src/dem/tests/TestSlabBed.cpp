// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The slab mode's beds: NBS equals brute force with the front and back walls,
// a settled slab carries its weight on the floor, save/load and 1 vs 2 threads bit for bit,
// and the mode's settings.

#include "TestHelpers.hpp"
#include "dem/Random.hpp"
#include "dem/SlabSystem.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <unistd.h>

using namespace dem;
using namespace dem::test;

namespace {

std::vector<std::pair<int, int>> sorted(const std::vector<IndexPair>& pairs)
{
    std::vector<std::pair<int, int>> s;
    for (const auto& p : pairs) s.emplace_back(p.i, p.j);
    std::sort(s.begin(), s.end());
    return s;
}

Settings slabBedSettings(double width, double height, double depth, int threads)
{
    Settings s = paperSettings({0.0, width, 0.0, height});
    s.dimension = 3;
    s.slabDepth = depth;
    s.gravity[1] = -9.81;
    s.nThreads = threads;
    return s;
}

} // namespace

TEST(SlabNbs, EqualsBruteForceWithFrontAndBackWalls)
{
    // Random spheres of both sizes through a slab 6 large diameters deep (overlaps allowed),
    // plus spheres pressed on the front and back walls, on cell edges and in the corners.
    for (std::uint64_t seed : {1u, 2u}) {
        for (double margin : {0.0, 1.5e-4}) {
            const double w = 0.0437, h = 0.06, depth = 0.015;
            NbsSearch nbs(0.0, w, 0.0, h, 2.5e-3 + margin);
            const double cell = nbs.mapper().cellWidth();
            Random random(seed);
            std::vector<double> x, y, z, r;
            auto add = [&](double px, double py, double pz, double pr) {
                x.push_back(px); y.push_back(py); z.push_back(pz); r.push_back(pr);
            };
            for (int k = 0; k < 3000; ++k) {
                const double pr = random.uniform() < 0.5 ? 0.75e-3 : 1.25e-3;
                add(random.uniform(pr, w - pr), random.uniform(pr, h - pr), random.uniform(pr, depth - pr), pr);
            }
            for (int k = 0; k < 200; ++k) {
                const double pr = k % 2 ? 0.75e-3 : 1.25e-3;
                const double s = random.uniform(), t = random.uniform();
                add(s * w, t * h, 0.99 * pr, pr);                           // on the front wall
                add(s * w, t * h + 0.3 * pr, depth - pr, pr);                // on the back wall
                add(std::floor(s * w / cell) * cell, t * h, random.uniform(0.0, depth), pr);
                add(s * w, std::floor(t * h / cell) * cell, random.uniform(0.0, depth), pr);
            }
            for (double px : {0.0, w}) {
                for (double py : {0.0, h}) {
                    for (double pz : {0.0, depth}) add(px, py, pz, 1.25e-3);
                }
            }
            std::vector<IndexPair> fast, slow, two;
            nbs.findPairs(x.data(), y.data(), z.data(), r.data(), x.size(), margin, fast);
            bruteForcePairs(x.data(), y.data(), z.data(), r.data(), x.size(), margin, slow);
            ASSERT_GT(slow.size(), 1000u);
            EXPECT_EQ(sorted(fast), sorted(slow)) << "seed " << seed << " margin " << margin;
            // Two threads: the one-thread list entry for entry.
            nbs.findPairs(x.data(), y.data(), z.data(), r.data(), x.size(), margin, two, 2);
            ASSERT_EQ(two.size(), fast.size());
            for (std::size_t k = 0; k < two.size(); ++k) {
                ASSERT_TRUE(two[k].i == fast[k].i && two[k].j == fast[k].j) << "entry " << k;
            }
        }
    }
}

TEST(SlabNbs, SystemListHoldsEveryPairWithinTheSkin)
{
    SlabSystem sim(slabBedSettings(0.03, 0.05, 0.01, 1));
    sim.packRandom({400, 100}, {0.0, 0.03, 0.0, 0.03}, 3);
    sim.rebuildNeighbourList();
    const SlabParticles& p = sim.particles();
    std::vector<IndexPair> slow;
    bruteForcePairs(p.x.data(), p.y.data(), p.z.data(), p.radius.data(), p.size(), sim.neighbourSkin(), slow);
    std::vector<IndexPair> listed;
    for (std::size_t k = 0; k < sim.pairList().size(); ++k) {
        listed.push_back({sim.pairList().i[k], sim.pairList().j[k]});
    }
    ASSERT_FALSE(slow.empty());
    EXPECT_EQ(sorted(listed), sorted(slow));
}

TEST(SlabNbs, IntrudersLeftOutOfTheCellsKeepEveryPair)
{
    // NETL's bed in small: beads and a few intruders four times larger, which the search
    // tests against every particle while its cells follow the beads; a mixture with many
    // large ones keeps cells of the largest. Either way the list is the oracle's.
    for (const int nLarge : {5, 40}) {
        Settings s = slabBedSettings(0.03, 0.06, 0.012, 1);
        s.classes[1].diameter = 6e-3;
        SlabSystem sim(s);
        sim.packRandom({1000, nLarge}, {0.0, 0.03, 0.0, 0.06}, 5);
        SlabParticles& p = sim.particles();
        // Two intruders pressed together and one against the front wall, in reach of each
        // other and of the wall
        std::vector<std::size_t> large;
        for (std::size_t k = 0; k < p.size(); ++k) {
            if (p.radius[k] == 3e-3) large.push_back(k);
        }
        ASSERT_EQ(large.size(), std::size_t(nLarge));
        const std::size_t a = large[1], b = large[0];
        p.x[a] = 0.012; p.y[a] = 0.030; p.z[a] = 0.006;
        p.x[b] = 0.017; p.y[b] = 0.031; p.z[b] = 0.0062;
        sim.rebuildNeighbourList();
        EXPECT_EQ(sim.searchCellDiameter(), nLarge == 5 ? s.classes[0].diameter : 6e-3);
        std::vector<IndexPair> slow;
        bruteForcePairs(p.x.data(), p.y.data(), p.z.data(), p.radius.data(), p.size(), sim.neighbourSkin(), slow);
        std::vector<IndexPair> listed;
        for (std::size_t k = 0; k < sim.pairList().size(); ++k) {
            listed.push_back({sim.pairList().i[k], sim.pairList().j[k]});
        }
        bool pressed = false;
        for (const auto& q : slow) pressed |= std::size_t(q.i) == b && std::size_t(q.j) == a;
        ASSERT_TRUE(pressed);
        EXPECT_EQ(sorted(listed), sorted(slow)) << nLarge << " large";
    }
}

namespace {

/// A binary slab bed packed and settled; reused by the tests below.
std::unique_ptr<SlabSystem> settledSlab(int threads, double frictionWall, double time,
                                        double keTolerance = 0.0)
{
    Settings s = slabBedSettings(0.03, 0.06, 0.0075, threads);   // 3 large diameters deep
    s.contact.frictionWall = frictionWall;
    auto sim = std::make_unique<SlabSystem>(s);
    sim->packRandom({300, 100}, {0.0, 0.03, 0.0, 0.04}, 11);
    sim->settle(time, keTolerance);
    return sim;
}

double totalWeight(const SlabSystem& sim)
{
    double w = 0.0;
    for (double m : sim.particles().mass) w += 9.81 * m;
    return w;
}

} // namespace

TEST(SlabBed, SettledSlabCarriesItsWeightOnTheFloor)
{
    // At rest the forces on the particles balance their weight. Without wall friction the
    // walls other than the floor can only push normal to themselves (horizontally), so the
    // floor carries the whole weight; with friction all the walls together do. At rest
    // means translational energy < 1e-12 J each: speeds below 5e-4 m/s, but the contacts
    // still ring (period ~1 ms) with accelerations of ~1 % of g, so the wall forces are
    // averaged over 0.05 s after settling. Tolerance: 0.2 %, the bed's momentum (below
    // 400 x 1e-5 kg x 5e-4 m/s) over that time is 0.1 % of its weight.
    for (double muWall : {0.0, 0.1}) {
        auto sim = settledSlab(1, muWall, 1.0, 1e-12);
        // Translational energy only: spin about a frictionless wall's normal is not damped.
        const SlabParticles& p = sim->particles();
        double ke = 0.0;
        for (std::size_t i = 0; i < p.size(); ++i) ke += 0.5 * p.mass[i] * p.velocity(i).squaredNorm();
        ke /= static_cast<double>(p.size());
        std::printf("  muWall %.1f: settled for %.3g s, translational energy per particle %.3g J\n",
                    muWall, sim->time(), ke);
        EXPECT_LT(ke, 1e-12);
        const double weight = totalWeight(*sim);
        Eigen::Vector3d allWalls = Eigen::Vector3d::Zero();
        Eigen::Vector3d floor = Eigen::Vector3d::Zero();
        constexpr int averageSteps = 5000;
        for (int k = 0; k < averageSteps; ++k) {
            sim->step(false);
            for (int w = 0; w < static_cast<int>(sim->walls().size()); ++w) allWalls += sim->wallForce(w);
            floor += sim->wallForce(0);
        }
        allWalls /= averageSteps;
        floor /= averageSteps;
        std::printf("  muWall %.1f: floor %.6g N, all walls %.6g N, weight %.6g N\n", muWall,
                    -floor.y(), -allWalls.y(), weight);
        EXPECT_NEAR(-allWalls.y(), weight, 0.002 * weight);
        if (muWall == 0.0) {
            EXPECT_NEAR(-floor.y(), weight, 0.002 * weight);
        }
        // The front and back walls hold the bed in the slab: the spheres reach both.
        EXPECT_LT(sim->wallForce(4).z(), 0.0);
        EXPECT_GT(sim->wallForce(5).z(), 0.0);
    }
}

namespace {

void expectSameBits(const SlabSystem& a, const SlabSystem& b, const char* what)
{
    ASSERT_EQ(a.stepCount(), b.stepCount()) << what;
    int arrays = 0, differing = 0;
    std::vector<const void*> da, db;
    std::vector<std::size_t> bytes;
    a.particles().forEachArray([&](const auto& v) {
        da.push_back(v.data());
        bytes.push_back(v.size() * sizeof(v[0]));
    });
    b.particles().forEachArray([&](const auto& v) { db.push_back(v.data()); });
    for (std::size_t k = 0; k < da.size(); ++k) {
        ++arrays;
        if (std::memcmp(da[k], db[k], bytes[k]) != 0) ++differing;
    }
    EXPECT_EQ(differing, 0) << what << ": " << differing << " of " << arrays << " arrays differ";
    const auto& pa = a.pairList();
    const auto& pb = b.pairList();
    ASSERT_EQ(pa.size(), pb.size()) << what;
    EXPECT_TRUE(pa.i == pb.i && pa.j == pb.j) << what;
    EXPECT_EQ(std::memcmp(pa.xi.data(), pb.xi.data(), pa.size() * sizeof(pa.xi[0])), 0) << what;
}

} // namespace

TEST(SlabBed, OneAndTwoThreadsGiveTheSameBits)
{
    auto one = settledSlab(1, 0.1, 0.05);
    auto two = settledSlab(2, 0.1, 0.05);
    expectSameBits(*one, *two, "1 vs 2 threads");
}

TEST(SlabBed, SaveAndLoadContinueBitForBit)
{
    auto sim = settledSlab(2, 0.1, 0.03);
    const std::string path = (std::filesystem::temp_directory_path()
                              / ("demSlabState-" + std::to_string(::getpid()))).string();
    sim->save(path);
    SlabSystem copy(sim->settings());
    copy.load(path);
    expectSameBits(*sim, copy, "after load");
    for (int k = 0; k < 2000; ++k) {   // through several neighbour-list builds
        sim->step(false);
        copy.step(false);
    }
    expectSameBits(*sim, copy, "2000 steps after load");
    EXPECT_GT(sim->neighbourListBuilds(), 1);

    // Another slab depth is refused, naming it.
    Settings other = sim->settings();
    other.slabDepth = 0.01;
    SlabSystem wrong(other);
    try {
        wrong.load(path);
        ADD_FAILURE() << "a state of another slab depth was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("slabDepth"), std::string::npos) << e.what();
    }
    std::filesystem::remove(path);
}

TEST(SlabSettings, ModeSelectionRefusesBadValues)
{
    Settings s = slabBedSettings(0.03, 0.05, 0.01, 1);
    s.dimension = 4;
    try {
        SlabSystem sim(s);
        ADD_FAILURE() << "dimension 4 accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("dimension = 4 is outside {2, 3}"), std::string::npos)
            << e.what();
    }
    s.dimension = 3;
    for (double depth : {0.0, 2.0e-3, -1.0, double(NAN)}) {   // 2 mm < the large diameter
        s.slabDepth = depth;
        try {
            SlabSystem sim(s);
            ADD_FAILURE() << "slabDepth " << depth << " accepted";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("slabDepth"), std::string::npos) << e.what();
        }
    }
}
