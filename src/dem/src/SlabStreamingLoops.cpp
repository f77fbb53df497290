// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The slab's streaming loops of StreamingLoops.hpp: one body each, compiled for the baseline
// and for AVX2 (Compiled), as the 2D ones (StreamingLoops.cpp).

#include "StreamingLoops.hpp"

#include <algorithm>

namespace dem {

namespace {

using Index = std::ptrdiff_t;

// The arrays by value: the loops see plain local pointers
[[gnu::always_inline]] inline void driftBody(const SlabDriftArrays a, const SlabDriftStep& c,
                                             Index first, Index last, double& maxDisplacement2,
                                             double& lost)
{
    const double dt = c.dt, h = c.h, gx = c.gx, gy = c.gy, depth = c.depth;
    const double xMin = c.box.xMin, xMax = c.box.xMax, yMin = c.box.yMin, yMax = c.box.yMax;
    double maxD2 = maxDisplacement2;
    // Counted in a double from selects: GCC vectorises that, and not an integer flag
    double outside = lost;
#pragma omp simd reduction(max : maxD2) reduction(+ : outside)
    for (Index i = first; i < last; ++i) {
        const double invM = a.invMass[i];
        const double hI = h * a.invInertia[i];
        const double vxNew = a.vx[i] + h * ((a.fx[i] + a.fluidX[i]) * invM + gx);
        const double vyNew = a.vy[i] + h * ((a.fy[i] + a.fluidY[i]) * invM + gy);
        const double vzNew = a.vz[i] + h * ((a.fz[i] + a.fluidZ[i]) * invM);
        a.vx[i] = vxNew;
        a.vy[i] = vyNew;
        a.vz[i] = vzNew;
        a.wx[i] += hI * a.tx[i];
        a.wy[i] += hI * a.ty[i];
        a.wz[i] += hI * a.tz[i];
        const double xNew = a.x[i] + dt * vxNew;
        const double yNew = a.y[i] + dt * vyNew;
        const double zNew = a.z[i] + dt * vzNew;
        a.x[i] = xNew;
        a.y[i] = yNew;
        a.z[i] = zNew;
        const double dx = xNew - a.xRef[i];
        const double dy = yNew - a.yRef[i];
        const double dz = zNew - a.zRef[i];
        maxD2 = std::max(maxD2, dx * dx + dy * dy + dz * dz);
        const double outX = xNew >= xMin && xNew <= xMax ? 0.0 : 1.0;
        const double outY = yNew >= yMin && yNew <= yMax ? 0.0 : 1.0;
        const double outZ = zNew >= 0.0 && zNew <= depth ? 0.0 : 1.0;
        outside += outX + outY + outZ;
    }
    maxDisplacement2 = maxD2;
    lost = outside;
}

// Sphere i's torque made whole and stored (as wholeTorque of the 2D loops, per component)
[[gnu::always_inline]] inline void wholeTorque(const SlabKickArrays& a, Index i, double& tx,
                                               double& ty, double& tz)
{
    const double scale = a.wallStart[i] == a.wallStart[i + 1] ? a.radius[i] : 1.0;
    tx = scale * a.tx[i];
    ty = scale * a.ty[i];
    tz = scale * a.tz[i];
    a.tx[i] = tx;
    a.ty[i] = ty;
    a.tz[i] = tz;
}

[[gnu::always_inline]] inline void kickBody(const SlabKickArrays a, Index first, Index last,
                                            double h, double gx, double gy, double weight,
                                            KickMode mode)
{
    if (mode == KickMode::fluid) {
#pragma omp simd
        for (Index i = first; i < last; ++i) {
            double tx, ty, tz;
            wholeTorque(a, i, tx, ty, tz);
            const double invM = a.invMass[i];
            // Second half-kick, the drag implicit: v = v_half + h (F + K (u - v) + extra)/m.
            const double K = a.dragK[i];
            const double denominator = 1.0 + h * K * invM;
            const double vxNew =
                (a.vx[i] + h * ((a.fx[i] + K * a.gasVx[i] + a.extraFx[i]) * invM + gx))
                / denominator;
            const double vyNew =
                (a.vy[i] + h * ((a.fy[i] + K * a.gasVy[i] + a.extraFy[i]) * invM + gy))
                / denominator;
            const double vzNew =
                (a.vz[i] + h * ((a.fz[i] + K * a.gasVz[i] + a.extraFz[i]) * invM))
                / denominator;
            a.vx[i] = vxNew;
            a.vy[i] = vyNew;
            a.vz[i] = vzNew;
            a.fluidX[i] = K * (a.gasVx[i] - vxNew) + a.extraFx[i];
            a.fluidY[i] = K * (a.gasVy[i] - vyNew) + a.extraFy[i];
            a.fluidZ[i] = K * (a.gasVz[i] - vzNew) + a.extraFz[i];
            a.meanVx[i] += weight * vxNew;
            a.meanVy[i] += weight * vyNew;
            a.meanVz[i] += weight * vzNew;
            const double hI = h * a.invInertia[i];
            a.wx[i] += hI * tx;
            a.wy[i] += hI * ty;
            a.wz[i] += hI * tz;
        }
    } else if (mode == KickMode::forcesOnly) {
#pragma omp simd
        for (Index i = first; i < last; ++i) {
            double tx, ty, tz;
            wholeTorque(a, i, tx, ty, tz);
            const double invM = a.invMass[i];
            a.vx[i] += h * (a.fx[i] * invM + gx);
            a.vy[i] += h * (a.fy[i] * invM + gy);
            a.vz[i] += h * (a.fz[i] * invM);
            const double hI = h * a.invInertia[i];
            a.wx[i] += hI * tx;
            a.wy[i] += hI * ty;
            a.wz[i] += hI * tz;
        }
    } else {
#pragma omp simd
        for (Index i = first; i < last; ++i) {
            double tx, ty, tz;
            wholeTorque(a, i, tx, ty, tz);
        }
    }
}

} // namespace

namespace slabLoops {

SlabDriftLoop drift(SimdLevel level)
{
#ifdef DEM_HAVE_AVX2_LOOPS
    if (level == SimdLevel::avx2) return Compiled<driftBody, SlabDriftLoop>::avx2;
#endif
    return Compiled<driftBody, SlabDriftLoop>::baseline;
}

SlabKickLoop kick(SimdLevel level)
{
#ifdef DEM_HAVE_AVX2_LOOPS
    if (level == SimdLevel::avx2) return Compiled<kickBody, SlabKickLoop>::avx2;
#endif
    return Compiled<kickBody, SlabKickLoop>::baseline;
}

} // namespace slabLoops

} // namespace dem
