// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Lacey index on hand-made configurations with known answers (docs/model.md,
// "Mixing"). Diameters 1 mm and 2 mm give the equivalent-particle weight
// w = (2/1)^3 = 8, which keeps the hand arithmetic exact. Tolerance: 1e-12
// (absolute) on values of order 1, the arithmetic being a few sums.
#include "mixing/LaceyIndex.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{

constexpr double tol = 1e-12;
constexpr double h = 5e-3;                       // sampling cell (m)
const std::vector<double> d12 = {1e-3, 2e-3};    // small, large (w = 8)

/// Particles with class indices; add() puts them near the centre of
/// sampling cell (i, j), spread a little so that no two coincide.
struct Bed
{
    std::vector<double> x, y;
    std::vector<int> c;

    void add(int i, int j, int nSmall, int nLarge)
    {
        for (int k = 0; k < nSmall + nLarge; ++k)
        {
            x.push_back((i + 0.5)*h + 1e-4*(k % 5 - 2));
            y.push_back((j + 0.5)*h + 1e-4*(k/5 - 2));
            c.push_back(k < nSmall ? 0 : 1);
        }
    }
    std::size_t n() const { return x.size(); }

    mixing::LaceyResult lacey(mixing::VarianceBasis basis,
                              const std::vector<double>& d = d12) const
    {
        mixing::LaceySettings s;
        s.basis = basis;
        s.useRegion = true;
        s.region = {0, 0.02, 0, 0.02};  // 4 x 4 cells from the origin
        return mixing::laceyIndex(n(), x.data(), y.data(), c.data(), d, s);
    }
};

using mixing::VarianceBasis;

} // namespace


// Every occupied cell holds one class only, so X_i is 1 or 0:
// S2 = [p K (1-p)^2 + q K p^2]/K = p q (q + p) = p q = S02, hence M = 0
// whatever N is. Here two cells of 3 small and two of 1 large:
// K = 6 + 2*8 = 22, p = 6/22.
TEST(LaceyIndex, FullySegregatedGivesZero)
{
    Bed bed;
    bed.add(0, 0, 3, 0);
    bed.add(1, 0, 3, 0);
    bed.add(0, 1, 0, 1);
    bed.add(1, 1, 0, 1);
    for (auto basis : {VarianceBasis::wholeBed, VarianceBasis::perSample})
    {
        const auto r = bed.lacey(basis);
        EXPECT_NEAR(r.p, 6.0/22.0, tol);
        EXPECT_NEAR(r.S2, r.S02, tol);
        EXPECT_NEAR(r.S02, (6.0/22.0)*(16.0/22.0), tol);
        EXPECT_NEAR(r.M, 0.0, tol);
        EXPECT_EQ(r.nCells, 4u);
        EXPECT_EQ(r.nSmall, 6u);
        EXPECT_EQ(r.nLarge, 2u);
    }
}

// Ten identical cells of 4 small + 1 large: k = 4 + 8 = 12, X_i = 1/3 = p,
// so S2 = 0 and M = S02/(S02 - S02/n) = 1/(1 - 1/n).
// perSample: n = 120/10 = 12 -> M = 12/11. wholeBed: N = 120 -> M = 120/119.
TEST(LaceyIndex, IdenticalCellsGiveOneOverOneMinusOneOverN)
{
    Bed bed;
    for (int cell = 0; cell < 10; ++cell)
    {
        bed.add(cell % 4, cell/4, 4, 1);
    }
    const auto s = bed.lacey(VarianceBasis::perSample);
    EXPECT_NEAR(s.S2, 0.0, tol);
    EXPECT_NEAR(s.p, 1.0/3.0, tol);
    EXPECT_NEAR(s.N, 12.0, tol);
    EXPECT_NEAR(s.M, 1.0/(1.0 - 1.0/12.0), tol);
    EXPECT_EQ(s.nCells, 10u);
    EXPECT_EQ(s.basis, VarianceBasis::perSample);

    const auto w = bed.lacey(VarianceBasis::wholeBed);
    EXPECT_NEAR(w.N, 120.0, tol);
    EXPECT_NEAR(w.M, 120.0/119.0, tol);
}

// Three cells, w = 8:
//   A: 4 small, 0 large: k = 4,  X = 1
//   B: 2 small, 1 large: k = 10, X = 1/5
//   C: 2 small, 2 large: k = 18, X = 1/9
// K = 32, p = 8/32 = 1/4, S02 = 3/16.
// S2 = [4 (3/4)^2 + 10 (1/20)^2 + 18 (5/36)^2]/32 = (9/4 + 1/40 + 25/72)/32
//    = (118/45)/32 = 59/720.
// wholeBed:  N = 32,   SR2 = 3/512, M = (19/180)/(93/512) = 2432/4185.
// perSample: n = 32/3, SR2 = 9/512, M = (19/180)/(87/512) = 2432/3915.
TEST(LaceyIndex, ThreeCellsByHand)
{
    Bed bed;
    bed.add(0, 0, 4, 0);
    bed.add(1, 0, 2, 1);
    bed.add(2, 0, 2, 2);

    const auto w = bed.lacey(VarianceBasis::wholeBed);
    EXPECT_EQ(w.nCells, 3u);
    EXPECT_NEAR(w.weightLarge, 8.0, tol);
    EXPECT_NEAR(w.p, 0.25, tol);
    EXPECT_NEAR(w.S02, 3.0/16.0, tol);
    EXPECT_NEAR(w.S2, 59.0/720.0, tol);
    EXPECT_NEAR(w.N, 32.0, tol);
    EXPECT_NEAR(w.SR2, 3.0/512.0, tol);
    EXPECT_NEAR(w.M, 2432.0/4185.0, tol);

    const auto s = bed.lacey(VarianceBasis::perSample);
    EXPECT_NEAR(s.S2, 59.0/720.0, tol);
    EXPECT_NEAR(s.N, 32.0/3.0, tol);
    EXPECT_NEAR(s.SR2, 9.0/512.0, tol);
    EXPECT_NEAR(s.M, 2432.0/3915.0, tol);
}

// Which index is small follows the diameters, not the order: swapping the
// class list and every index gives the same answer.
TEST(LaceyIndex, SmallClassFollowsDiameterNotIndex)
{
    Bed bed;
    bed.add(0, 0, 4, 0);
    bed.add(1, 0, 2, 1);
    bed.add(2, 0, 2, 2);
    Bed swapped = bed;
    for (int& c : swapped.c) { c = 1 - c; }
    const auto a = bed.lacey(VarianceBasis::wholeBed);
    const auto b = swapped.lacey(VarianceBasis::wholeBed, {2e-3, 1e-3});
    EXPECT_NEAR(a.M, b.M, tol);
    EXPECT_NEAR(a.p, b.p, tol);
    EXPECT_EQ(a.nSmall, b.nSmall);
}

// The paper's sizes: one 2.5 mm particle counts (2.5/1.5)^3 = 125/27 = 4.63
// small ones. One cell with 27 small and 27 large: K = 27 + 125 = 152,
// p = 27/152.
TEST(LaceyIndex, PaperWeightIsDiameterRatioCubed)
{
    Bed bed;
    bed.add(0, 0, 27, 27);
    const auto r = bed.lacey(VarianceBasis::wholeBed, {1.5e-3, 2.5e-3});
    EXPECT_NEAR(r.weightLarge, 125.0/27.0, tol);
    EXPECT_NEAR(r.p, 27.0/152.0, tol);
    EXPECT_NEAR(r.N, 152.0, 1e-9);
}

// Classes from diameters: the diameter overload equals the class-index one.
TEST(LaceyIndex, DiameterOverloadMatchesClassIndices)
{
    Bed bed;
    bed.add(0, 0, 4, 0);
    bed.add(1, 0, 2, 1);
    bed.add(2, 0, 2, 2);
    std::vector<double> d;
    for (int c : bed.c) { d.push_back(d12[c]); }
    mixing::LaceySettings s;
    s.useRegion = true;
    s.region = {0, 0.02, 0, 0.02};
    const auto a = mixing::laceyIndex(bed.n(), bed.x.data(), bed.y.data(), d.data(), s);
    EXPECT_NEAR(a.M, 2432.0/4185.0, tol);

    const auto sc = mixing::classifyByDiameter(d.size(), d.data());
    ASSERT_EQ(sc.diameters.size(), 2u);
    EXPECT_EQ(sc.diameters[0], 1e-3);
    EXPECT_EQ(sc.classIndex, bed.c);
}

// Particles outside the region are ignored; without a region the bounding
// box of the centres is sampled, the grid starting at its lower-left corner.
TEST(LaceyIndex, RegionSelectsParticles)
{
    Bed bed;
    bed.add(0, 0, 4, 0);
    bed.add(1, 0, 2, 1);
    bed.add(2, 0, 2, 2);
    bed.x.push_back(0.5);            // far outside the 2 cm region
    bed.y.push_back(0.5);
    bed.c.push_back(1);
    const auto r = bed.lacey(VarianceBasis::wholeBed);
    EXPECT_EQ(r.nLarge, 3u);
    EXPECT_NEAR(r.M, 2432.0/4185.0, tol);

    // One small at the origin, one large 1 cm to the right: two cells.
    const double x[] = {0.0, 0.01}, y[] = {0.0, 0.0};
    const int c[] = {0, 1};
    const auto b = mixing::laceyIndex(2, x, y, c, d12);
    EXPECT_EQ(b.nCells, 2u);
    EXPECT_NEAR(b.M, 0.0, tol);
}

// A measure that is undefined gives NaN, not an exception.
TEST(LaceyIndex, OneClassOnlyGivesNaN)
{
    Bed bed;
    bed.add(0, 0, 5, 0);
    const auto r = bed.lacey(VarianceBasis::wholeBed);
    EXPECT_TRUE(std::isnan(r.M));
    EXPECT_EQ(r.S02, 0.0);
    const auto e = mixing::laceyIndex(0, nullptr, nullptr,
                                      static_cast<const int*>(nullptr), d12);
    EXPECT_TRUE(std::isnan(e.M));
    EXPECT_EQ(e.nCells, 0u);
}

namespace
{

/// Message of the std::invalid_argument that f throws ("" if none).
template<class F>
std::string invalidMessage(F f)
{
    try { f(); }
    catch (const std::invalid_argument& e) { return e.what(); }
    return "";
}

bool has(const std::string& s, const char* part)
{
    return s.find(part) != std::string::npos;
}

} // namespace

TEST(LaceyIndex, ClearErrors)
{
    Bed bed;
    bed.add(0, 0, 4, 1);
    mixing::LaceySettings s;

    auto three = invalidMessage([&] {
        mixing::laceyIndex(bed.n(), bed.x.data(), bed.y.data(), bed.c.data(),
                           {1e-3, 2e-3, 3e-3}, s); });
    EXPECT_TRUE(has(three, "classDiameters") && has(three, "exactly 2")) << three;

    auto equal = invalidMessage([&] {
        mixing::laceyIndex(bed.n(), bed.x.data(), bed.y.data(), bed.c.data(),
                           {1e-3, 1e-3}, s); });
    EXPECT_TRUE(has(equal, "classDiameters") && has(equal, "different")) << equal;

    for (double size : {0.0, -5e-3})
    {
        s.cellSize = size;
        auto cell = invalidMessage([&] {
            mixing::laceyIndex(bed.n(), bed.x.data(), bed.y.data(), bed.c.data(), d12, s); });
        EXPECT_TRUE(has(cell, "cellSize") && has(cell, "> 0")) << cell;
    }
    s.cellSize = h;

    bed.c[0] = 2;
    auto index = invalidMessage([&] {
        mixing::laceyIndex(bed.n(), bed.x.data(), bed.y.data(), bed.c.data(), d12, s); });
    EXPECT_TRUE(has(index, "classIndex[0] = 2") && has(index, "0 or 1")) << index;
    bed.c[0] = 0;

    s.useRegion = true;
    s.region = {0.1, 0.0, 0.0, 0.1};
    auto region = invalidMessage([&] {
        mixing::laceyIndex(bed.n(), bed.x.data(), bed.y.data(), bed.c.data(), d12, s); });
    EXPECT_TRUE(has(region, "region") && has(region, "xMin <= xMax")) << region;

    const double d3[] = {1e-3, 2e-3, 3e-3}, x3[] = {0, 0, 0};
    auto poly = invalidMessage([&] { mixing::laceyIndex(3, x3, x3, d3); });
    EXPECT_TRUE(has(poly, "3 size classes")) << poly;

    auto basis = invalidMessage([] { mixing::varianceBasisFromString("lacey"); });
    EXPECT_TRUE(has(basis, "varianceBasis") && has(basis, "wholeBed")
             && has(basis, "perSample")) << basis;
    EXPECT_EQ(mixing::varianceBasisFromString("perSample"), VarianceBasis::perSample);
    EXPECT_STREQ(mixing::toString(VarianceBasis::wholeBed), "wholeBed");
}
