// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Segregation indices on hand-made layouts (LaceyIndex.hpp documents the
// definitions). Diameters 1 mm and 2 mm: a large particle has the volume of
// 8 small ones, so a row of 1 large and a row of 8 small hold the same solid
// volume -- layouts of uniform solids fraction are easy to draw. Region: the
// square [0, 4] x [0, 4] m (floor y = 0, centre line x = 2). Tolerance 1e-12.
#include "mixing/LaceyIndex.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace
{

constexpr double tol = 1e-12;
const std::vector<double> d12 = {1e-3, 2e-3};
const mixing::Region box{0, 4, 0, 4};

struct Layout
{
    std::vector<double> x, y;
    std::vector<int> c;

    void add(double px, double py, int cls)
    {
        x.push_back(px); y.push_back(py); c.push_back(cls);
    }
    /// A row of 8 small particles across the width at height py:
    /// x = 0.25, 0.75, ..., 3.75, mean |x - 2| = (1.75+1.25+0.75+0.25)/4 = 1.
    void smallRow(double py)
    {
        for (int i = 0; i < 8; ++i) { add(0.25 + 0.5*i, py, 0); }
    }
    mixing::SegregationResult indices(const mixing::Region* r = &box) const
    {
        return mixing::segregationIndices(x.size(), x.data(), y.data(), c.data(), d12, r);
    }
};

} // namespace


// Small on top, large below, same solid volume per row (uniform bed, H = 4):
//   large: rows y = 0.5 (x = 1) and y = 1.5 (x = 3): hLarge = 1, rLarge = 1
//   small: rows y = 2.5 and 3.5, 8 each:              hSmall = 3, rSmall = 1
//   hAll = (8*0.5 + 8*1.5 + 8*2.5 + 8*3.5)/32 = 2 = H/2
//   vertical = (3 - 1)/2 = +1 (complete, small on top); horizontal = 0/1 = 0.
TEST(SegregationIndices, SmallOnTopIsPlusOneVertical)
{
    Layout bed;
    bed.add(1, 0.5, 1);
    bed.add(3, 1.5, 1);
    bed.smallRow(2.5);
    bed.smallRow(3.5);
    const auto r = bed.indices();
    EXPECT_NEAR(r.hLarge, 1.0, tol);
    EXPECT_NEAR(r.hSmall, 3.0, tol);
    EXPECT_NEAR(r.hAll, 2.0, tol);
    EXPECT_NEAR(r.vertical, 1.0, tol);
    EXPECT_NEAR(r.rSmall, 1.0, tol);
    EXPECT_NEAR(r.rLarge, 1.0, tol);
    EXPECT_NEAR(r.horizontal, 0.0, tol);
    EXPECT_EQ(r.nSmall, 16u);
    EXPECT_EQ(r.nLarge, 2u);
}

// The same rows upside down (large on top): vertical = (1 - 3)/2 = -1.
TEST(SegregationIndices, LargeOnTopIsMinusOneVertical)
{
    Layout bed;
    bed.smallRow(0.5);
    bed.smallRow(1.5);
    bed.add(1, 2.5, 1);
    bed.add(3, 3.5, 1);
    EXPECT_NEAR(bed.indices().vertical, -1.0, tol);
}

// Every row mixed (1 large + 8 small at the same height): vertical = 0.
TEST(SegregationIndices, MixedRowsAreZero)
{
    Layout bed;
    for (double py : {0.5, 1.5, 2.5, 3.5})
    {
        bed.add(py < 2 ? 1 : 3, py, 1);
        bed.smallRow(py);
    }
    const auto r = bed.indices();
    EXPECT_NEAR(r.vertical, 0.0, tol);
    EXPECT_NEAR(r.horizontal, 0.0, tol);
}

// A layout that is not of uniform packing gives a value other than 1:
// 2 large at height 1, 4 small at height 3 (x symmetric about 2).
// hAll = (8*1 + 8*1 + 4*3)/20 = 1.4, vertical = (3 - 1)/1.4 = 10/7.
TEST(SegregationIndices, UnevenLayoutByHand)
{
    Layout bed;
    bed.add(1, 1, 1);
    bed.add(3, 1, 1);
    for (double px : {0.5, 1.5, 2.5, 3.5}) { bed.add(px, 3, 0); }
    const auto r = bed.indices();
    EXPECT_NEAR(r.hAll, 1.4, tol);
    EXPECT_NEAR(r.vertical, 10.0/7.0, tol);
    // r: large |1-2| = |3-2| = 1; small (1.5+0.5+0.5+1.5)/4 = 1
    EXPECT_NEAR(r.horizontal, 0.0, tol);
}

// Small at the walls, large in the centre, all at the same height y = 1:
// columns x = 0.5 and 3.5 hold 8 small each (r = 1.5), x = 1.5 and 2.5 one
// large each (r = 0.5): rAll = (16*1.5 + 16*0.5)/32 = 1 = W/4,
// horizontal = (1.5 - 0.5)/1 = +1; vertical = 0 (same heights).
TEST(SegregationIndices, SmallAtWallsIsPlusOneHorizontal)
{
    Layout bed;
    for (int k = 0; k < 8; ++k)
    {
        bed.add(0.5, 1, 0);
        bed.add(3.5, 1, 0);
    }
    bed.add(1.5, 1, 1);
    bed.add(2.5, 1, 1);
    const auto r = bed.indices();
    EXPECT_NEAR(r.rSmall, 1.5, tol);
    EXPECT_NEAR(r.rLarge, 0.5, tol);
    EXPECT_NEAR(r.rAll, 1.0, tol);
    EXPECT_NEAR(r.horizontal, 1.0, tol);
    EXPECT_NEAR(r.vertical, 0.0, tol);

    // Mirror image (one large at each wall, 8 small in each core column):
    // horizontal = (0.5 - 1.5)/1 = -1.
    Layout inverse;
    for (int k = 0; k < 8; ++k)
    {
        inverse.add(1.5, 1, 0);
        inverse.add(2.5, 1, 0);
    }
    inverse.add(0.5, 1, 1);
    inverse.add(3.5, 1, 1);
    EXPECT_NEAR(inverse.indices().horizontal, -1.0, tol);
}

// Heights count from the region's floor: lowering the floor by 1 adds 1 to
// every mean height. Small-on-top layout above: hAll = 3, vertical = 2/3.
// Particles outside the region do not count.
TEST(SegregationIndices, FloorAndRegion)
{
    Layout bed;
    bed.add(1, 0.5, 1);
    bed.add(3, 1.5, 1);
    bed.smallRow(2.5);
    bed.smallRow(3.5);
    bed.add(2, 10, 0);  // above the region
    const mixing::Region lower{0, 4, -1, 4};
    const auto r = bed.indices(&lower);
    EXPECT_EQ(r.nSmall, 16u);
    EXPECT_NEAR(r.hSmall, 4.0, tol);
    EXPECT_NEAR(r.hAll, 3.0, tol);
    EXPECT_NEAR(r.vertical, 2.0/3.0, tol);

    // Diameter overload, same answer.
    std::vector<double> d;
    for (int c : bed.c) { d.push_back(d12[c]); }
    const auto q = mixing::segregationIndices(bed.x.size(), bed.x.data(),
                                              bed.y.data(), d.data(), &lower);
    EXPECT_NEAR(q.vertical, 2.0/3.0, tol);
}

TEST(SegregationIndices, ErrorsAndAbsentClass)
{
    Layout bed;
    bed.smallRow(1);
    EXPECT_THROW(mixing::segregationIndices(bed.x.size(), bed.x.data(), bed.y.data(),
                     bed.c.data(), {1e-3}, &box), std::invalid_argument);
    const auto r = bed.indices();
    EXPECT_TRUE(std::isnan(r.hLarge));
    EXPECT_TRUE(std::isnan(r.vertical));
    EXPECT_NEAR(r.hSmall, 1.0, tol);
}
