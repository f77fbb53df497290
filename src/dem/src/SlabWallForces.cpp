// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The slab's wall forces and the second half-kick: each particle's touching wall contacts
// picked out of its candidates, their forces evaluated (in batches by the vectorised kernel,
// or one by one with rolling resistance) and added in wall order, then the kick. Planes and
// cylinders alike, by SlabSystem::wallSide.

#include "dem/SlabSystem.hpp"

#include "PairGroups.hpp"
#include "StreamingLoops.hpp"
#include "WallGeometry.hpp"

#include <algorithm>
#include <cstddef>

namespace dem {

namespace {

using Index = std::ptrdiff_t;   // OpenMP loop index
using Vec3 = Eigen::Vector3d;

} // namespace

void SlabSystem::addWallForcesAndKick(double historyDt, bool kick, bool fluid)
{
    withContactLaw([&](auto law, auto rolling) {
        addWallForcesAndKickWith<decltype(law), decltype(rolling)::value>(historyDt, kick, fluid);
    });
}

template <class Law>
void SlabSystem::batchedWallForces(const WallPick* picked, int m, double historyDt,
                                   std::size_t& touching, double& maxOverlap)
{
    const SlabPairLoop kernel = streamingLoops().slab<Law>().walls;
    SlabParticles& p = p_;
    Vec3* wXi = wallContacts_.xi.data();
    SlabPairBatch b;
    for (int first = 0; first < m; first += SlabPairBatch::capacity) {
        const int count = std::min(m - first, SlabPairBatch::capacity);
        for (int q = 0; q < count; ++q) {
            const auto [s, i] = picked[first + q];
            const double ri = p.radius[i];
            const WallSide side = wallSide(wallContacts_.wall[s], p.position(i));
            // As contactForce's caller: nHat = -side.nHat, v_i + (r_i w_i) x nHat
            b.overlap[q] = ri - side.distance;
            b.nx[q] = -side.nHat.x();
            b.ny[q] = -side.nHat.y();
            b.nz[q] = -side.nHat.z();
            b.dvx[q] = p.vx[i];
            b.dvy[q] = p.vy[i];
            b.dvz[q] = p.vz[i];
            b.sx[q] = ri * p.wx[i];
            b.sy[q] = ri * p.wy[i];
            b.sz[q] = ri * p.wz[i];
            b.xix[q] = wXi[s].x();
            b.xiy[q] = wXi[s].y();
            b.xiz[q] = wXi[s].z();
            b.setLaw<Law>(q, wallLaws_[p.classIndex[i]]);
        }
        kernel(b, count, historyDt);
        for (int q = 0; q < count; ++q) {
            const auto [s, i] = picked[first + q];
            const double ri = p.radius[i];
            p.fx[i] += b.fx[q]; p.fy[i] += b.fy[q]; p.fz[i] += b.fz[q];
            p.tx[i] += ri * b.nxFx[q]; p.ty[i] += ri * b.nxFy[q]; p.tz[i] += ri * b.nxFz[q];
            wXi[s] = Vec3(b.xix[q], b.xiy[q], b.xiz[q]);
            maxOverlap = std::max(maxOverlap, b.overlap[q]);
        }
        touching += static_cast<std::size_t>(count);
    }
}

template <class Law, bool Rolling>
void SlabSystem::addWallForcesAndKickWith(double historyDt, bool kick, bool fluid)
{
    const Index n = static_cast<Index>(p_.size());
    const double h = 0.5 * settings_.dt;
    const double weight = meanWeight_;
    const int* wStart = wallContacts_.start.data();
    const int* wWall = wallContacts_.wall.data();
    Vec3* wXi = wallContacts_.xi.data();
    const ContactLaw* wallLaws = wallLaws_.data();
    SlabParticles& p = p_;

    wallPicks_.resize(wallContacts_.size());

    // The second half-kick (StreamingLoops.hpp) after the wall contacts
    const SlabKickArrays kickArrays{
        wStart,
        p.fx.data(), p.fy.data(), p.fz.data(), p.radius.data(), p.invMass.data(),
        p.invInertia.data(), p.dragCoefficient.data(),
        p.gasVx.data(), p.gasVy.data(), p.gasVz.data(),
        p.extraFx.data(), p.extraFy.data(), p.extraFz.data(),
        p.tx.data(), p.ty.data(), p.tz.data(),
        p.vx.data(), p.vy.data(), p.vz.data(),
        p.wx.data(), p.wy.data(), p.wz.data(),
        p.fluidX.data(), p.fluidY.data(), p.fluidZ.data(),
        p.meanVx.data(), p.meanVy.data(), p.meanVz.data()};
    const SlabKickLoop kickLoop = streamingLoops().slabSecondHalfKick;
    const KickMode mode = kickMode(kick, fluid);
    const double gx = settings_.gravity[0];
    const double gy = settings_.gravity[1];

    std::size_t touching = 0;
    double maxOverlap = maxOverlap_;
#pragma omp parallel num_threads(threads_) reduction(+ : touching) \
    reduction(max : maxOverlap)
    {
        // As System's: each thread its own range of particles for every loop (no barrier
        // between them), the wall contacts first, then every particle's kick, vectorised.
        const auto [first, last] = threadShare(n);
        // Two passes, as the pair loop's: the touching wall contacts picked out without a
        // jump (every sphere of a thin slab has the front and back walls as candidates, and
        // a jump on touching mispredicted), each particle's torque made whole (r ft + the
        // wall torques); then the touching contacts' forces and torques, added in wall order
        WallPick* picked = wallPicks_.data() + wStart[first];
        int m = 0;
        for (Index i = first; i < last; ++i) {
            if (wStart[i] == wStart[i + 1]) continue;
            const double ri = p.radius[i];
            p.tx[i] *= ri;
            p.ty[i] *= ri;
            p.tz[i] *= ri;
            const Vec3 pos = p.position(i);
            for (int s = wStart[i]; s < wStart[i + 1]; ++s) {
                const bool touch = !(ri - wallDistance(wWall[s], pos) <= 0.0);
                picked[m] = {s, static_cast<int>(i)};
                m += touch;
                wXi[s] = selectWithoutBranch(touch, wXi[s], Vec3::Zero());
            }
        }
        if constexpr (Rolling) {
            for (int q = 0; q < m; ++q) {
                const auto [s, i] = picked[q];
                const double ri = p.radius[i];
                const WallSide side = wallSide(wWall[s], p.position(i));
                PairGeometry3 c = wallGeometry(p, i, side.nHat, ri - side.distance);
                c.xiT = wXi[s];
                const PairForce3 f = contactForce<3, Law, true>(c, wallLaws[p.classIndex[i]], historyDt);
                p.fx[i] += f.force.x(); p.fy[i] += f.force.y(); p.fz[i] += f.force.z();
                // The rolling part scaled by the particle's limit (limitRollingTorques)
                const Vec3 torque = f.torqueI + (rollingScale_[i] - 1.0) * f.rollingTorque;
                p.tx[i] += torque.x(); p.ty[i] += torque.y(); p.tz[i] += torque.z();
                wXi[s] = f.xiT;
                ++touching;
                maxOverlap = std::max(maxOverlap, c.overlap);
            }
        } else {
            batchedWallForces<Law>(picked, m, historyDt, touching, maxOverlap);
        }
        kickLoop(kickArrays, first, last, h, gx, gy, weight, mode);
    }
    contactCount_ += touching;
    maxOverlap_ = maxOverlap;
}

} // namespace dem
