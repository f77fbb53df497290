// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The 2D engine's own part (EngineBase does the rest): adding particles, the drift, the
// pair forces over the groups, the wall contacts with the second half-kick, the energies.

#include "dem/System.hpp"

#include "PairGroups.hpp"
#include "WallGeometry.hpp"
#include "StreamingLoops.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace dem {

namespace {

const Settings& validated(const Settings& s)
{
    validateSettings(s);
    if (s.dimension != 2) {
        throw Error("dimension = " + std::to_string(s.dimension) + " is outside {2}: the 2D "
                    "engine runs discs in a plane; the slab (dimension 3) runs in dem::SlabSystem, "
                    "which dem::Simulation selects for it");
    }
    return s;
}

using Index = std::ptrdiff_t;   // OpenMP loop index

} // namespace

System::System(const Settings& settings)
    : EngineBase(validated(settings), boxWalls(settings.box), skinStartFraction,
                 settings.neighbourSkin < 0.0),
      timeStepBound_(dem::timeStepBound(settings))
{
}

void System::addParticle(int cls, double x, double y, double vx, double vy, double omega)
{
    checkClass(cls);
    const double d = meanDiameter(settings_.classes[cls]);   // a distribution's mean
    const double r = 0.5 * d;
    const double tolerance = 0.01 * d;
    const Eigen::Vector2d pos(x, y);
    for (const PlaneWall& w : walls_) {
        if (!(w.distance(pos) >= r - tolerance)) {
            const Box& b = settings_.box;
            throw Error("particle of class '" + settings_.classes[cls].name + "' at ("
                        + formatValue(x) + ", " + formatValue(y) + ") m is outside the box ["
                        + formatValue(b.xMin) + ", " + formatValue(b.xMax) + "] x ["
                        + formatValue(b.yMin) + ", " + formatValue(b.yMax)
                        + "] m: its disc must lie inside the walls within 1 % of its diameter");
        }
    }
    for (std::size_t k = 0; k < p_.size(); ++k) {
        const double dx = p_.x[k] - x;
        const double dy = p_.y[k] - y;
        const double overlap = r + p_.radius[k] - std::sqrt(dx * dx + dy * dy);
        const double allowed = 0.01 * std::min(d, p_.diameter[k]);
        if (overlap > allowed) {
            throw Error("particle at (" + formatValue(x) + ", " + formatValue(y)
                        + ") m overlaps particle " + std::to_string(k) + " by "
                        + formatValue(overlap) + " m, outside [0, " + formatValue(allowed)
                        + "] m (1 % of the smaller diameter)");
        }
    }
    p_.append(cls, d, settings_.classes[cls].density, x, y, vx, vy, omega);
    listValid_ = false;
    forcesValid_ = false;
    recipe_.reset();   // the particles are no longer the recipe's alone
}

void System::computePairForces(double historyDt)
{
    withContactLaw([&](auto law, auto rolling) {
        sumPairForces<decltype(law), decltype(rolling)::value>(historyDt);
    });
}

template <class Law, bool Rolling>
void System::sumPairForces(double historyDt)
{
    const int* pi = pairs_.i.data();
    const int* pj = pairs_.j.data();
    const int* law = pairs_.law.data();
    const int* groupStart = pairs_.groupStart.data();
    double* xiT = pairs_.xi.data();
    const double* x = p_.x.data();
    const double* y = p_.y.data();
    const double* vx = p_.vx.data();
    const double* vy = p_.vy.data();
    const double* om = p_.omega.data();
    const double* r = p_.radius.data();
    const ContactLaw* laws = pairLaws_.data();
    // Sums over each particle's pairs; p.torque holds the sum of tangential forces until
    // addWallForcesAndKick multiplies it by the radius.
    double* sumFx = p_.fx.data();
    double* sumFy = p_.fy.data();
    double* sumFt = p_.torque.data();
    const std::size_t n = p_.size();
    if constexpr (Rolling) {
        pairRolling_.resize(pairs_.size());
        rollingScale_.resize(n);
        touchingPerGroup_.resize(nPairGroups);
    }
    double* pairRolling = pairRolling_.data();
    double* share = rollingScale_.data();
    const double* invInertia = p_.invInertia.data();
    const double dt = settings_.dt;

    // A touching pair (found by the group's first pass). Inlined into the group's second
    // pass: called out of line, it reloaded its dozen captured pointers for every pair.
    auto pairForce = [&](Index k, std::size_t& touching, double& maxOverlap)
                         __attribute__((always_inline)) {
        const int i = pi[k];
        const int j = pj[k];
        const double dx = x[j] - x[i];
        const double dy = y[j] - y[i];
        const double d2 = dx * dx + dy * dy;
        const double rSum = r[i] + r[j];
        const double dist = std::sqrt(d2);
        const double invDist = 1.0 / dist;
        PairGeometry g;
        g.overlap = rSum - dist;
        g.nHat = Eigen::Vector2d(dx * invDist, dy * invDist);
        const Eigen::Vector2d tHat(-g.nHat.y(), g.nHat.x());
        g.vRel = Eigen::Vector2d(vx[i] - vx[j], vy[i] - vy[j]) + (om[i] * r[i] + om[j] * r[j]) * tHat;
        g.rI = r[i];
        g.rJ = r[j];
        g.xiT = xiT[k];
        if constexpr (Rolling) g.omegaRel = om[i] - om[j];
        const PairForce f = contactForce<2, Law, Rolling>(g, laws[law[k]], historyDt);
        xiT[k] = f.xiT;
        sumFx[i] += f.force.x();
        sumFy[i] += f.force.y();
        sumFx[j] -= f.force.x();
        sumFy[j] -= f.force.y();
        sumFt[i] += f.ft;   // the torque on either partner is r ft (see contactForce)
        sumFt[j] += f.ft;
        if constexpr (Rolling) {
            // Added by limitRollingTorques, scaled, once every contact's share is known
            pairRolling[k] = f.rollingTorque;
            share[i] += f.rollingCoefficient * dt * invInertia[i];
            share[j] += f.rollingCoefficient * dt * invInertia[j];
        }
        ++touching;
        maxOverlap = std::max(maxOverlap, g.overlap);
    };

    // The groups as sumPairGroups runs them. Two passes per group: the touching pairs
    // picked out without a branch (most candidates do not touch, and a branch per pair
    // mispredicts), then their forces in list order.
    touchingScratch_.resize(pairs_.size());   // (a loaded state's list has no build here)
    int* touchingPairs = touchingScratch_.data();
    auto group = [&](int g, std::size_t& touching, double& maxOverlap) {
        int* picked = touchingPairs + groupStart[g];
        int m = 0;
        const int end = groupStart[g + 1];   // read once: the picks are ints too
        for (int k = groupStart[g]; k < end; ++k) {
            const int i = pi[k];
            const int j = pj[k];
            const double dx = x[j] - x[i];
            const double dy = y[j] - y[i];
            const double rSum = r[i] + r[j];
            const bool touch = !(dx * dx + dy * dy >= rSum * rSum);   // NaN counts as touching
            picked[m] = k;
            m += touch;
            const double xi = xiT[k];
            xiT[k] = selectWithoutBranch(touch, xi, 0.0);   // separated: the history ends
        }
        for (int q = 0; q < m; ++q) pairForce(picked[q], touching, maxOverlap);
        if constexpr (Rolling) touchingPerGroup_[g] = m;
    };
    auto zeroBlock = [&](std::size_t first, std::size_t last) {
        std::fill(sumFx + first, sumFx + last, 0.0);
        std::fill(sumFy + first, sumFy + last, 0.0);
        std::fill(sumFt + first, sumFt + last, 0.0);
        if constexpr (Rolling) std::fill(share + first, share + last, 0.0);
    };
    sumPairGroups(threads_, n, zeroBlock, group, contactCount_, maxOverlap_);
    if constexpr (Rolling) limitRollingTorques();
}

void System::addWallForcesAndKick(double historyDt, bool kick, bool fluid)
{
    withContactLaw([&](auto law, auto rolling) {
        addWallForcesAndKickWith<decltype(law), decltype(rolling)::value>(historyDt, kick, fluid);
    });
}

template <class Law, bool Rolling>
void System::addWallForcesAndKickWith(double historyDt, bool kick, bool fluid)
{
    const Index n = static_cast<Index>(p_.size());
    const double h = 0.5 * settings_.dt;
    const double gx = settings_.gravity[0];
    const double gy = settings_.gravity[1];
    const double weight = meanWeight_;
    const int* wStart = wallContacts_.start.data();
    const int* wWall = wallContacts_.wall.data();
    double* wXi = wallContacts_.xi.data();
    const PlaneWall* walls = walls_.data();
    const ContactLaw* wallLaws = wallLaws_.data();
    Particles& p = p_;
    // Plain pointers, for the wall loop and the kick's arrays
    double* fxA = p.fx.data();
    double* fyA = p.fy.data();
    double* torqueA = p.torque.data();
    const double* radius = p.radius.data();
    const double* rollingScale = rollingScale_.data();

    const KickArrays kickArrays{
        wStart,          fxA,           fyA,           radius,      p.invMass.data(),
        p.invInertia.data(), p.dragCoefficient.data(), p.gasVx.data(), p.gasVy.data(),
        p.extraFx.data(), p.extraFy.data(), torqueA,  p.vx.data(),  p.vy.data(),
        p.omega.data(),  p.fluidX.data(), p.fluidY.data(), p.meanVx.data(), p.meanVy.data()};

    const KickLoop kickLoop = streamingLoops().secondHalfKick;
    const KickMode mode = kickMode(kick, fluid);

    std::size_t touching = 0;
    double maxOverlap = maxOverlap_;
#pragma omp parallel num_threads(threads_) reduction(+ : touching) \
    reduction(max : maxOverlap)
    {
        // Each thread its own range of particles, for both loops (no barrier between).
        // The few particles with wall candidates first: their wall forces are added to the
        // pair sums in wall order, and their torque made whole (r ft + wall torques); then
        // every particle's kick, in a loop the compiler vectorises.
        const auto [first, last] = threadShare(n);
        // wStart is non-decreasing: equal ends of a run of 16 particles mean none of them
        // has a wall candidate, and the run is skipped with two loads
        constexpr Index run = 16;
        for (Index i = first; i < last; ++i) {
            if (i % run == 0 && i + run <= last && wStart[i] == wStart[i + run]) {
                i += run - 1;
                continue;
            }
            if (wStart[i] == wStart[i + 1]) continue;
            double fx = fxA[i], fy = fyA[i];
            const double ri = radius[i];
            double torque = ri * torqueA[i];
            for (int s = wStart[i]; s < wStart[i + 1]; ++s) {
                const PlaneWall& w = walls[wWall[s]];
                const Eigen::Vector2d pos(p.x[i], p.y[i]);
                const double overlap = ri - w.distance(pos);
                if (overlap <= 0.0) {
                    wXi[s] = 0.0;
                    continue;
                }
                PairGeometry g = wallGeometry(p, i, w, overlap);
                g.xiT = wXi[s];
                const PairForce f = contactForce<2, Law, Rolling>(g, wallLaws[p.classIndex[i]], historyDt);
                fx += f.force.x();
                fy += f.force.y();
                torque += f.torqueI;
                // The rolling part scaled by the particle's limit (limitRollingTorques)
                if constexpr (Rolling) torque += (rollingScale[i] - 1.0) * f.rollingTorque;
                wXi[s] = f.xiT;
                ++touching;
                maxOverlap = std::max(maxOverlap, overlap);
            }
            fxA[i] = fx;
            fyA[i] = fy;
            torqueA[i] = torque;
        }
        kickLoop(kickArrays, first, last, h, gx, gy, weight, mode);
    }
    contactCount_ += touching;
    maxOverlap_ = maxOverlap;
}

double System::drift()
{
    const Index n = static_cast<Index>(p_.size());
    const DriftStep c{settings_.dt, 0.5 * settings_.dt, settings_.gravity[0],
                      settings_.gravity[1], settings_.box};
    Particles& p = p_;
    const DriftArrays a{p.invMass.data(), p.invInertia.data(), p.fx.data(),     p.fy.data(),
                        p.fluidX.data(),  p.fluidY.data(),     p.torque.data(), p.xRef.data(),
                        p.yRef.data(),    p.vx.data(),         p.vy.data(),     p.omega.data(),
                        p.x.data(),       p.y.data()};
    const DriftLoop driftLoop = streamingLoops().firstHalfKickAndDrift;
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

double System::kineticEnergy() const
{
    double ke = 0.0;
    for (std::size_t i = 0; i < p_.size(); ++i) {
        ke += 0.5 * p_.mass[i] * (p_.vx[i] * p_.vx[i] + p_.vy[i] * p_.vy[i])
              + 0.5 * p_.omega[i] * p_.omega[i] / p_.invInertia[i];
    }
    return ke;
}

double System::elasticEnergy() const
{
    double energy = 0.0;
    withContactLaw([&](auto lawType, auto) {
        using Law = decltype(lawType);
        for (std::size_t k = 0; k < pairs_.size(); ++k) {
            const int i = pairs_.i[k];
            const int j = pairs_.j[k];
            const double dx = p_.x[j] - p_.x[i];
            const double dy = p_.y[j] - p_.y[i];
            const double overlap = p_.radius[i] + p_.radius[j] - std::sqrt(dx * dx + dy * dy);
            if (overlap > 0.0) {
                energy += Law::elasticEnergy(overlap, pairs_.xi[k], pairLaws_[pairs_.law[k]]);
            }
        }
        for (std::size_t i = 0; i + 1 < wallContacts_.start.size(); ++i) {
            for (int s = wallContacts_.start[i]; s < wallContacts_.start[i + 1]; ++s) {
                const Eigen::Vector2d pos(p_.x[i], p_.y[i]);
                const double overlap = p_.radius[i] - walls_[wallContacts_.wall[s]].distance(pos);
                if (overlap > 0.0) {
                    energy += Law::elasticEnergy(overlap, wallContacts_.xi[s], wallLaws_[p_.classIndex[i]]);
                }
            }
        }
    });
    return energy;
}

std::size_t System::memoryBytes() const
{
    return p_.memoryBytes() + listMemoryBytes()
           + touchingScratch_.capacity() * sizeof(touchingScratch_[0]);
}

void System::throwLostParticle() const
{
    const Box& b = settings_.box;
    for (std::size_t i = 0; i < p_.size(); ++i) {
        if (!(p_.x[i] >= b.xMin && p_.x[i] <= b.xMax && p_.y[i] >= b.yMin && p_.y[i] <= b.yMax)) {
            throw Error("particle id " + std::to_string(p_.id[i]) + " left the box at ("
                        + formatValue(p_.x[i]) + ", " + formatValue(p_.y[i]) + ") m, outside ["
                        + formatValue(b.xMin) + ", " + formatValue(b.xMax) + "] x ["
                        + formatValue(b.yMin) + ", " + formatValue(b.yMax) + "] m");
        }
    }
    throw Error("a particle left the box");
}

} // namespace dem
