// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The slab's contact kernel over a batch of touching pairs or wall contacts
// (StreamingLoops.hpp): contactForce<3, Law> without rolling resistance, written per
// component in its operations and their order, on packs of two contacts (the baseline's
// SSE2) or four (AVX2), picked as the streaming loops (one at a time without SSE2). The law's
// force is its policy's own response on the packs; every law of ContactLaws gets its loops.

// The four-double packs pass only between functions inlined into the AVX2 one (the laws'
// responses among them, hence before the includes): no call crosses the ABI GCC warns of
#pragma GCC diagnostic ignored "-Wpsabi"

#include "StreamingLoops.hpp"

#include <array>
#include <cmath>
#include <initializer_list>
#if defined(__SSE2__) || defined(DEM_HAVE_AVX2_LOOPS)
#include <immintrin.h>
#endif

namespace dem {

namespace {

enum class Partner { sphere, wall };   // a wall's nHat and overlap come given

// Packs of doubles, one contact a lane: two (SSE2) or four (AVX2), a plain double on other
// CPUs; the IEEE operations of a lane are the scalar ones (no fused multiply-add in any).
#if defined(__SSE2__)
typedef double BaselinePack __attribute__((vector_size(16), may_alias));
[[gnu::always_inline]] inline BaselinePack squareRoot(BaselinePack x) { return _mm_sqrt_pd(x); }
#else
using BaselinePack = double;
[[gnu::always_inline]] inline double squareRoot(double x) { return std::sqrt(x); }
#endif
#ifdef DEM_HAVE_AVX2_LOOPS
typedef double Pack4 __attribute__((vector_size(32), may_alias));
// Not always_inline: inlined where pairBody is, into the AVX2 function
[[gnu::target("avx2")]] inline Pack4 squareRoot(Pack4 x)
{
    return _mm256_sqrt_pd(x);
}
#endif

// The square root a law's response takes on packs
struct PackRoot {
    template <class Pack> [[gnu::always_inline]] Pack operator()(const Pack& x) const
    {
        return squareRoot(x);
    }
};

// The pack at p (aligned: the batch's arrays and q a multiple of the width), by reference
template <class Pack> [[gnu::always_inline]] inline const Pack& load(const double* p)
{
    return *reinterpret_cast<const Pack*>(p);
}
template <class Pack> [[gnu::always_inline]] inline Pack& at(double* p)
{
    return *reinterpret_cast<Pack*>(p);
}

// Both sides of the kernel's two branches are computed and selected; the side not taken
// gets operands that raise no floating-point exception (the solver traps them).
template <class Law, Partner partner, class Pack>
[[gnu::always_inline]] inline void pairBody(SlabPairBatch& b, int count, double dt)
{
    constexpr int width = sizeof(Pack) / sizeof(double);
    // Lanes past count repeat the last contact: valid operands, results unread
    for (int q = count; q % width != 0; ++q) {
        auto repeat = [&](std::initializer_list<double*> inputs) {
            for (double* in : inputs) in[q] = in[count - 1];
        };
        if constexpr (partner == Partner::sphere) repeat({b.dx, b.dy, b.dz, b.rSum});
        else repeat({b.nx, b.ny, b.nz, b.overlap});
        repeat({b.dvx, b.dvy, b.dvz, b.sx, b.sy, b.sz, b.xix, b.xiy, b.xiz, b.normal,
                b.normalDamping, b.tangential, b.tangentialDamping, b.mu});
    }
    const Pack zero = {}, one = zero + 1.0;
    for (int q = 0; q < count; q += width) {
        Pack overlap, nx, ny, nz;
        if constexpr (partner == Partner::sphere) {
            const Pack dx = load<Pack>(b.dx + q), dy = load<Pack>(b.dy + q),
                       dz = load<Pack>(b.dz + q);
            const Pack dist = squareRoot(dx * dx + dy * dy + dz * dz);
            overlap = load<Pack>(b.rSum + q) - dist;
            nx = dx / dist;
            ny = dy / dist;
            nz = dz / dist;
        } else {
            overlap = load<Pack>(b.overlap + q);
            nx = load<Pack>(b.nx + q);
            ny = load<Pack>(b.ny + q);
            nz = load<Pack>(b.nz + q);
        }
        // v_i - v_j + (r_i w_i + r_j w_j) x nHat
        const Pack sx = load<Pack>(b.sx + q), sy = load<Pack>(b.sy + q), sz = load<Pack>(b.sz + q);
        const Pack vx = load<Pack>(b.dvx + q) + (sy * nz - sz * ny);
        const Pack vy = load<Pack>(b.dvy + q) + (sz * nx - sx * nz);
        const Pack vz = load<Pack>(b.dvz + q) + (sx * ny - sy * nx);
        const Pack vn = vx * nx + vy * ny + vz * nz;
        // The law's force and its clamp (stiffnessOf)
        const LawConstants<Pack> constants{load<Pack>(b.normal + q),
                                           load<Pack>(b.normalDamping + q),
                                           load<Pack>(b.tangential + q),
                                           load<Pack>(b.tangentialDamping + q)};
        const LawResponse<Pack> response = Law::response(overlap, vn, constants, PackRoot{});
        // std::max(response.normal, 0.0), NaN kept
        const Pack fn = response.normal < zero ? zero : response.normal;
        const Pack kt = response.kt, etaT = response.etaT;
        const Pack limit = load<Pack>(b.mu + q) * fn;
        const Pack vtx = vx - vn * nx, vty = vy - vn * ny, vtz = vz - vn * nz;
        // The stored displacement turned into the tangent plane, its length kept
        const Pack x0 = load<Pack>(b.xix + q), y0 = load<Pack>(b.xiy + q), z0 = load<Pack>(b.xiz + q);
        const Pack along = x0 * nx + y0 * ny + z0 * nz;
        Pack xix = x0 - along * nx, xiy = y0 - along * ny, xiz = z0 - along * nz;
        const Pack before2 = x0 * x0 + y0 * y0 + z0 * z0;
        const Pack after2 = xix * xix + xiy * xiy + xiz * xiz;
        const auto turns = (after2 > zero) & (after2 != before2);
        const Pack turn = squareRoot((turns ? before2 : one) / (turns ? after2 : one));
        xix = turns ? xix * turn : xix;
        xiy = turns ? xiy * turn : xiy;
        xiz = turns ? xiz * turn : xiz;
        xix += vtx * dt;
        xiy += vty * dt;
        xiz += vtz * dt;
        Pack ftx = -kt * xix - etaT * vtx;
        Pack fty = -kt * xiy - etaT * vty;
        Pack ftz = -kt * xiz - etaT * vtz;
        // Coulomb's limit
        const Pack ft2 = ftx * ftx + fty * fty + ftz * ftz;
        const auto slides = ft2 > limit * limit;
        const Pack cap = (slides ? limit : one) / squareRoot(slides ? ft2 : one);
        ftx = slides ? ftx * cap : ftx;
        fty = slides ? fty * cap : fty;
        ftz = slides ? ftz * cap : ftz;
        // Spring and dashpot give the capped force; a spring that would point against it is relaxed
        const Pack ktSliding = slides ? kt : one;
        const Pack springX = ftx + etaT * vtx, springY = fty + etaT * vty, springZ = ftz + etaT * vtz;
        const auto springAlong = springX * ftx + springY * fty + springZ * ftz > zero;
        at<Pack>(b.xix + q) = slides ? (springAlong ? -springX : zero) / ktSliding : xix;
        at<Pack>(b.xiy + q) = slides ? (springAlong ? -springY : zero) / ktSliding : xiy;
        at<Pack>(b.xiz + q) = slides ? (springAlong ? -springZ : zero) / ktSliding : xiz;
        at<Pack>(b.fx + q) = -fn * nx + ftx;
        at<Pack>(b.fy + q) = -fn * ny + fty;
        at<Pack>(b.fz + q) = -fn * nz + ftz;
        at<Pack>(b.nxFx + q) = ny * ftz - nz * fty;
        at<Pack>(b.nxFy + q) = nz * ftx - nx * ftz;
        at<Pack>(b.nxFz + q) = nx * fty - ny * ftx;
        at<Pack>(b.overlap + q) = overlap;
    }
}

template <class Law, Partner partner> void baselinePairs(SlabPairBatch& b, int count, double dt)
{
    pairBody<Law, partner, BaselinePack>(b, count, dt);
}

#ifdef DEM_HAVE_AVX2_LOOPS
template <class Law, Partner partner>
__attribute__((target("avx2"))) void avx2Pairs(SlabPairBatch& b, int count, double dt)
{
    pairBody<Law, partner, Pack4>(b, count, dt);
}
#endif

template <class Law, Partner partner>
SlabPairLoop pairs(SimdLevel level)
{
#ifdef DEM_HAVE_AVX2_LOOPS
    if (level == SimdLevel::avx2) return avx2Pairs<Law, partner>;
#endif
    return baselinePairs<Law, partner>;
}

template <class... Laws>
std::array<SlabLawLoops, sizeof...(Laws)> lawLoops(SimdLevel level, LawList<Laws...>)
{
    return {{{pairs<Laws, Partner::sphere>(level), pairs<Laws, Partner::wall>(level)}...}};
}

} // namespace

namespace slabLoops {

std::array<SlabLawLoops, ContactLaws::size> laws(SimdLevel level)
{
    return lawLoops(level, ContactLaws{});
}

} // namespace slabLoops

} // namespace dem
