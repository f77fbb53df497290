// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Renumbering the slab's spheres by search cell leaves the physics alone: a pair whose
// partners swap numbers keeps its tangential history as seen from the other partner (the
// 3-vector changes sign), and a bed sorted now and then follows, to round-off, the one
// never sorted.

#include "TestHelpers.hpp"
#include "dem/SlabSystem.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <memory>

using namespace dem;
using namespace dem::test;

namespace {

Settings slabSettings(double width, double height, int threads)
{
    Settings s = paperSettings({0.0, width, 0.0, height});
    s.dimension = 3;
    s.slabDepth = 0.0075;   // 3 large diameters
    s.gravity[1] = -9.81;
    s.nThreads = threads;
    return s;
}

struct State { Eigen::Vector3d x, v, w; };

std::map<std::int64_t, State> byId(const SlabSystem& sim)
{
    const SlabParticles& p = sim.particles();
    std::map<std::int64_t, State> m;
    for (std::size_t i = 0; i < p.size(); ++i) m[p.id[i]] = {p.position(i), p.velocity(i), p.spin(i)};
    return m;
}

/// Largest differences between the states of the same ids: position, velocity, spin.
std::array<double, 3> worstDifference(const SlabSystem& a, const SlabSystem& b)
{
    const auto sa = byId(a);
    const auto sb = byId(b);
    std::array<double, 3> worst{0.0, 0.0, 0.0};
    for (const auto& [id, s] : sa) {
        const State& t = sb.at(id);
        worst[0] = std::max(worst[0], (s.x - t.x).cwiseAbs().maxCoeff());
        worst[1] = std::max(worst[1], (s.v - t.v).cwiseAbs().maxCoeff());
        worst[2] = std::max(worst[2], (s.w - t.w).cwiseAbs().maxCoeff());
    }
    return worst;
}

/// A drag that depends on where the sphere is, not on its number.
void setFluid(SlabSystem& sim)
{
    SlabParticles& p = sim.particles();
    for (std::size_t i = 0; i < p.size(); ++i) {
        p.dragCoefficient[i] = 0.5 * p.mass[i] / 0.05;
        p.gasVx[i] = 0.05 * std::sin(p.y[i] * 300.0);
        p.gasVy[i] = 0.3;
        p.gasVz[i] = 0.02 * std::cos(p.x[i] * 500.0);
    }
}

} // namespace

TEST(SlabSortByCell, SwappedPairKeepsItsTangentialHistory)
{
    // Sphere 1 (large) on the floor, sphere 0 (small) resting on it a search row higher
    // (both pressed in by their weights, 3e-7 and 5e-8 m), sliding sideways in x and z slowly
    // enough (4.7 mm/s) that the dashpot carries less than the Coulomb limit: friction loads
    // the pair's tangential spring with the rest, a 3-vector history of about 1e-8 m.
    // Sorting renumbers them (1 -> 0, 0 -> 1) mid-contact; the pair (i, j) becomes (j, i) and
    // its history must change sign. Then 200 more steps, as the run never sorted: a history
    // kept with the wrong sign reverses the friction (6.6e-6 N on 4.5e-6 kg: velocities apart
    // by ~1e-3 m/s), round-off alone leaves ~1e-15.
    auto make = [] {
        Settings settings = slabSettings(0.02, 0.02, 1);
        settings.neighbourSkin = 0.1 * dSmall;   // search rows of 2.65 mm: y < 2.65 mm is row 0
        auto sim = std::make_unique<SlabSystem>(settings);
        const double z = 0.00375;
        const double yLarge = 0.5 * dLarge - 3e-7;
        sim->addParticle(0, {0.01, yLarge + 0.5 * (dLarge + dSmall) - 5e-8, z}, {0.004, 0.0, -0.0025});
        sim->addParticle(1, {0.01, yLarge, z}, {0.0, 0.0, 0.0});
        return sim;
    };
    auto plain = make();
    auto sorted = make();
    for (int k = 0; k < 100; ++k) {
        plain->step(false);
        sorted->step(false);
    }
    ASSERT_EQ(sorted->pairList().size(), 1u);
    const Eigen::Vector3d xi = sorted->pairList().xi[0];
    ASSERT_GT(std::abs(xi.x()), 1e-9);   // m: a loaded spring in x and z
    ASSERT_GT(std::abs(xi.z()), 1e-9);

    sorted->sortByCell();
    ASSERT_EQ(sorted->particles().id[0], 1);   // the two swapped
    EXPECT_EQ(sorted->pairList().xi[0], Eigen::Vector3d(-xi));
    for (int k = 0; k < 200; ++k) {
        plain->step(false);
        sorted->step(false);
    }
    EXPECT_EQ(plain->contactCount(), sorted->contactCount());
    const auto worst = worstDifference(*plain, *sorted);
    EXPECT_LT(worst[0], 1e-15);   // m
    EXPECT_LT(worst[1], 1e-12);   // m/s
    EXPECT_LT(worst[2], 1e-9);    // rad/s
}

TEST(SlabSortByCell, LeavesTheTrajectoryAlone)
{
    // A settled slab with the fluid on, 20 CFD steps sorting every 5: every sphere within
    // round-off (1e-12 m) of the run never sorted; and sorting runs 1 and 2 threads alike.
    auto bed = [](int threads) {
        auto sim = std::make_unique<SlabSystem>(slabSettings(0.02, 0.04, threads));
        sim->packRandom({120, 40}, {0.0, 0.02, 0.0, 0.015}, 5);
        sim->settle(0.15, 0.0);
        return sim;
    };
    auto plain = bed(1);
    auto sorted = bed(1);
    auto sorted2 = bed(2);
    ASSERT_GT(plain->contactCount(), 100u);
    for (int k = 0; k < 20; ++k) {
        if (k % 5 == 0) {
            sorted->sortByCell();
            sorted2->sortByCell();
        }
        for (SlabSystem* s : {plain.get(), sorted.get(), sorted2.get()}) {
            setFluid(*s);
            s->advance(1e-4);
        }
    }
    EXPECT_EQ(plain->contactCount(), sorted->contactCount());
    const auto worst = worstDifference(*plain, *sorted);
    EXPECT_LT(worst[0], 1e-12);
    const SlabParticles& a = sorted->particles();
    const SlabParticles& b = sorted2->particles();
    using Array = std::vector<double> SlabParticles::*;
    for (Array m : {&SlabParticles::x, &SlabParticles::y, &SlabParticles::z, &SlabParticles::vx,
                    &SlabParticles::wz}) {
        EXPECT_EQ(std::memcmp((a.*m).data(), (b.*m).data(), a.size() * sizeof(double)), 0);
    }
}
