// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// NBS (Munjiza & Andrews 1998) must find exactly the pairs of the brute-force oracle.

#include "dem/NbsSearch.hpp"
#include "dem/Random.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

using namespace dem;

namespace {

struct Config {
    std::vector<double> x, y, r;
};

/// Random positions (overlaps allowed: the search must not care) of both paper sizes, plus
/// particles placed on the walls, in the corners and exactly on cell edges.
Config makeConfig(std::uint64_t seed, int n, double w, double h, double cell)
{
    Random random(seed);
    Config c;
    auto add = [&](double x, double y, double r) {
        c.x.push_back(x);
        c.y.push_back(y);
        c.r.push_back(r);
    };
    for (int k = 0; k < n; ++k) {
        const double r = random.uniform() < 0.5 ? 0.75e-3 : 1.25e-3;
        add(random.uniform(r, w - r), random.uniform(r, h - r), r);
    }
    for (int k = 0; k < 40; ++k) {
        const double r = k % 2 ? 0.75e-3 : 1.25e-3;
        const double s = random.uniform(0.0, 1.0);
        add(r * 0.99, s * h, r);                         // left wall, slightly overlapping it
        add(w - r, s * h, r);                            // right wall
        add(s * w, 0.0, r);                              // on the floor line
        add(s * w, h, r);                                // on the ceiling line
        add(std::floor(s * w / cell) * cell, s * h, r);  // on a column edge
        add(s * w, std::floor(s * h / cell) * cell, r);  // on a row edge
    }
    for (double x : {0.0, w}) {
        for (double y : {0.0, h}) add(x, y, 1.25e-3);   // corners
    }
    return c;
}

std::vector<std::pair<int, int>> sorted(const std::vector<IndexPair>& pairs)
{
    std::vector<std::pair<int, int>> s;
    for (const auto& p : pairs) s.emplace_back(p.i, p.j);
    std::sort(s.begin(), s.end());
    return s;
}

} // namespace

TEST(Nbs, EqualsBruteForceOnSeededConfigurations)
{
    // Box widths that are and are not multiples of the cell; margin 0 (contacts) and the
    // Verlet skins of 0.1, 0.4 and 0.8 d_small (the adaptive skin's bounds and start);
    // dense and dilute.
    for (std::uint64_t seed : {1u, 2u, 3u}) {
        for (double w : {0.15, 0.0437}) {
            for (int n : {300, 3000}) {
                for (double margin : {0.0, 1.5e-4, 6e-4, 1.2e-3}) {
                    const double h = 0.06;
                    const double cellMin = 2.5e-3 + margin;
                    NbsSearch nbs(0.0, w, 0.0, h, cellMin);
                    const Config c = makeConfig(seed, n, w, h, nbs.mapper().cellWidth());
                    std::vector<IndexPair> fast, slow;
                    nbs.findPairs(c.x.data(), c.y.data(), c.r.data(), c.x.size(), margin, fast);
                    bruteForcePairs(c.x.data(), c.y.data(), c.r.data(), c.x.size(), margin, slow);
                    ASSERT_FALSE(slow.empty());
                    EXPECT_EQ(fast.size(), slow.size()) << "seed " << seed << " w " << w << " n " << n;
                    EXPECT_EQ(sorted(fast), sorted(slow)) << "seed " << seed << " w " << w << " n " << n;
                }
            }
        }
    }
}

TEST(Nbs, BandsOfRowsGiveTheOneThreadOrder)
{
    // The pair order fixes the order of the force sums: 2 and 3 threads must give the
    // 1-thread list entry for entry, also with more threads than occupied rows.
    for (int n : {3000, 5}) {
        const double w = 0.15, h = 0.06, margin = 1.5e-4;
        NbsSearch nbs(0.0, w, 0.0, h, 2.5e-3 + margin);
        const Config c = makeConfig(7, n, w, h, nbs.mapper().cellWidth());
        std::vector<IndexPair> one, many;
        nbs.findPairs(c.x.data(), c.y.data(), c.r.data(), c.x.size(), margin, one, 1);
        for (int threads : {2, 3}) {
            nbs.findPairs(c.x.data(), c.y.data(), c.r.data(), c.x.size(), margin, many, threads);
            ASSERT_EQ(many.size(), one.size()) << threads << " threads, n " << n;
            for (std::size_t k = 0; k < one.size(); ++k) {
                ASSERT_TRUE(many[k].i == one[k].i && many[k].j == one[k].j)
                    << "entry " << k << ", " << threads << " threads, n " << n;
            }
        }
    }
}

TEST(Nbs, CellsAreAboutOneLargestDiameter)
{
    NbsSearch nbs(0.0, 0.15, 0.0, 0.9, 2.65e-3);
    EXPECT_EQ(nbs.mapper().nColumns(), 56);
    EXPECT_GE(nbs.mapper().cellWidth(), 2.65e-3);
    EXPECT_LT(nbs.mapper().cellWidth(), 1.1 * 2.65e-3);
    EXPECT_GE(nbs.mapper().cellHeight(), 2.65e-3);
}

TEST(Nbs, ParticlesTooLargeForTheCellsAreTestedAgainstAll)
{
    // Beads of 3.1 mm with cells sized by them and eight intruders of 9.4 mm, three of them
    // overlapping one another, one on a wall, one in a corner: the pairs of the oracle, in
    // the same order for any thread count.
    const double w = 0.038, h = 0.05, rBead = 1.55e-3, rLarge = 4.7e-3;
    for (double margin : {0.0, 3e-4}) {
        NbsSearch nbs(0.0, w, 0.0, h, 2.0 * rBead + margin);
        Random random(11);
        Config c;
        for (int k = 0; k < 400; ++k) {
            c.x.push_back(random.uniform(rBead, w - rBead));
            c.y.push_back(random.uniform(rBead, h - rBead));
            c.r.push_back(rBead);
        }
        const double large[8][2] = {{0.010, 0.020}, {0.018, 0.021}, {0.014, 0.027}, {0.030, 0.010},
                                    {0.99 * rLarge, 0.04}, {0.0, 0.0}, {0.025, 0.045}, {0.033, 0.030}};
        for (int k = 0; k < 8; ++k) {
            const auto at = c.x.begin() + 50 * k;   // among the beads' indices
            c.y.insert(c.y.begin() + 50 * k, large[k][1]);
            c.r.insert(c.r.begin() + 50 * k, rLarge);
            c.x.insert(at, large[k][0]);
        }
        std::vector<IndexPair> fast, slow, two;
        nbs.findPairs(c.x.data(), c.y.data(), c.r.data(), c.x.size(), margin, fast);
        bruteForcePairs(c.x.data(), c.y.data(), c.r.data(), c.x.size(), margin, slow);
        int largeLarge = 0;
        for (const auto& p : slow) largeLarge += c.r[p.i] == rLarge && c.r[p.j] == rLarge;
        ASSERT_GE(largeLarge, 3);
        EXPECT_EQ(sorted(fast), sorted(slow)) << "margin " << margin;
        nbs.findPairs(c.x.data(), c.y.data(), c.r.data(), c.x.size(), margin, two, 2);
        ASSERT_EQ(two.size(), fast.size());
        for (std::size_t k = 0; k < two.size(); ++k) {
            ASSERT_TRUE(two[k].i == fast[k].i && two[k].j == fast[k].j) << "entry " << k;
        }
    }
}
