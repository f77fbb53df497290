// The adaptive Verlet skin (Settings::neighbourSkin < 0): a build every ~25 steps at the
// fastest particle's speed, within [0.1, 0.8] d_min; an explicit skin stays fixed.

#include "TestHelpers.hpp"

#include <gtest/gtest.h>

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
    // In free flight a particle moves v dt per step, so a build every 25 steps needs a skin
    // of 2 x 25 v dt (the rebuild comes when it has covered half the skin): 0.3 mm at
    // 0.6 m/s (dt = 1e-5 s), reached from the starting 0.6 mm within a few builds.
    EXPECT_NEAR(skinAfter(0.6, 2000), 2 * 25 * 0.6 * 1e-5, 1e-9);
    // Too fast for the widest skin: 0.8 d_small; at rest: the narrowest, 0.1 d_small.
    EXPECT_DOUBLE_EQ(skinAfter(5.0, 2000), 0.8 * dSmall);
    EXPECT_DOUBLE_EQ(skinAfter(0.0, 2000), 0.1 * dSmall);
}

TEST(AdaptiveSkin, AnExplicitSkinStaysFixed)
{
    EXPECT_EQ(skinAfter(0.6, 2000, 1.5e-4), 1.5e-4);
    EXPECT_EQ(skinAfter(0.0, 2000, 9e-4), 9e-4);
}
