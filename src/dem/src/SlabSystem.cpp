// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The slab mode's engine: System's step with 3-vectors and the 3D contact kernel (its pair
// forces in SlabPairForces.cpp, its wall forces and kick in SlabWallForces.cpp).

#include "dem/SlabSystem.hpp"
#include "dem/Particles.hpp"
#include "dem/System.hpp"

#include "PairGroups.hpp"
#include "SlabWalls.hpp"
#include "StreamingLoops.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

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
    : EngineBase(validatedSlab(settings), planeWalls(settings), skinStartFraction,
                 settings.neighbourSkin < 0.0),
      cylinders_(cylinderWalls(settings))
{
}

void SlabSystem::addWall(const Vec3& point, const Vec3& normal)
{
    const double length = normal.norm();
    if (!(length > 0.0) || !std::isfinite(length)) {
        throw Error("wall normal of length " + formatValue(length) + " is outside (0, inf)");
    }
    // After the planes: the cylinders' contacts move up one, their history with them
    const int planes = static_cast<int>(walls_.size());
    for (int& w : wallContacts_.wall) w += w >= planes;
    walls_.push_back({point, normal / length});
    listValid_ = false;
    forcesValid_ = false;
}

void SlabSystem::addParticle(int cls, const Vec3& pos, const Vec3& vel, const Vec3& spin)
{
    checkClass(cls);
    const double d = meanDiameter(settings_.classes[cls]);   // a distribution's mean
    const double r = 0.5 * d;
    const int planes = static_cast<int>(walls_.size());
    for (int w = 0; w < wallCount(); ++w) {
        const double clearance = r - 0.01 * d;
        if (!(wallDistance(w, pos) >= clearance)) {
            throw Error("particle of class '" + settings_.classes[cls].name + "' at ("
                        + formatValue(pos.x()) + ", " + formatValue(pos.y()) + ", "
                        + formatValue(pos.z()) + ") m pokes through "
                        + slabWallName(settings_, w, planes) + " by more than 1 % of its "
                        "diameter: "
                        + wallAllowance(clearance, w < planes ? nullptr : &cylinders_[w - planes]));
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
                const double overlap = p_.radius[i] - wallDistance(wallContacts_.wall[s], p_.position(i));
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
            const double ri = p_.radius[i];
            // Touching first, as the rolling limit: a candidate's normal may be undefined
            if (ri - wallDistance(w, p_.position(i)) <= 0.0) continue;
            const WallSide side = wallSide(w, p_.position(i));
            const double overlap = ri - side.distance;
            PairGeometry3 c;
            c.overlap = overlap;
            c.nHat = -side.nHat;
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
