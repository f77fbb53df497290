// The streaming loops of StreamingLoops.hpp: one body each, inlined into a baseline and an
// AVX2 function, and the choice between them.

#include "StreamingLoops.hpp"

#include "dem/Error.hpp"
#include "dem/Facade.hpp"

#include <algorithm>
#include <cstdlib>
#include <string>

#if defined(__x86_64__) && defined(__GNUC__)
#define DEM_HAVE_AVX2_LOOPS 1
#endif

namespace dem {

namespace {

using Index = std::ptrdiff_t;

[[gnu::always_inline]] inline void driftBody(const DriftArrays& a, const DriftStep& c,
                                             Index first, Index last, double& maxDisplacement2,
                                             double& lost)
{
    const double dt = c.dt, h = c.h, gx = c.gx, gy = c.gy;
    const double xMin = c.box.xMin, xMax = c.box.xMax, yMin = c.box.yMin, yMax = c.box.yMax;
    const double* invMass = a.invMass;
    const double* invInertia = a.invInertia;
    const double* fx = a.fx;
    const double* fy = a.fy;
    const double* fluidX = a.fluidX;
    const double* fluidY = a.fluidY;
    const double* torque = a.torque;
    const double* xRef = a.xRef;
    const double* yRef = a.yRef;
    double* vx = a.vx;
    double* vy = a.vy;
    double* omega = a.omega;
    double* x = a.x;
    double* y = a.y;
    double maxD2 = maxDisplacement2;
    // Counted in a double from selects: GCC vectorises that, and not an integer flag
    double outside = lost;
#pragma omp simd reduction(max : maxD2) reduction(+ : outside)
    for (Index i = first; i < last; ++i) {
        const double invM = invMass[i];
        const double vxNew = vx[i] + h * ((fx[i] + fluidX[i]) * invM + gx);
        const double vyNew = vy[i] + h * ((fy[i] + fluidY[i]) * invM + gy);
        vx[i] = vxNew;
        vy[i] = vyNew;
        omega[i] += h * torque[i] * invInertia[i];
        const double xNew = x[i] + dt * vxNew;
        const double yNew = y[i] + dt * vyNew;
        x[i] = xNew;
        y[i] = yNew;
        const double dx = xNew - xRef[i];
        const double dy = yNew - yRef[i];
        maxD2 = std::max(maxD2, dx * dx + dy * dy);
        const double outX = xNew >= xMin && xNew <= xMax ? 0.0 : 1.0;
        const double outY = yNew >= yMin && yNew <= yMax ? 0.0 : 1.0;
        outside += outX + outY;
    }
    maxDisplacement2 = maxD2;
    lost = outside;
}

[[gnu::always_inline]] inline void kickBody(const KickArrays& a, Index first, Index last,
                                            double h, double gx, double gy, double weight,
                                            bool fluid)
{
    const int* wStart = a.wallStart;
    const double* fx = a.fx;
    const double* fy = a.fy;
    const double* radius = a.radius;
    const double* invMass = a.invMass;
    const double* invInertia = a.invInertia;
    const double* dragK = a.dragK;
    const double* gasVx = a.gasVx;
    const double* gasVy = a.gasVy;
    const double* extraFx = a.extraFx;
    const double* extraFy = a.extraFy;
    double* torqueA = a.torque;
    double* vx = a.vx;
    double* vy = a.vy;
    double* omega = a.omega;
    double* fluidX = a.fluidX;
    double* fluidY = a.fluidY;
    double* meanVx = a.meanVx;
    double* meanVy = a.meanVy;
    if (fluid) {
#pragma omp simd
        for (Index i = first; i < last; ++i) {
            // Particles with walls have their whole torque already: a factor of 1 keeps it
            // exactly, and a select of loaded values vectorises
            const double torque = (wStart[i] == wStart[i + 1] ? radius[i] : 1.0) * torqueA[i];
            torqueA[i] = torque;
            const double invM = invMass[i];
            // Second half-kick with the drag implicit: v = v_half + h (F + K (u - v) + extra)/m.
            const double K = dragK[i];
            const double denominator = 1.0 + h * K * invM;
            const double vxNew = (vx[i] + h * ((fx[i] + K * gasVx[i] + extraFx[i]) * invM + gx))
                                 / denominator;
            const double vyNew = (vy[i] + h * ((fy[i] + K * gasVy[i] + extraFy[i]) * invM + gy))
                                 / denominator;
            vx[i] = vxNew;
            vy[i] = vyNew;
            fluidX[i] = K * (gasVx[i] - vxNew) + extraFx[i];
            fluidY[i] = K * (gasVy[i] - vyNew) + extraFy[i];
            meanVx[i] += weight * vxNew;
            meanVy[i] += weight * vyNew;
            omega[i] += h * torque * invInertia[i];
        }
    } else {
#pragma omp simd
        for (Index i = first; i < last; ++i) {
            const double torque = (wStart[i] == wStart[i + 1] ? radius[i] : 1.0) * torqueA[i];
            torqueA[i] = torque;
            const double invM = invMass[i];
            vx[i] += h * (fx[i] * invM + gx);
            vy[i] += h * (fy[i] * invM + gy);
            omega[i] += h * torque * invInertia[i];
        }
    }
}


void driftBaseline(const DriftArrays& a, const DriftStep& c, Index first, Index last,
                   double& maxDisplacement2, double& lost)
{
    driftBody(a, c, first, last, maxDisplacement2, lost);
}

void kickBaseline(const KickArrays& a, Index first, Index last, double h, double gx, double gy,
                  double weight, bool fluid)
{
    kickBody(a, first, last, h, gx, gy, weight, fluid);
}

#ifdef DEM_HAVE_AVX2_LOOPS
__attribute__((target("avx2"))) void driftAvx2(const DriftArrays& a, const DriftStep& c,
                                               Index first, Index last,
                                               double& maxDisplacement2, double& lost)
{
    driftBody(a, c, first, last, maxDisplacement2, lost);
}

__attribute__((target("avx2"))) void kickAvx2(const KickArrays& a, Index first, Index last,
                                              double h, double gx, double gy, double weight,
                                              bool fluid)
{
    kickBody(a, first, last, h, gx, gy, weight, fluid);
}
#endif

const StreamingLoops baselineLoops{SimdLevel::baseline, driftBaseline, kickBaseline};

const StreamingLoops& chosenLoops()
{
    const char* variable = std::getenv("DEM_SIMD");
    const std::string wanted = variable ? variable : "";
    if (wanted == "baseline") return baselineLoops;
    if (wanted == "avx2") return streamingLoops(SimdLevel::avx2);
    if (!wanted.empty()) {
        throw Error("environment variable DEM_SIMD = '" + wanted
                    + "' is not one of: baseline, avx2 (or unset: the best this CPU runs)");
    }
    return cpuHasAvx2() ? streamingLoops(SimdLevel::avx2) : baselineLoops;
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
    if (level == SimdLevel::baseline) return baselineLoops;
#ifdef DEM_HAVE_AVX2_LOOPS
    static const StreamingLoops avx2Loops{SimdLevel::avx2, driftAvx2, kickAvx2};
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
