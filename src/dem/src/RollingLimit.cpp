// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The limit on each particle's rolling torques (RollingLimit.hpp), for both engines: after
// the pair forces, each particle's share D_i from its pair contacts (summed by the pair loop)
// and its wall contacts (here), its scale s_i, then the pairs' rolling torques scaled by
// min(s_i, s_j) and added in list order; the wall loop scales the walls' by s_i.

#include "dem/SlabSystem.hpp"
#include "dem/System.hpp"

#include "PairGroups.hpp"
#include "RollingLimit.hpp"
#include "WallGeometry.hpp"

#include <cmath>
#include <cstddef>

namespace dem {

namespace {

using Index = std::ptrdiff_t;   // OpenMP loop index
using Vec3 = Eigen::Vector3d;

} // namespace

void System::limitRollingTorques()
{
    const Index n = static_cast<Index>(p_.size());
    const int* wStart = wallContacts_.start.data();
    double* share = rollingScale_.data();
    const double dt = settings_.dt;
    withLaw(settings_.contact.law, [&](auto policy) {
        using Law = decltype(policy);
#pragma omp parallel num_threads(threads_)
        {
            const auto [first, last] = threadShare(n);
            for (Index i = first; i < last; ++i) {
                const Eigen::Vector2d pos(p_.x[i], p_.y[i]);
                for (int s = wStart[i]; s < wStart[i + 1]; ++s) {
                    const PlaneWall& w = walls_[wallContacts_.wall[s]];
                    const double overlap = p_.radius[i] - w.distance(pos);
                    if (overlap <= 0.0) continue;
                    const ContactLaw& law = wallLaws_[p_.classIndex[i]];
                    const PairGeometry g = wallGeometry(p_, i, w, overlap);
                    const double fn = stiffnessOf<Law>(overlap, g.vRel.dot(g.nHat), law).fn;
                    share[i] += rollingResistance(g, fn, law).coefficient * dt * p_.invInertia[i];
                }
            }
            rollingScales(share, static_cast<std::size_t>(first), static_cast<std::size_t>(last));
        }
    });
    // The pairs' torques over the radius the torque sums are multiplied by, in list order
    const int* pi = pairs_.i.data();
    const int* pj = pairs_.j.data();
    const int* groupStart = pairs_.groupStart.data();
    const int* touchingPairs = touchingScratch_.data();
    const double* pairRolling = pairRolling_.data();
    const double* r = p_.radius.data();
    double* sumFt = p_.torque.data();
    auto group = [&](int g, std::size_t&, double&) {
        const int* picked = touchingPairs + groupStart[g];
        for (int q = 0; q < touchingPerGroup_[g]; ++q) {
            const int k = picked[q];
            const int i = pi[k];
            const int j = pj[k];
            const double torque = rollingScale(share, i, j) * pairRolling[k];
            sumFt[i] += torque / r[i];
            sumFt[j] -= torque / r[j];
        }
    };
    std::size_t unusedCount = 0;
    double unusedOverlap = 0.0;
    sumPairGroups(threads_, p_.size(), [](std::size_t, std::size_t) {}, group,
                  unusedCount, unusedOverlap);
}

void SlabSystem::limitRollingTorques()
{
    const Index n = static_cast<Index>(p_.size());
    const int* wStart = wallContacts_.start.data();
    double* share = rollingScale_.data();
    const double dt = settings_.dt;
    SlabParticles& p = p_;
    withLaw(settings_.contact.law, [&](auto policy) {
        using Law = decltype(policy);
#pragma omp parallel num_threads(threads_)
        {
            const auto [first, last] = threadShare(n);
            for (Index i = first; i < last; ++i) {
                for (int s = wStart[i]; s < wStart[i + 1]; ++s) {
                    // Touching first: a candidate's normal may be undefined (a sphere on a
                    // cylinder's axis, 0/0), a touching sphere's is not
                    const Vec3 position = p.position(i);
                    if (p.radius[i] - wallDistance(wallContacts_.wall[s], position) <= 0.0) continue;
                    const WallSide side = wallSide(wallContacts_.wall[s], position);
                    const double overlap = p.radius[i] - side.distance;
                    const ContactLaw& law = wallLaws_[p.classIndex[i]];
                    const PairGeometry3 c = wallGeometry(p, i, side.nHat, overlap);
                    const double fn = stiffnessOf<Law>(overlap, c.vRel.dot(c.nHat), law).fn;
                    share[i] += rollingResistance(c, fn, law).coefficient * dt * p.invInertia[i];
                }
            }
            rollingScales(share, static_cast<std::size_t>(first), static_cast<std::size_t>(last));
        }
    });
    // The pairs' torques over the radius the torque sums are multiplied by, in list order
    const int* pi = pairs_.i.data();
    const int* pj = pairs_.j.data();
    const int* groupStart = pairs_.groupStart.data();
    const int* touchingPairs = touchingScratch_.data();
    const double* radius = p.radius.data();
    double* tx = p.tx.data();
    double* ty = p.ty.data();
    double* tz = p.tz.data();
    auto group = [&](int g, std::size_t&, double&) {
        const int* picked = touchingPairs + groupStart[g];
        for (int q = 0; q < touchingPerGroup_[g]; ++q) {
            const int k = picked[q];
            const int i = pi[k];
            const int j = pj[k];
            const Vec3 torque = rollingScale(share, i, j) * pairRolling_[k];
            const Vec3 ti = torque / radius[i];
            const Vec3 tj = torque / radius[j];
            tx[i] += ti.x(); ty[i] += ti.y(); tz[i] += ti.z();
            tx[j] -= tj.x(); ty[j] -= tj.y(); tz[j] -= tj.z();
        }
    };
    std::size_t unusedCount = 0;
    double unusedOverlap = 0.0;
    sumPairGroups(threads_, p.size(), [](std::size_t, std::size_t) {}, group,
                  unusedCount, unusedOverlap);
}

} // namespace dem
