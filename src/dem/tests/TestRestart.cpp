// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Save -> load -> continue equals an uninterrupted run, and 1 thread equals 2 threads,
// bit for bit.

#include "TestHelpers.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>

using namespace dem;
using namespace dem::test;

namespace {

const Box box{0.0, 0.03, 0.0, 0.1};

Settings settings(int threads)
{
    Settings s = paperSettings(box);
    s.gravity[1] = -9.81;
    s.nThreads = threads;
    return s;
}

/// A falling, colliding, frictional bed with a drag that varies between CFD steps.
std::unique_ptr<Simulation> start(int threads)
{
    auto sim = std::make_unique<Simulation>(settings(threads));
    sim->packRandom({300, 100}, {0.0, 0.03, 0.0, 0.06}, 42);
    return sim;
}

void cfdStep(Simulation& sim, int step)
{
    for (std::size_t i = 0; i < sim.size(); ++i) {
        sim.dragCoefficient()[i] = 0.5 * sim.mass()[i] / 0.05;
        sim.gasVelocityX()[i] = 0.05 * std::sin(0.1 * step + sim.y()[i] * 100.0);
        sim.gasVelocityY()[i] = 0.3;
        sim.extraForceY()[i] = 1e-6;
    }
    sim.advance(1e-4);
}

bool same(const double* a, const double* b, std::size_t n)
{
    return std::memcmp(a, b, n * sizeof(double)) == 0;
}

void expectIdentical(const Simulation& a, const Simulation& b)
{
    ASSERT_EQ(a.size(), b.size());
    const std::size_t n = a.size();
    EXPECT_TRUE(same(a.x(), b.x(), n));
    EXPECT_TRUE(same(a.y(), b.y(), n));
    EXPECT_TRUE(same(a.vx(), b.vx(), n));
    EXPECT_TRUE(same(a.vy(), b.vy(), n));
    EXPECT_TRUE(same(a.omega(), b.omega(), n));
    EXPECT_TRUE(same(a.meanFluidForceX(), b.meanFluidForceX(), n));
    EXPECT_TRUE(same(a.meanFluidForceY(), b.meanFluidForceY(), n));
    EXPECT_EQ(a.stepCount(), b.stepCount());
    EXPECT_EQ(a.contactCount(), b.contactCount());
}

} // namespace

TEST(Restart, SaveLoadContinueIsBitwiseIdentical)
{
    const std::string path = testing::TempDir() + "demRestart.state";
    auto whole = start(1);
    double skinAtSave = 0.0;
    for (int k = 0; k < 600; ++k) {
        if (k == 300) {
            whole->save(path);
            skinAtSave = whole->neighbourSkin();
        }
        cfdStep(*whole, k);
    }
    // The adaptive skin has left its start (0.4 d_small), so the file carries its state.
    EXPECT_NE(skinAtSave, 0.4 * dSmall);
    Simulation resumed(settings(1));
    resumed.load(path);
    EXPECT_EQ(resumed.stepCount(), 3000);
    for (int k = 300; k < 600; ++k) cfdStep(resumed, k);
    EXPECT_GT(whole->contactCount(), 100u);
    expectIdentical(*whole, resumed);
    std::remove(path.c_str());
}

TEST(Restart, ContinuesWithAnotherNeighbourSkin)
{
    // The skin only decides which candidate pairs are tested: the contacts and the
    // trajectory are the same up to the order of round-off (20 CFD steps, 200 DEM steps,
    // before the bed's chaos could amplify it past 1e-12 m).
    const std::string path = testing::TempDir() + "demRestartSkin.state";
    auto whole = start(1);
    for (int k = 0; k < 300; ++k) cfdStep(*whole, k);
    whole->save(path);
    Settings wide = settings(1);
    wide.neighbourSkin = 3.0 * 0.1 * 1.5e-3;
    Simulation resumed(wide);
    resumed.load(path);
    for (int k = 300; k < 320; ++k) {
        cfdStep(*whole, k);
        cfdStep(resumed, k);
    }
    EXPECT_EQ(whole->contactCount(), resumed.contactCount());
    double worst = 0.0;
    for (std::size_t i = 0; i < whole->size(); ++i) {
        worst = std::max({worst, std::abs(whole->x()[i] - resumed.x()[i]),
                          std::abs(whole->y()[i] - resumed.y()[i])});
    }
    EXPECT_LT(worst, 1e-12);
    std::remove(path.c_str());
}

TEST(Restart, OneThreadEqualsTwoThreads)
{
    auto one = start(1);
    auto two = start(2);
    for (int k = 0; k < 600; ++k) {
        cfdStep(*one, k);
        cfdStep(*two, k);
    }
    expectIdentical(*one, *two);
}

TEST(Restart, WithAFewLargeParticlesAndSortsIsBitwiseIdentical)
{
    // Three discs 3.3 times the beads' diameter (0.75 % of the particles) are searched
    // apart from the beads' grid, whose cells are then sized by the beads. The sort by
    // cell, as the solver calls it every 3000 DEM steps (here at the restart's step, 9000,
    // and not again before the end), must use the same cells after a load as in the
    // uninterrupted run: the same order of the particles.
    const std::string path = testing::TempDir() + "demRestartLarge.state";
    Settings s = settings(1);
    s.classes = {{"bead", dSmall, rho}, {"intruder", 5e-3, 1000.0}};
    auto begin = [&] {
        auto sim = std::make_unique<Simulation>(s);
        sim->packRandom({400, 3}, {0.0, 0.03, 0.0, 0.06}, 7);
        return sim;
    };
    auto run = [](Simulation& sim, int k) {
        if (k % 300 == 0) sim.sortByCell();
        cfdStep(sim, k);
    };
    auto whole = begin();
    for (int k = 0; k < 1190; ++k) {
        if (k == 900) whole->save(path);
        run(*whole, k);
    }
    Simulation resumed(s);
    resumed.load(path);
    for (int k = 900; k < 1190; ++k) run(resumed, k);
    EXPECT_GT(whole->contactCount(), 100u);
    expectIdentical(*whole, resumed);
    std::remove(path.c_str());
}

TEST(Restart, BadFilesAreNamed)
{
    const std::string path = testing::TempDir() + "demBad.state";
    {
        std::ofstream out(path);
        out << "not a state file";
    }
    Simulation sim(settings(1));
    try {
        sim.load(path);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }

    // A state written with other settings.
    auto other = start(1);
    other->save(path);
    Settings s = settings(1);
    s.dt = 2e-5;
    Simulation mismatched(s);
    try {
        mismatched.load(path);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("other settings"), std::string::npos) << e.what();
    }

    // A truncated state.
    {
        std::ifstream in(path, std::ios::binary);
        std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size() / 2));
    }
    try {
        sim.load(path);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
    EXPECT_EQ(sim.size(), 0u);
    std::remove(path.c_str());
}
