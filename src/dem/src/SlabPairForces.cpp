// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The slab's pair forces: each group's touching pairs picked out of the neighbour list, their
// forces evaluated (in batches by the vectorised kernel, or one by one with rolling
// resistance) and added to both partners in list order.

#include "dem/SlabSystem.hpp"

#include "PairGroups.hpp"
#include "StreamingLoops.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace dem {

namespace {

using Index = std::ptrdiff_t;
using Vec3 = Eigen::Vector3d;

/// Plain pointers to the slab's per-particle arrays that the pair loop reads and sums into,
/// taken once before it: the loop reads them without re-loading through the vectors.
struct Arrays {
    double *x, *y, *z, *vx, *vy, *vz, *wx, *wy, *wz, *fx, *fy, *fz, *tx, *ty, *tz, *radius;

    explicit Arrays(SlabParticles& p)
        : x(p.x.data()), y(p.y.data()), z(p.z.data()), vx(p.vx.data()), vy(p.vy.data()),
          vz(p.vz.data()), wx(p.wx.data()), wy(p.wy.data()), wz(p.wz.data()),
          fx(p.fx.data()), fy(p.fy.data()), fz(p.fz.data()), tx(p.tx.data()),
          ty(p.ty.data()), tz(p.tz.data()), radius(p.radius.data())
    {
    }
};

} // namespace

void SlabSystem::computePairForces(double historyDt)
{
    withContactLaw([&](auto law, auto rolling) {
        sumPairForces<decltype(law), decltype(rolling)::value>(historyDt);
    });
}

template <class Law, bool Rolling>
void SlabSystem::sumPairForces(double historyDt)
{
    SlabParticles& p = p_;
    const std::size_t n = p.size();
    const int* pi = pairs_.i.data();
    const int* pj = pairs_.j.data();
    const int* law = pairs_.law.data();
    const int* groupStart = pairs_.groupStart.data();
    Vec3* xiT = pairs_.xi.data();
    const ContactLaw* laws = pairLaws_.data();
    const SlabPairLoop kernel = streamingLoops().slab<Law>().pairs;
    // Sums over each particle's pairs in a.f* and a.t*; the t* hold the sum of nHat x Ft
    // until addWallForcesAndKick multiplies it by the radius (the torque on either partner
    // is r nHat x Ft, see contactForce).
    const Arrays a(p);

    // A touching pair with rolling resistance, by contactForce
    auto rollingPairForce = [&](Index k, std::size_t& touching, double& maxOverlap) {
        const int i = pi[k];
        const int j = pj[k];
        const Vec3 d(a.x[j] - a.x[i], a.y[j] - a.y[i], a.z[j] - a.z[i]);
        const double dist = std::sqrt(d.x() * d.x() + d.y() * d.y() + d.z() * d.z());
        PairGeometry3 g;
        g.overlap = a.radius[i] + a.radius[j] - dist;
        g.nHat = d / dist;
        g.rI = a.radius[i];
        g.rJ = a.radius[j];
        // Contact points: v_i + w_i x (r_i n) and v_j + w_j x (-r_j n).
        const Vec3 wI(a.wx[i], a.wy[i], a.wz[i]);
        const Vec3 wJ(a.wx[j], a.wy[j], a.wz[j]);
        g.vRel = Vec3(a.vx[i] - a.vx[j], a.vy[i] - a.vy[j], a.vz[i] - a.vz[j])
                 + (g.rI * wI + g.rJ * wJ).cross(g.nHat);
        g.xiT = xiT[k];
        g.omegaRel = wI - wJ;
        const PairForce3 f = contactForce<3, Law, true>(g, laws[law[k]], historyDt);
        xiT[k] = f.xiT;
        const Vec3 nxF = g.nHat.cross(f.ft);
        a.fx[i] += f.force.x(); a.fy[i] += f.force.y(); a.fz[i] += f.force.z();
        a.fx[j] -= f.force.x(); a.fy[j] -= f.force.y(); a.fz[j] -= f.force.z();
        a.tx[i] += nxF.x(); a.ty[i] += nxF.y(); a.tz[i] += nxF.z();
        a.tx[j] += nxF.x(); a.ty[j] += nxF.y(); a.tz[j] += nxF.z();
        // Added by limitRollingTorques, scaled, once every contact's share is known
        pairRolling_[k] = f.rollingTorque;
        rollingScale_[i] += f.rollingCoefficient * settings_.dt * p.invInertia[i];
        rollingScale_[j] += f.rollingCoefficient * settings_.dt * p.invInertia[j];
        ++touching;
        maxOverlap = std::max(maxOverlap, g.overlap);
    };

    // The touching pairs picked[0, m) without rolling resistance, a batch at a time: the
    // kernel's inputs gathered, evaluated together, the results added in list order.
    auto batchedPairForces = [&](const int* picked, int m, std::size_t& touching,
                                 double& maxOverlap) {
        SlabPairBatch b;
        for (int first = 0; first < m; first += SlabPairBatch::capacity) {
            const int count = std::min(m - first, SlabPairBatch::capacity);
            for (int q = 0; q < count; ++q) {
                const int k = picked[first + q];
                const int i = pi[k];
                const int j = pj[k];
                const double rI = a.radius[i];
                const double rJ = a.radius[j];
                b.dx[q] = a.x[j] - a.x[i];
                b.dy[q] = a.y[j] - a.y[i];
                b.dz[q] = a.z[j] - a.z[i];
                b.rSum[q] = rI + rJ;
                b.dvx[q] = a.vx[i] - a.vx[j];
                b.dvy[q] = a.vy[i] - a.vy[j];
                b.dvz[q] = a.vz[i] - a.vz[j];
                b.sx[q] = rI * a.wx[i] + rJ * a.wx[j];
                b.sy[q] = rI * a.wy[i] + rJ * a.wy[j];
                b.sz[q] = rI * a.wz[i] + rJ * a.wz[j];
                b.xix[q] = xiT[k].x();
                b.xiy[q] = xiT[k].y();
                b.xiz[q] = xiT[k].z();
                b.setLaw<Law>(q, laws[law[k]]);
            }
            kernel(b, count, historyDt);
            for (int q = 0; q < count; ++q) {
                const int k = picked[first + q];
                const int i = pi[k];
                const int j = pj[k];
                xiT[k] = Vec3(b.xix[q], b.xiy[q], b.xiz[q]);
                a.fx[i] += b.fx[q]; a.fy[i] += b.fy[q]; a.fz[i] += b.fz[q];
                a.fx[j] -= b.fx[q]; a.fy[j] -= b.fy[q]; a.fz[j] -= b.fz[q];
                a.tx[i] += b.nxFx[q]; a.ty[i] += b.nxFy[q]; a.tz[i] += b.nxFz[q];
                a.tx[j] += b.nxFx[q]; a.ty[j] += b.nxFy[q]; a.tz[j] += b.nxFz[q];
                maxOverlap = std::max(maxOverlap, b.overlap[q]);
            }
            touching += static_cast<std::size_t>(count);
        }
    };

    // The groups as sumPairGroups runs them, in two passes as System's: the touching pairs
    // picked out without a branch, then their forces in list order.
    touchingScratch_.resize(pairs_.size());   // (a loaded state's list has no build here)
    int* touchingPairs = touchingScratch_.data();
    if constexpr (Rolling) {
        pairRolling_.resize(pairs_.size());
        rollingScale_.resize(n);
        touchingPerGroup_.resize(nPairGroups);
    }
    auto group = [&](int gr, std::size_t& touching, double& maxOverlap) {
        int* picked = touchingPairs + groupStart[gr];
        int m = 0;
        const int end = groupStart[gr + 1];   // read once: the picks are ints too
        for (int k = groupStart[gr]; k < end; ++k) {
            const int i = pi[k];
            const int j = pj[k];
            const double dx = a.x[j] - a.x[i];
            const double dy = a.y[j] - a.y[i];
            const double dz = a.z[j] - a.z[i];
            const double rSum = a.radius[i] + a.radius[j];
            const bool touch = !(dx * dx + dy * dy + dz * dz >= rSum * rSum);   // NaN: touching
            picked[m] = k;
            m += touch;
            double* xi = xiT[k].data();   // separated: the contact's history ends
            xi[0] = selectWithoutBranch(touch, xi[0], 0.0);
            xi[1] = selectWithoutBranch(touch, xi[1], 0.0);
            xi[2] = selectWithoutBranch(touch, xi[2], 0.0);
        }
        if constexpr (Rolling) {
            for (int q = 0; q < m; ++q) rollingPairForce(picked[q], touching, maxOverlap);
            touchingPerGroup_[gr] = m;
        } else {
            batchedPairForces(picked, m, touching, maxOverlap);
        }
    };
    auto zeroBlock = [&](std::size_t first, std::size_t last) {
        for (double* sum : {a.fx, a.fy, a.fz, a.tx, a.ty, a.tz}) {
            std::fill(sum + first, sum + last, 0.0);
        }
        if constexpr (Rolling) std::fill(rollingScale_.begin() + first, rollingScale_.begin() + last, 0.0);
    };
    sumPairGroups(threads_, n, zeroBlock, group, contactCount_, maxOverlap_);
    if constexpr (Rolling) limitRollingTorques();
}

} // namespace dem
