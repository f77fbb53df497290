// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The 2D streaming loops of StreamingLoops.hpp: one body each, compiled for the baseline and
// for AVX2 (Compiled), and the choice between them (the slab's in SlabStreamingLoops.cpp).

#include "StreamingLoops.hpp"

#include "dem/Error.hpp"
#include "dem/Facade.hpp"

#include <algorithm>
#include <cstdlib>
#include <string>

namespace dem {

namespace {

using Index = std::ptrdiff_t;

// The arrays by value: the loops see plain local pointers
[[gnu::always_inline]] inline void driftBody(const DriftArrays a, const DriftStep& c,
                                             Index first, Index last, double& maxDisplacement2,
                                             double& lost)
{
    const double dt = c.dt, h = c.h, gx = c.gx, gy = c.gy;
    const double xMin = c.box.xMin, xMax = c.box.xMax, yMin = c.box.yMin, yMax = c.box.yMax;
    double maxD2 = maxDisplacement2;
    // Counted in a double from selects: GCC vectorises that, and not an integer flag
    double outside = lost;
#pragma omp simd reduction(max : maxD2) reduction(+ : outside)
    for (Index i = first; i < last; ++i) {
        const double invM = a.invMass[i];
        const double vxNew = a.vx[i] + h * ((a.fx[i] + a.fluidX[i]) * invM + gx);
        const double vyNew = a.vy[i] + h * ((a.fy[i] + a.fluidY[i]) * invM + gy);
        a.vx[i] = vxNew;
        a.vy[i] = vyNew;
        a.omega[i] += h * a.torque[i] * a.invInertia[i];
        const double xNew = a.x[i] + dt * vxNew;
        const double yNew = a.y[i] + dt * vyNew;
        a.x[i] = xNew;
        a.y[i] = yNew;
        const double dx = xNew - a.xRef[i];
        const double dy = yNew - a.yRef[i];
        maxD2 = std::max(maxD2, dx * dx + dy * dy);
        const double outX = xNew >= xMin && xNew <= xMax ? 0.0 : 1.0;
        const double outY = yNew >= yMin && yNew <= yMax ? 0.0 : 1.0;
        outside += outX + outY;
    }
    maxDisplacement2 = maxD2;
    lost = outside;
}

// Particle i's torque made whole and stored: one with wall candidates has it already (a
// factor of 1 keeps it exactly, and a select of loaded values vectorises), the others the
// sum of their tangential forces, times the radius here
[[gnu::always_inline]] inline double wholeTorque(const KickArrays& a, Index i)
{
    const double scale = a.wallStart[i] == a.wallStart[i + 1] ? a.radius[i] : 1.0;
    const double torque = scale * a.torque[i];
    a.torque[i] = torque;
    return torque;
}

[[gnu::always_inline]] inline void kickBody(const KickArrays a, Index first, Index last,
                                            double h, double gx, double gy, double weight,
                                            KickMode mode)
{
    if (mode == KickMode::fluid) {
#pragma omp simd
        for (Index i = first; i < last; ++i) {
            const double torque = wholeTorque(a, i);
            const double invM = a.invMass[i];
            // Second half-kick, the drag implicit: v = v_half + h (F + K (u - v) + extra)/m.
            const double K = a.dragK[i];
            const double denominator = 1.0 + h * K * invM;
            const double ax = (a.fx[i] + K * a.gasVx[i] + a.extraFx[i]) * invM + gx;
            const double ay = (a.fy[i] + K * a.gasVy[i] + a.extraFy[i]) * invM + gy;
            const double vxNew = (a.vx[i] + h * ax) / denominator;
            const double vyNew = (a.vy[i] + h * ay) / denominator;
            a.vx[i] = vxNew;
            a.vy[i] = vyNew;
            a.fluidX[i] = K * (a.gasVx[i] - vxNew) + a.extraFx[i];
            a.fluidY[i] = K * (a.gasVy[i] - vyNew) + a.extraFy[i];
            a.meanVx[i] += weight * vxNew;
            a.meanVy[i] += weight * vyNew;
            a.omega[i] += h * torque * a.invInertia[i];
        }
    } else if (mode == KickMode::forcesOnly) {
#pragma omp simd
        for (Index i = first; i < last; ++i) {
            const double torque = wholeTorque(a, i);
            const double invM = a.invMass[i];
            a.vx[i] += h * (a.fx[i] * invM + gx);
            a.vy[i] += h * (a.fy[i] * invM + gy);
            a.omega[i] += h * torque * a.invInertia[i];
        }
    } else {
#pragma omp simd
        for (Index i = first; i < last; ++i) wholeTorque(a, i);
    }
}

/// The loops of a level, the 2D engine's given.
StreamingLoops loopsOf(SimdLevel level, DriftLoop drift, KickLoop kick)
{
    StreamingLoops l{level, drift, kick, slabLoops::drift(level), slabLoops::kick(level),
                     slabLoops::laws(level), nullptr, nullptr, nullptr, nullptr};
    l.slabLinearPairs = l.slab<LinearSpringDashpot>().pairs;
    l.slabLinearWalls = l.slab<LinearSpringDashpot>().walls;
    l.slabHertzPairs = l.slab<HertzMindlin>().pairs;
    l.slabHertzWalls = l.slab<HertzMindlin>().walls;
    return l;
}

const StreamingLoops& baselineLoops()
{
    static const StreamingLoops loops = loopsOf(SimdLevel::baseline,
                                                Compiled<driftBody, DriftLoop>::baseline,
                                                Compiled<kickBody, KickLoop>::baseline);
    return loops;
}

const StreamingLoops& chosenLoops()
{
    const char* variable = std::getenv("DEM_SIMD");
    const std::string wanted = variable ? variable : "";
    if (wanted == "baseline") return baselineLoops();
    if (wanted == "avx2") return streamingLoops(SimdLevel::avx2);
    if (!wanted.empty()) {
        throw Error("environment variable DEM_SIMD = '" + wanted
                    + "' is not one of: baseline, avx2 (or unset: the best this CPU runs)");
    }
    return cpuHasAvx2() ? streamingLoops(SimdLevel::avx2) : baselineLoops();
}

} // namespace

bool cpuHasAvx2()
{
#ifdef DEM_HAVE_AVX2_LOOPS
    return __builtin_cpu_supports("avx2");
#else
    return false;
#endif
}

const StreamingLoops& streamingLoops(SimdLevel level)
{
    if (level == SimdLevel::baseline) return baselineLoops();
#ifdef DEM_HAVE_AVX2_LOOPS
    static const StreamingLoops avx2Loops = loopsOf(SimdLevel::avx2,
                                                    Compiled<driftBody, DriftLoop>::avx2,
                                                    Compiled<kickBody, KickLoop>::avx2);
    if (cpuHasAvx2()) return avx2Loops;
#endif
    throw Error("environment variable DEM_SIMD = avx2: this CPU (or build) has no AVX2; unset "
                "DEM_SIMD or set it to baseline");
}

const StreamingLoops& streamingLoops()
{
    static const StreamingLoops& chosen = chosenLoops();
    return chosen;
}

std::string streamingLoopsInUse()
{
    return streamingLoops().level == SimdLevel::avx2 ? "avx2" : "baseline";
}

} // namespace dem
