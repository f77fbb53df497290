// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The adaptive Verlet skin (Settings::neighbourSkin < 0): sqrt(20 d_min u) for the fastest
// particle's displacement u per step, within [0.1, 0.8] d_min; an explicit skin stays fixed.

#include "TestHelpers.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace dem;
using namespace dem::test;

namespace {

const Box box{0.0, 0.15, 0.0, 0.1};

/// One small disc in free flight at speed v (m/s) along x, no gravity, after `steps` steps.
double skinAfter(double v, int steps, double skin = -1.0)
{
    Settings s = paperSettings(box);
    s.neighbourSkin = skin;
    Simulation sim(s);
    sim.addParticle(0, 0.01, 0.05, v, 0.0);
    sim.addParticle(0, 0.01, 0.08);   // a second particle, at rest
    sim.settle(steps * s.dt, 0.0);
    return sim.neighbourSkin();
}

} // namespace

TEST(AdaptiveSkin, FollowsTheFastestParticle)
{
    // In free flight a particle moves u = v dt per step: at 0.6 m/s (dt = 1e-5 s) the skin
    // is sqrt(20 x 1.5 mm x 6 um) = 0.424 mm, reached from the starting 0.6 mm at the first
    // builds.
    EXPECT_NEAR(skinAfter(0.6, 2000), std::sqrt(20 * dSmall * 0.6 * 1e-5), 1e-9);
    // Too fast for the widest skin: 0.8 d_small; at rest: the narrowest, 0.1 d_small.
    EXPECT_DOUBLE_EQ(skinAfter(10.0, 1000), 0.8 * dSmall);
    EXPECT_DOUBLE_EQ(skinAfter(0.0, 2000), 0.1 * dSmall);
}

TEST(AdaptiveSkin, AnExplicitSkinStaysFixed)
{
    EXPECT_EQ(skinAfter(0.6, 2000, 1.5e-4), 1.5e-4);
    EXPECT_EQ(skinAfter(0.0, 2000, 9e-4), 9e-4);
}
