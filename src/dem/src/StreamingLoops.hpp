// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The engines' loops that stream through the particle arrays, one particle at a time: the
// first half-kick with the drift, and the second half-kick, for the 2D discs and for the
// slab's spheres (internal to the library).
//
// Compiled twice, for AVX2 (4 doubles a vector) and for the baseline x86-64 (SSE2, 2
// doubles), and picked at run time: AVX2 where the CPU has it, unless the environment
// variable DEM_SIMD says baseline; the build stays portable. Neither version fuses
// multiply-adds (AVX2 without FMA), so both do the same IEEE operations per particle: the
// same bits (dem.StreamingLoops.AvxGivesTheBaselineBits).
//
// Why not GCC's target_clones("avx2", "default"): it compiles the same two versions (GCC 12:
// the same instructions but for the order of commuted operands and stack slots; the same
// bits and, within the noise, the same time in demBench's fluidized bed and slab), but its
// resolver picks one by the CPU when the library is loaded and offers no other: DEM_SIMD,
// and the test above, which runs both versions in one process, would then need a second
// compile of each body for the baseline, the work Compiled does here.

#include "dem/ContactLaw.hpp"
#include "dem/Facade.hpp"   // Box

#include <array>
#include <cstddef>

namespace dem {

struct DriftArrays {
    const double *invMass, *invInertia, *fx, *fy, *fluidX, *fluidY, *torque, *xRef, *yRef;
    double *vx, *vy, *omega, *x, *y;
};

struct DriftStep {
    double dt, h, gx, gy;   ///< time step, half of it, gravity
    Box box;
};

/// v += h (F + F_fluid)/m + h g, omega += h T/I, x += dt v for particles [first, last);
/// raises maxDisplacement2 to the largest squared distance from (xRef, yRef) and adds to
/// lost the particles outside the box (NaN counts as outside).
using DriftLoop = void (*)(const DriftArrays& a, const DriftStep& c, std::ptrdiff_t first,
                          std::ptrdiff_t last, double& maxDisplacement2, double& lost);

struct KickArrays {
    const int* wallStart;   ///< the wall list's start: particles with walls have their torque
    const double *fx, *fy, *radius, *invMass, *invInertia, *dragK, *gasVx, *gasVy, *extraFx,
        *extraFy;
    double *torque, *vx, *vy, *omega, *fluidX, *fluidY, *meanVx, *meanVy;
};

/// What the second half-kick does besides making the torque whole: kick with the drag
/// implicit and the sub-step means, kick with the forces and gravity only, or nothing more
/// (the first force evaluation).
enum class KickMode { fluid, forcesOnly, torqueOnly };

/// The mode of an engine's addWallForcesAndKick(historyDt, kick, fluid).
inline KickMode kickMode(bool kick, bool fluid)
{
    return !kick ? KickMode::torqueOnly : fluid ? KickMode::fluid : KickMode::forcesOnly;
}

/// The second half-kick of particles [first, last). torque holds the sum of tangential
/// forces of a particle without wall candidates (times its radius here) and the whole torque
/// of one with them.
using KickLoop = void (*)(const KickArrays& a, std::ptrdiff_t first, std::ptrdiff_t last,
                         double h, double gx, double gy, double weight, KickMode mode);

struct SlabDriftArrays {
    const double *invMass, *invInertia, *fx, *fy, *fz, *fluidX, *fluidY, *fluidZ, *tx, *ty,
        *tz, *xRef, *yRef, *zRef;
    double *vx, *vy, *vz, *wx, *wy, *wz, *x, *y, *z;
};

struct SlabDriftStep {
    double dt, h, gx, gy;   ///< time step, half of it, gravity (in the plane)
    Box box;
    double depth;           ///< the slab's walls at z = 0 and z = depth
};

/// The slab's DriftLoop: spheres in 3D, outside the box or the slab counted as lost.
using SlabDriftLoop = void (*)(const SlabDriftArrays& a, const SlabDriftStep& c,
                              std::ptrdiff_t first, std::ptrdiff_t last,
                              double& maxDisplacement2, double& lost);

struct SlabKickArrays {
    const int* wallStart;   ///< as KickArrays
    const double *fx, *fy, *fz, *radius, *invMass, *invInertia, *dragK, *gasVx, *gasVy, *gasVz,
        *extraFx, *extraFy, *extraFz;
    double *tx, *ty, *tz, *vx, *vy, *vz, *wx, *wy, *wz, *fluidX, *fluidY, *fluidZ, *meanVx,
        *meanVy, *meanVz;
};

/// The slab's KickLoop (the torque a vector).
using SlabKickLoop = void (*)(const SlabKickArrays& a, std::ptrdiff_t first,
                             std::ptrdiff_t last, double h, double gx, double gy,
                             double weight, KickMode mode);

/// The touching contacts of the slab in a batch, structure of arrays: the pair or wall loop
/// gathers them, a SlabPairLoop evaluates contactForce<3, Law> for all at once (vectorised
/// across the contacts, no branch), the loop adds the forces in list order. One contact's
/// operations and their order are contactForce's, the law's force its policy's: the same bits.
struct SlabPairBatch {
    static constexpr int capacity = 64;
    // In, pairs: x_j - x_i, r_i + r_j; walls: nHat (towards the wall), the overlap. Both:
    // v_i - v_j (walls: v_i), r_i w_i + r_j w_j (walls: r_i w_i), the law's four constants
    // (LawConstants), mu. xi*: the stored tangential history in, the new one out.
    alignas(64) double dx[capacity], dy[capacity], dz[capacity], rSum[capacity];
    alignas(64) double nx[capacity], ny[capacity], nz[capacity];
    alignas(64) double dvx[capacity], dvy[capacity], dvz[capacity];
    alignas(64) double sx[capacity], sy[capacity], sz[capacity];
    alignas(64) double xix[capacity], xiy[capacity], xiz[capacity];
    alignas(64) double normal[capacity], normalDamping[capacity], tangential[capacity],
        tangentialDamping[capacity], mu[capacity];
    // Out: the force on i, nHat x Ft (the torque on either partner over its radius), overlap.
    alignas(64) double fx[capacity], fy[capacity], fz[capacity];
    alignas(64) double nxFx[capacity], nxFy[capacity], nxFz[capacity], overlap[capacity];

    /// Contact q's constants of law Law and its friction.
    template <class Law> void setLaw(int q, const ContactLaw& c)
    {
        const LawConstants<double> k = Law::constants(c);
        normal[q] = k.normal;
        normalDamping[q] = k.normalDamping;
        tangential[q] = k.tangential;
        tangentialDamping[q] = k.tangentialDamping;
        mu[q] = c.mu;
    }
};

/// contactForce<3, Law> without rolling resistance for contacts [0, count) of a batch, the
/// history accumulated over dt.
using SlabPairLoop = void (*)(SlabPairBatch& b, int count, double dt);

/// One law's batched loops: of sphere pairs, and of wall contacts (nHat and overlap given).
struct SlabLawLoops {
    SlabPairLoop pairs;
    SlabPairLoop walls;
};

enum class SimdLevel { baseline, avx2 };

struct StreamingLoops {
    SimdLevel level;
    DriftLoop firstHalfKickAndDrift;
    KickLoop secondHalfKick;
    SlabDriftLoop slabFirstHalfKickAndDrift;
    SlabKickLoop slabSecondHalfKick;
    std::array<SlabLawLoops, ContactLaws::size> slabLaws;   ///< in the order of ContactLaws
    // Those of the linear law and of Hertz-Mindlin by name, as their test takes them
    SlabPairLoop slabLinearPairs, slabHertzPairs, slabLinearWalls, slabHertzWalls;

    /// The batched loops of law Law.
    template <class Law> const SlabLawLoops& slab() const
    {
        return slabLaws[ContactLaws::indexOf<Law>()];
    }
};

#if defined(__x86_64__) && defined(__GNUC__)
#define DEM_HAVE_AVX2_LOOPS 1
#endif

/// One loop body compiled for both instruction sets: Compiled<body, Loop>::baseline and
/// ::avx2 have the signature of the function pointer type Loop and inline body (an
/// always_inline function), so that the compiler vectorises it for each.
template <auto body, class Loop>
struct Compiled;

template <auto body, class... Args>
struct Compiled<body, void (*)(Args...)> {
    static void baseline(Args... args) { body(args...); }
#ifdef DEM_HAVE_AVX2_LOOPS
    __attribute__((target("avx2"))) static void avx2(Args... args) { body(args...); }
#endif
};

/// The slab's loops of a level (SlabStreamingLoops.cpp), for the tables of streamingLoops.
namespace slabLoops {
SlabDriftLoop drift(SimdLevel level);
SlabKickLoop kick(SimdLevel level);
/// Every law's batched loops, in the order of ContactLaws (SlabPairKernel.cpp).
std::array<SlabLawLoops, ContactLaws::size> laws(SimdLevel level);
} // namespace slabLoops

/// Whether this CPU runs the AVX2 version.
bool cpuHasAvx2();

/// The loops of one level; throws dem::Error for avx2 on a CPU without it.
const StreamingLoops& streamingLoops(SimdLevel level);

/// The loops in use, chosen once: $DEM_SIMD = baseline or avx2 if set (anything else, or
/// avx2 on a CPU without it, throws dem::Error naming the variable), else the best the CPU
/// has.
const StreamingLoops& streamingLoops();

} // namespace dem
