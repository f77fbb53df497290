// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The slab mode's engine: System's step with 3-vectors and the 3D contact kernel (its pair
// forces in SlabPairForces.cpp).

#include "dem/SlabSystem.hpp"
#include "dem/Particles.hpp"
#include "dem/System.hpp"

#include "PairGroups.hpp"
#include "StreamingLoops.hpp"
#include "WallGeometry.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <type_traits>

namespace dem {

namespace {

using Index = std::ptrdiff_t;   // OpenMP loop index
using Vec3 = Eigen::Vector3d;

const Settings& validatedSlab(const Settings& s)
{
    validateSettings(s);
    if (s.dimension != 3) {
        throw Error("dimension = " + std::to_string(s.dimension) + " is outside {3}: the slab "
                    "engine runs spheres in a slab");
    }
    return s;
}

constexpr double skinStartFraction = 0.4;   // of d_min, the adaptive skin's start, as System's

/// Whether a sphere centre lies in the slab; written so that NaN counts as outside.
inline bool insideSlab(double x, double y, double z, const Box& b, double depth)
{
    return x >= b.xMin && x <= b.xMax && y >= b.yMin && y <= b.yMax && z >= 0.0 && z <= depth;
}

} // namespace

std::vector<PlaneWall3> slabWalls(const Box& box, double depth)
{
    return {
        {Vec3(box.xMin, box.yMin, 0.0), Vec3(0.0, 1.0, 0.0)},    // floor
        {Vec3(box.xMax, box.yMin, 0.0), Vec3(-1.0, 0.0, 0.0)},   // right
        {Vec3(box.xMin, box.yMax, 0.0), Vec3(0.0, -1.0, 0.0)},   // ceiling
        {Vec3(box.xMin, box.yMin, 0.0), Vec3(1.0, 0.0, 0.0)},    // left
        {Vec3(box.xMin, box.yMin, 0.0), Vec3(0.0, 0.0, 1.0)},    // front, z = 0
        {Vec3(box.xMin, box.yMin, depth), Vec3(0.0, 0.0, -1.0)}, // back, z = depth
    };
}

namespace {

// The name of wall w in messages: the slab's six in slabWalls' order, then added ones.
std::string wallName(std::size_t w)
{
    static const char* const names[] = {"the floor (y = yMin)", "the right wall (x = xMax)",
                                        "the ceiling (y = yMax)", "the left wall (x = xMin)",
                                        "the front wall (z = 0)", "the back wall (z = slabDepth)"};
    return w < 6 ? names[w] : "added wall " + std::to_string(w);
}

} // namespace

void SlabParticles::append(int cls, double diam, double density, const Vec3& pos, const Vec3& vel,
                           const Vec3& w)
{
    x.push_back(pos.x()); y.push_back(pos.y()); z.push_back(pos.z());
    vx.push_back(vel.x()); vy.push_back(vel.y()); vz.push_back(vel.z());
    wx.push_back(w.x()); wy.push_back(w.y()); wz.push_back(w.z());
    appendSphereConstants(*this, cls, diam, density);
    for (auto* a : {&fx, &fy, &fz, &tx, &ty, &tz, &fluidX, &fluidY, &fluidZ, &dragCoefficient,
                    &gasVx, &gasVy, &gasVz, &extraFx, &extraFy, &extraFz, &meanVx, &meanVy,
                    &meanVz, &meanFluidX, &meanFluidY, &meanFluidZ}) {
        a->push_back(0.0);
    }
    xRef.push_back(pos.x()); yRef.push_back(pos.y()); zRef.push_back(pos.z());
}

SlabSystem::SlabSystem(const Settings& settings)
    : EngineBase(validatedSlab(settings), slabWalls(settings.box, settings.slabDepth),
                 skinStartFraction, settings.neighbourSkin < 0.0)
{
}

void SlabSystem::addWall(const Vec3& point, const Vec3& normal)
{
    const double length = normal.norm();
    if (!(length > 0.0) || !std::isfinite(length)) {
        throw Error("wall normal of length " + formatValue(length) + " is outside (0, inf)");
    }
    walls_.push_back({point, normal / length});
    listValid_ = false;
    forcesValid_ = false;
}

void SlabSystem::addParticle(int cls, const Vec3& pos, const Vec3& vel, const Vec3& spin)
{
    checkClass(cls);
    const double d = meanDiameter(settings_.classes[cls]);   // a distribution's mean
    const double r = 0.5 * d;
    for (std::size_t w = 0; w < walls_.size(); ++w) {
        if (!(walls_[w].distance(pos) >= r - 0.01 * d)) {
            throw Error("particle of class '" + settings_.classes[cls].name + "' at ("
                        + formatValue(pos.x()) + ", " + formatValue(pos.y()) + ", "
                        + formatValue(pos.z()) + ") m pokes through " + wallName(w)
                        + " by more than 1 % of its diameter");
        }
    }
    for (std::size_t k = 0; k < p_.size(); ++k) {
        const double overlap = r + p_.radius[k] - (p_.position(k) - pos).norm();
        const double allowed = 0.01 * std::min(d, p_.diameter[k]);
        if (overlap > allowed) {
            throw Error("particle at (" + formatValue(pos.x()) + ", " + formatValue(pos.y()) + ", "
                        + formatValue(pos.z()) + ") m overlaps particle " + std::to_string(k)
                        + " by " + formatValue(overlap) + " m, outside [0, "
                        + formatValue(allowed) + "] m (1 % of the smaller diameter)");
        }
    }
    p_.append(cls, d, settings_.classes[cls].density, pos, vel, spin);
    listValid_ = false;
    forcesValid_ = false;
    recipe_.reset();   // the particles are no longer the recipe's alone
}

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
    constexpr bool hertz = std::is_same_v<Law, HertzMindlin>;
    static_assert(hertz || std::is_same_v<Law, LinearSpringDashpot>,
                  "a law needs its version of the batched kernel (SlabPairKernel.cpp)");
    const SlabPairLoop kernel =
        hertz ? streamingLoops().slabHertzWalls : streamingLoops().slabLinearWalls;
    SlabParticles& p = p_;
    Vec3* wXi = wallContacts_.xi.data();
    SlabPairBatch b;
    for (int first = 0; first < m; first += SlabPairBatch::capacity) {
        const int count = std::min(m - first, SlabPairBatch::capacity);
        for (int q = 0; q < count; ++q) {
            const auto [s, i] = picked[first + q];
            const double ri = p.radius[i];
            const PlaneWall3& wall = walls_[wallContacts_.wall[s]];
            // As contactForce's caller: nHat = -wall.nHat, v_i + (r_i w_i) x nHat
            b.overlap[q] = ri - wall.distance(p.position(i));
            b.nx[q] = -wall.nHat.x();
            b.ny[q] = -wall.nHat.y();
            b.nz[q] = -wall.nHat.z();
            b.dvx[q] = p.vx[i];
            b.dvy[q] = p.vy[i];
            b.dvz[q] = p.vz[i];
            b.sx[q] = ri * p.wx[i];
            b.sy[q] = ri * p.wy[i];
            b.sz[q] = ri * p.wz[i];
            b.xix[q] = wXi[s].x();
            b.xiy[q] = wXi[s].y();
            b.xiz[q] = wXi[s].z();
            b.setLaw(q, wallLaws_[p.classIndex[i]], hertz);
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
    const PlaneWall3* walls = walls_.data();
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
                const bool touch = !(ri - walls[wWall[s]].distance(pos) <= 0.0);
                picked[m] = {s, static_cast<int>(i)};
                m += touch;
                wXi[s] = selectWithoutBranch(touch, wXi[s], Vec3::Zero());
            }
        }
        if constexpr (Rolling) {
            for (int q = 0; q < m; ++q) {
                const auto [s, i] = picked[q];
                const double ri = p.radius[i];
                const PlaneWall3& wall = walls[wWall[s]];
                PairGeometry3 c = wallGeometry(p, i, wall, ri - wall.distance(p.position(i)));
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

double SlabSystem::drift()
{
    const Index n = static_cast<Index>(p_.size());
    const SlabDriftStep c{settings_.dt, 0.5 * settings_.dt, settings_.gravity[0],
                          settings_.gravity[1], settings_.box, settings_.slabDepth};
    SlabParticles& p = p_;
    const SlabDriftArrays a{
        p.invMass.data(), p.invInertia.data(),
        p.fx.data(), p.fy.data(), p.fz.data(),
        p.fluidX.data(), p.fluidY.data(), p.fluidZ.data(),
        p.tx.data(), p.ty.data(), p.tz.data(),
        p.xRef.data(), p.yRef.data(), p.zRef.data(),
        p.vx.data(), p.vy.data(), p.vz.data(),
        p.wx.data(), p.wy.data(), p.wz.data(),
        p.x.data(), p.y.data(), p.z.data()};
    const SlabDriftLoop driftLoop = streamingLoops().slabFirstHalfKickAndDrift;
    double maxDisplacement2 = 0.0;
    double lost = 0.0;
#pragma omp parallel num_threads(threads_) reduction(max : maxDisplacement2) \
    reduction(+ : lost)
    {
        const auto [first, last] = threadShare(n);
        driftLoop(a, c, first, last, maxDisplacement2, lost);
    }
    if (lost > 0.0) throwLostParticle();
    return maxDisplacement2;
}

double SlabSystem::kineticEnergy() const
{
    double ke = 0.0;
    for (std::size_t i = 0; i < p_.size(); ++i) {
        ke += 0.5 * p_.mass[i] * p_.velocity(i).squaredNorm()
              + 0.5 * p_.spin(i).squaredNorm() / p_.invInertia[i];
    }
    return ke;
}

double SlabSystem::elasticEnergy() const
{
    double energy = 0.0;
    withContactLaw([&](auto lawType, auto) {
        using Law = decltype(lawType);
        for (std::size_t k = 0; k < pairs_.size(); ++k) {
            const int i = pairs_.i[k];
            const int j = pairs_.j[k];
            const double overlap = p_.radius[i] + p_.radius[j] - (p_.position(j) - p_.position(i)).norm();
            if (overlap > 0.0) {
                energy += Law::elasticEnergy(overlap, pairs_.xi[k], pairLaws_[pairs_.law[k]]);
            }
        }
        for (std::size_t i = 0; i + 1 < wallContacts_.start.size(); ++i) {
            for (int s = wallContacts_.start[i]; s < wallContacts_.start[i + 1]; ++s) {
                const double overlap = p_.radius[i] - walls_[wallContacts_.wall[s]].distance(p_.position(i));
                if (overlap > 0.0) {
                    energy += Law::elasticEnergy(overlap, wallContacts_.xi[s], wallLaws_[p_.classIndex[i]]);
                }
            }
        }
    });
    return energy;
}

Vec3 SlabSystem::wallForce(int w) const
{
    Vec3 total = Vec3::Zero();
    for (std::size_t i = 0; i + 1 < wallContacts_.start.size(); ++i) {
        for (int s = wallContacts_.start[i]; s < wallContacts_.start[i + 1]; ++s) {
            if (wallContacts_.wall[s] != w) continue;
            const PlaneWall3& wall = walls_[w];
            const double ri = p_.radius[i];
            const double overlap = ri - wall.distance(p_.position(i));
            if (overlap <= 0.0) continue;
            PairGeometry3 c;
            c.overlap = overlap;
            c.nHat = -wall.nHat;
            c.vRel = p_.velocity(i) + (ri * p_.spin(i)).cross(c.nHat);
            c.rI = ri;
            c.rJ = 0.0;
            c.xiT = wallContacts_.xi[s];
            withContactLaw([&](auto lawType, auto) {
                total -= contactForce<3, decltype(lawType)>(c, wallLaws_[p_.classIndex[i]], 0.0).force;
            });
        }
    }
    return total;
}

void SlabSystem::throwLostParticle() const
{
    for (std::size_t i = 0; i < p_.size(); ++i) {
        if (!insideSlab(p_.x[i], p_.y[i], p_.z[i], settings_.box, settings_.slabDepth)) {
            throw Error("particle id " + std::to_string(p_.id[i]) + " left the slab at ("
                        + formatValue(p_.x[i]) + ", " + formatValue(p_.y[i]) + ", "
                        + formatValue(p_.z[i]) + ") m");
        }
    }
    throw Error("a particle left the slab");
}

std::size_t SlabSystem::memoryBytes() const
{
    std::size_t bytes = listMemoryBytes();
    p_.forEachArray([&](const auto& a) { bytes += a.capacity() * sizeof(a[0]); });
    return bytes;
}

} // namespace dem
