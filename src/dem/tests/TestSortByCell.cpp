// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Renumbering the particles by search cell moves every particle's state along and leaves
// the physics alone: the same contacts and, to round-off, the same trajectory.

#include "TestHelpers.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <vector>

using namespace dem;
using namespace dem::test;

namespace {

const Box box{0.0, 0.03, 0.0, 0.1};

std::unique_ptr<Simulation> fallingBed()
{
    Settings s = paperSettings(box);
    s.gravity[1] = -9.81;
    auto sim = std::make_unique<Simulation>(s);
    sim->packRandom({300, 100}, {0.0, 0.03, 0.0, 0.06}, 42);
    return sim;
}

void cfdStep(Simulation& sim)
{
    // A drag that depends on where the particle is, not on its number.
    for (std::size_t i = 0; i < sim.size(); ++i) {
        sim.dragCoefficient()[i] = 0.5 * sim.mass()[i] / 0.05;
        sim.gasVelocityX()[i] = 0.05 * std::sin(sim.y()[i] * 300.0);
        sim.gasVelocityY()[i] = 0.3;
    }
    sim.advance(1e-4);
}

struct State { double x, y, vx, vy, omega; int cls; };

std::map<std::int64_t, State> byId(const Simulation& sim)
{
    std::map<std::int64_t, State> m;
    for (std::size_t i = 0; i < sim.size(); ++i) {
        m[sim.id()[i]] = {sim.x()[i], sim.y()[i], sim.vx()[i], sim.vy()[i], sim.omega()[i],
                          sim.classIndex()[i]};
    }
    return m;
}

} // namespace

TEST(SortByCell, MovesEveryParticleWhole)
{
    auto sim = fallingBed();
    for (int k = 0; k < 1500; ++k) cfdStep(*sim);   // settled on the floor: contacts, history
    const auto before = byId(*sim);
    sim->sortByCell();
    const auto after = byId(*sim);
    ASSERT_EQ(before.size(), sim->size());
    ASSERT_EQ(after.size(), sim->size());   // ids stay a permutation
    for (const auto& [id, a] : before) {
        const State& b = after.at(id);
        EXPECT_EQ(a.x, b.x);
        EXPECT_EQ(a.y, b.y);
        EXPECT_EQ(a.vx, b.vx);
        EXPECT_EQ(a.omega, b.omega);
        EXPECT_EQ(a.cls, b.cls);
    }
    // Row by row: the heights of successive particles fall back by at most one search
    // cell (2.75 mm: the largest diameter and the skin).
    for (std::size_t i = 1; i < sim->size(); ++i) {
        EXPECT_GT(sim->y()[i], sim->y()[i - 1] - 2 * (dLarge + 0.1 * dSmall)) << i;
    }
}

TEST(SortByCell, LeavesTheTrajectoryAlone)
{
    // 20 CFD steps (200 DEM steps), sorting every 5: positions within 1e-12 m of the run
    // that never sorts (round-off differences only; the bed's chaos has no time to grow).
    auto plain = fallingBed();
    auto sorted = fallingBed();
    for (int k = 0; k < 1500; ++k) {
        cfdStep(*plain);
        cfdStep(*sorted);
    }
    ASSERT_GT(plain->contactCount(), 100u);
    for (int k = 0; k < 20; ++k) {
        if (k % 5 == 0) sorted->sortByCell();
        cfdStep(*plain);
        cfdStep(*sorted);
    }
    EXPECT_EQ(plain->contactCount(), sorted->contactCount());
    const auto a = byId(*plain);
    const auto b = byId(*sorted);
    double worst = 0.0;
    for (const auto& [id, s] : a) {
        worst = std::max({worst, std::abs(s.x - b.at(id).x), std::abs(s.y - b.at(id).y)});
    }
    EXPECT_LT(worst, 1e-12);
}
