// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The streaming loops (first half-kick with drift, second half-kick) compiled for AVX2 give
// the baseline version's bits, particle by particle, in the vector body and the remainder:
// the 2D discs' and the slab's spheres'.

#include "StreamingLoops.hpp"
#include "TestHelpers.hpp"
#include "dem/Random.hpp"
#include "dem/SlabSystem.hpp"
#include "dem/System.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

using namespace dem;

namespace {

constexpr std::ptrdiff_t n = 1003;   // odd: every version has a remainder

/// count arrays of n values in [-1, 1), scaled below to plausible magnitudes; the
/// inverse mass and inertia (arrays 0 and 1) made positive and of a particle's size.
std::vector<std::vector<double>> randomArrays(int count, std::uint64_t seed)
{
    std::vector<std::vector<double>> a(count, std::vector<double>(n));
    Random rng(seed);
    for (auto& v : a) {
        for (double& x : v) x = rng.uniform(-1.0, 1.0);
    }
    for (std::ptrdiff_t i = 0; i < n; ++i) {
        a[0][i] = 1.0 / (1e-6 + 1e-5 * std::abs(a[0][i]));     // invMass
        a[1][i] = 1.0 / (1e-12 + 1e-11 * std::abs(a[1][i]));   // invInertia
    }
    return a;
}

/// Arrays of plausible magnitudes (forces ~1e-4 N, velocities ~0.1 m/s, positions in a
/// 0.15 m box), a few particles with wall candidates.
struct Bed {
    static constexpr std::uint64_t seed = 42;
    static constexpr DriftStep step{1e-5, 0.5e-5, 0.0, -9.81, Box{0.0, 0.15, 0.0, 0.9}};
    static DriftLoop driftOf(const StreamingLoops& l) { return l.firstHalfKickAndDrift; }
    static KickLoop kickOf(const StreamingLoops& l) { return l.secondHalfKick; }

    std::vector<std::vector<double>> a;
    std::vector<int> wallStart;
    explicit Bed(std::uint64_t seed) : a(randomArrays(22, seed)), wallStart(n + 1, 0)
    {
        for (std::ptrdiff_t i = 0; i < n; ++i) {
            for (int k : {2, 3, 4, 5, 6}) a[k][i] *= 1e-4;          // forces, torque
            a[7][i] = 0.075 + 0.07 * a[7][i];                        // xRef
            a[8][i] = 0.3 + 0.2 * a[8][i];                           // yRef
            for (int k : {9, 10}) a[k][i] *= 0.3;                   // vx, vy
            a[11][i] *= 100.0;                                       // omega
            a[12][i] = a[7][i] + 1e-4 * a[12][i];                    // x
            a[13][i] = a[8][i] + 1e-4 * a[13][i];                    // y
            a[14][i] = 7e-4 + 5e-4 * a[14][i];                       // radius
            a[15][i] = 1e-3 * std::abs(a[15][i]);                    // drag K
            wallStart[i + 1] = wallStart[i] + (i % 37 == 0 ? 1 : 0);
        }
        a[12][500] = 0.2;   // one particle outside the 0.15 m wide box (x = 0.2 m)
    }
    DriftArrays drift()
    {
        return {a[0].data(), a[1].data(), a[2].data(), a[3].data(), a[4].data(),
                a[5].data(), a[6].data(), a[7].data(), a[8].data(), a[9].data(),
                a[10].data(), a[11].data(), a[12].data(), a[13].data()};
    }
    KickArrays kick()
    {
        return {wallStart.data(), a[2].data(), a[3].data(), a[14].data(), a[0].data(),
                a[1].data(), a[15].data(), a[16].data(), a[17].data(), a[18].data(),
                a[19].data(), a[6].data(), a[9].data(), a[10].data(), a[11].data(),
                a[4].data(), a[5].data(), a[20].data(), a[21].data()};
    }
};

/// The slab's arrays alike, in 3D: the spheres of a 5-mm slab, one outside it in z.
struct SlabBed {
    static constexpr std::uint64_t seed = 7;
    static constexpr SlabDriftStep step{1e-5, 0.5e-5, 0.0, -9.81, Box{0.0, 0.15, 0.0, 0.9},
                                        5e-3};
    static SlabDriftLoop driftOf(const StreamingLoops& l) { return l.slabFirstHalfKickAndDrift; }
    static SlabKickLoop kickOf(const StreamingLoops& l) { return l.slabSecondHalfKick; }

    std::vector<std::vector<double>> a;
    std::vector<int> wallStart;
    explicit SlabBed(std::uint64_t seed) : a(randomArrays(34, seed)), wallStart(n + 1, 0)
    {
        for (std::ptrdiff_t i = 0; i < n; ++i) {
            for (int k = 2; k <= 10; ++k) a[k][i] *= 1e-4;          // forces, fluid, torques
            a[11][i] = 0.075 + 0.07 * a[11][i];                      // xRef
            a[12][i] = 0.3 + 0.2 * a[12][i];                         // yRef
            a[13][i] = 2.5e-3 + 1e-3 * a[13][i];                     // zRef
            for (int k : {14, 15, 16}) a[k][i] *= 0.3;              // velocity
            for (int k : {17, 18, 19}) a[k][i] *= 100.0;            // spin
            for (int k : {20, 21, 22}) a[k][i] = a[k - 9][i] + 1e-4 * a[k][i];   // position
            a[23][i] = 7e-4 + 5e-4 * a[23][i];                       // radius
            a[24][i] = 1e-3 * std::abs(a[24][i]);                    // drag K
            wallStart[i + 1] = wallStart[i] + (i % 3 == 0 ? 2 : 0);  // front and back walls
        }
        a[22][700] = 6e-3;   // one sphere behind the 5-mm slab
    }
    SlabDriftArrays drift()
    {
        return {a[0].data(),  a[1].data(),  a[2].data(),  a[3].data(),  a[4].data(),
                a[5].data(),  a[6].data(),  a[7].data(),  a[8].data(),  a[9].data(),
                a[10].data(), a[11].data(), a[12].data(), a[13].data(), a[14].data(),
                a[15].data(), a[16].data(), a[17].data(), a[18].data(), a[19].data(),
                a[20].data(), a[21].data(), a[22].data()};
    }
    SlabKickArrays kick()
    {
        return {wallStart.data(), a[2].data(),  a[3].data(),  a[4].data(),  a[23].data(),
                a[0].data(),      a[1].data(),  a[24].data(), a[25].data(), a[26].data(),
                a[27].data(),     a[28].data(), a[29].data(), a[30].data(), a[8].data(),
                a[9].data(),      a[10].data(), a[14].data(), a[15].data(), a[16].data(),
                a[17].data(),     a[18].data(), a[19].data(), a[5].data(),  a[6].data(),
                a[7].data(),      a[31].data(), a[32].data(), a[33].data()};
    }
};

template <class B>
bool sameBits(const B& x, const B& y)
{
    for (std::size_t k = 0; k < x.a.size(); ++k) {
        if (std::memcmp(x.a[k].data(), y.a[k].data(), n * sizeof(double)) != 0) return false;
    }
    return true;
}

/// The drift and the kick in all three modes, from the first particle and from the fifth,
/// on two copies of bed B: one by the baseline loops, one by the AVX2 ones.
template <class B>
void expectAvxGivesTheBaselineBits()
{
    const StreamingLoops& base = streamingLoops(SimdLevel::baseline);
    const StreamingLoops& avx2 = streamingLoops(SimdLevel::avx2);
    B b(B::seed), v(B::seed);
    for (const std::ptrdiff_t first : {std::ptrdiff_t{0}, std::ptrdiff_t{5}}) {
        double maxB = 0.0, lostB = 0.0, maxV = 0.0, lostV = 0.0;
        B::driftOf(base)(b.drift(), B::step, first, n, maxB, lostB);
        B::driftOf(avx2)(v.drift(), B::step, first, n, maxV, lostV);
        EXPECT_EQ(std::memcmp(&maxB, &maxV, sizeof(double)), 0);
        EXPECT_EQ(lostB, 1.0);   // the one particle out of bounds
        EXPECT_EQ(lostV, 1.0);
        for (const KickMode mode :
             {KickMode::fluid, KickMode::forcesOnly, KickMode::torqueOnly}) {
            B::kickOf(base)(b.kick(), first, n, 0.5e-5, 0.0, -9.81, 1.0, mode);
            B::kickOf(avx2)(v.kick(), first, n, 0.5e-5, 0.0, -9.81, 1.0, mode);
        }
    }
    EXPECT_TRUE(sameBits(b, v));
}

} // namespace

TEST(StreamingLoops, AvxGivesTheBaselineBits)
{
    if (!cpuHasAvx2()) GTEST_SKIP() << "this CPU has no AVX2: only the baseline runs here";
    ASSERT_EQ(streamingLoops(SimdLevel::baseline).level, SimdLevel::baseline);
    ASSERT_EQ(streamingLoops(SimdLevel::avx2).level, SimdLevel::avx2);
    expectAvxGivesTheBaselineBits<Bed>();
}

TEST(StreamingLoops, SlabAvxGivesTheBaselineBits)
{
    if (!cpuHasAvx2()) GTEST_SKIP() << "this CPU has no AVX2: only the baseline runs here";
    expectAvxGivesTheBaselineBits<SlabBed>();
}

// A bad DEM_SIMD is refused when an engine is made, 2D or slab, with a dem::Error naming the
// variable and the allowed values (the solver reports it as a bad setting), not at a first
// step. ctest runs each test in a process of its own, where no loops were chosen before.
TEST(StreamingLoops, BadDemSimdIsRefusedByBothEngines)
{
    Settings s = test::paperSettings({0.0, 0.15, 0.0, 0.9});
    ASSERT_EQ(setenv("DEM_SIMD", "sse9", 1), 0);
    for (const int dimension : {2, 3}) {
        s.dimension = dimension;
        s.slabDepth = 5e-3;
        try {
            if (dimension == 2) {
                System sim(s);
            } else {
                SlabSystem sim(s);
            }
            ADD_FAILURE() << "DEM_SIMD = sse9 accepted in " << dimension << "D";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("DEM_SIMD = 'sse9' is not one of: baseline, avx2"),
                      std::string::npos)
                << e.what();
        }
    }
    ASSERT_EQ(unsetenv("DEM_SIMD"), 0);
    SlabSystem sim(s);   // the best this CPU runs
}
