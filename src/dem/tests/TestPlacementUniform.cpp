// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// A particle laid at random on the floor (PlacedParticle::random) is drawn uniform over the
// floor clear of the walls, as a randomized placement by hand is taken to be: over 2000
// seeds, NETL's intruder (9.43 mm in the 38-mm square column) has x and z uniform on
// [r, L - r] (Kolmogorov-Smirnov, the 0.1 % critical value 1.95/sqrt(n)), and it lands in a
// corner (within a radius of two walls' closest approach) as often as a uniform draw does
// (4 (r/(L - 2r))^2, within 3.29 binomial standard deviations: two-sided 0.1 %); no corner is
// favoured. The experiment's excluded corner repeats laid the intruders in a corner on
// purpose (LaMarche et al. 2022, the data set's measurements.rst).

#include "Placement.hpp"
#include "TestHelpers.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace dem;
using dem::test::ksUniform;

namespace {

constexpr double dIntruder = 9.43e-3;   // m
constexpr double side = 0.038;          // m, the column's width and depth
constexpr int draws = 2000;

Settings column()
{
    Settings s;
    s.classes = {{"glass", 3.1e-3, 2522.0}, {"large", dIntruder, 941.0}};
    s.box = {0.0, side, 0.0, 0.12};
    s.gravity[1] = -9.81;
    s.dt = 1e-5;
    s.dimension = 3;
    s.slabDepth = side;
    return s;
}

} // namespace

TEST(PlacementUniform, ARandomIntruderIsUniformOverTheFloorAndNoCornerIsFavoured)
{
    const Settings s = column();
    const double r = 0.5 * dIntruder;
    std::vector<double> x, z;
    int corners = 0;
    for (int seed = 1; seed <= draws; ++seed) {
        BedRecipe recipe;
        recipe.countPerClass = {10, 1};
        recipe.region = {0.0, side, 0.0, 0.12};
        recipe.seed = static_cast<std::uint64_t>(seed);
        PlacedParticle p;
        p.classIndex = 1;
        p.random = true;
        recipe.placed = {p};
        std::vector<int> drawn;
        const std::vector<LaidParticle> laid = layPlacedParticles(s, recipe, drawn);
        ASSERT_EQ(laid.size(), 1u);
        const Vector3& c = laid[0].position;
        EXPECT_NEAR(c.y, r, 1e-15) << "seed " << seed << ": not on the floor";
        x.push_back(c.x);
        z.push_back(c.z);
        // within a radius of the closest approach to two walls at once
        const bool nearX = c.x < 2 * r || c.x > side - 2 * r;
        const bool nearZ = c.z < 2 * r || c.z > side - 2 * r;
        corners += nearX && nearZ;
    }
    const double critical = 1.95 / std::sqrt(static_cast<double>(draws));
    EXPECT_LT(ksUniform(x, r, side - r), critical);
    EXPECT_LT(ksUniform(z, r, side - r), critical);
    const double pCorner = 4 * std::pow(r / (side - 2 * r), 2);
    const double expected = draws * pCorner;
    const double sd = std::sqrt(draws * pCorner * (1 - pCorner));
    EXPECT_NEAR(corners, expected, 3.29 * sd)
        << "corner landings " << corners << " of " << draws << ", a uniform draw's "
        << expected;
}
