// The slab mode's engine: System's step with 3-vectors and the 3D contact kernel.

#include "dem/SlabSystem.hpp"
#include "dem/Particles.hpp"
#include "dem/System.hpp"

#include "PairGroups.hpp"

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
    const double d = settings_.classes[cls].diameter;
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

void SlabSystem::computePairForces(double historyDt)
{
    SlabParticles& p = p_;
    const std::size_t n = p.size();
    const ContactLaw* laws = pairLaws_.data();
    const int* groupStart = pairs_.groupStart.data();
    // Sums over each particle's pairs; p.t* hold the sum of nHat x Ft until
    // addWallForcesAndKick multiplies it by the radius (the torque on either partner is
    // r nHat x Ft, see contactForce).
    auto pairForce = [&](Index k, std::size_t& touching, double& maxOverlap) {
        const int i = pairs_.i[k];
        const int j = pairs_.j[k];
        const Vec3 d(p.x[j] - p.x[i], p.y[j] - p.y[i], p.z[j] - p.z[i]);
        const double d2 = d.squaredNorm();
        const double rSum = p.radius[i] + p.radius[j];
        if (d2 >= rSum * rSum) {
            pairs_.xi[k].setZero();   // separated: the contact's history ends
            return;
        }
        const double dist = std::sqrt(d2);
        PairGeometry3 g;
        g.overlap = rSum - dist;
        g.nHat = d / dist;
        g.rI = p.radius[i];
        g.rJ = p.radius[j];
        // Contact points: v_i + w_i x (r_i n) and v_j + w_j x (-r_j n).
        g.vRel = p.velocity(i) - p.velocity(j) + (g.rI * p.spin(i) + g.rJ * p.spin(j)).cross(g.nHat);
        g.xiT = pairs_.xi[k];
        const PairForce3 f = contactForce(g, laws[pairs_.law[k]], historyDt);
        pairs_.xi[k] = f.xiT;
        const Vec3 nxF = g.nHat.cross(f.ft);
        p.fx[i] += f.force.x(); p.fy[i] += f.force.y(); p.fz[i] += f.force.z();
        p.fx[j] -= f.force.x(); p.fy[j] -= f.force.y(); p.fz[j] -= f.force.z();
        p.tx[i] += nxF.x(); p.ty[i] += nxF.y(); p.tz[i] += nxF.z();
        p.tx[j] += nxF.x(); p.ty[j] += nxF.y(); p.tz[j] += nxF.z();
        ++touching;
        maxOverlap = std::max(maxOverlap, g.overlap);
    };
    auto group = [&](int gr, std::size_t& touching, double& maxOverlap) {
        for (Index k = groupStart[gr]; k < groupStart[gr + 1]; ++k) pairForce(k, touching, maxOverlap);
    };
    auto zeroBlock = [&](std::size_t first, std::size_t last) {
        for (auto* a : {&p.fx, &p.fy, &p.fz, &p.tx, &p.ty, &p.tz}) {
            std::fill(a->begin() + first, a->begin() + last, 0.0);
        }
    };
    sumPairGroups(settings_.nThreads, n, zeroBlock, group, contactCount_, maxOverlap_);
}

void SlabSystem::addWallForcesAndKick(double historyDt, bool kick, bool fluid)
{
    const Index n = static_cast<Index>(p_.size());
    const double h = 0.5 * settings_.dt;
    const Vec3 g(settings_.gravity[0], settings_.gravity[1], 0.0);
    const double weight = meanWeight_;
    SlabParticles& p = p_;

    std::size_t touching = 0;
    double maxOverlap = maxOverlap_;
#pragma omp parallel for num_threads(settings_.nThreads) schedule(static) \
    reduction(+ : touching) reduction(max : maxOverlap)
    for (Index i = 0; i < n; ++i) {
        const double ri = p.radius[i];
        Vec3 force(p.fx[i], p.fy[i], p.fz[i]);
        Vec3 torque = ri * Vec3(p.tx[i], p.ty[i], p.tz[i]);
        const Vec3 pos = p.position(i);
        const Vec3 v = p.velocity(i);
        const Vec3 w = p.spin(i);
        for (int s = wallContacts_.start[i]; s < wallContacts_.start[i + 1]; ++s) {
            const PlaneWall3& wall = walls_[wallContacts_.wall[s]];
            const double overlap = ri - wall.distance(pos);
            if (overlap <= 0.0) {
                wallContacts_.xi[s].setZero();
                continue;
            }
            PairGeometry3 c;
            c.overlap = overlap;
            c.nHat = -wall.nHat;
            c.vRel = v + (ri * w).cross(c.nHat);
            c.rI = ri;
            c.rJ = 0.0;
            c.xiT = wallContacts_.xi[s];
            const PairForce3 f = contactForce(c, wallLaws_[p.classIndex[i]], historyDt);
            force += f.force;
            torque += f.torqueI;
            wallContacts_.xi[s] = f.xiT;
            ++touching;
            maxOverlap = std::max(maxOverlap, overlap);
        }
        p.fx[i] = force.x(); p.fy[i] = force.y(); p.fz[i] = force.z();
        p.tx[i] = torque.x(); p.ty[i] = torque.y(); p.tz[i] = torque.z();
        if (!kick) continue;

        const double invM = p.invMass[i];
        Vec3 vNew;
        if (fluid) {
            // Second half-kick with the drag implicit, as System.
            const double K = p.dragCoefficient[i];
            const Vec3 gas(p.gasVx[i], p.gasVy[i], p.gasVz[i]);
            const Vec3 extra(p.extraFx[i], p.extraFy[i], p.extraFz[i]);
            vNew = (v + h * ((force + K * gas + extra) * invM + g)) / (1.0 + h * K * invM);
            const Vec3 fluidForce = K * (gas - vNew) + extra;
            p.fluidX[i] = fluidForce.x(); p.fluidY[i] = fluidForce.y(); p.fluidZ[i] = fluidForce.z();
            p.meanVx[i] += weight * vNew.x();
            p.meanVy[i] += weight * vNew.y();
            p.meanVz[i] += weight * vNew.z();
        } else {
            vNew = v + h * (force * invM + g);
        }
        p.vx[i] = vNew.x(); p.vy[i] = vNew.y(); p.vz[i] = vNew.z();
        const Vec3 wNew = w + h * p.invInertia[i] * torque;
        p.wx[i] = wNew.x(); p.wy[i] = wNew.y(); p.wz[i] = wNew.z();
    }
    contactCount_ += touching;
    maxOverlap_ = maxOverlap;
}

bool SlabSystem::inside(std::size_t i) const
{
    const Box& b = settings_.box;
    // Written so that NaN counts as outside.
    return p_.x[i] >= b.xMin && p_.x[i] <= b.xMax && p_.y[i] >= b.yMin && p_.y[i] <= b.yMax
           && p_.z[i] >= 0.0 && p_.z[i] <= settings_.slabDepth;
}

double SlabSystem::drift()
{
    const Index n = static_cast<Index>(p_.size());
    const double dt = settings_.dt;
    const double h = 0.5 * dt;
    const Vec3 g(settings_.gravity[0], settings_.gravity[1], 0.0);
    SlabParticles& p = p_;

    double maxDisplacement2 = 0.0;
    int lost = 0;
#pragma omp parallel for num_threads(settings_.nThreads) schedule(static) \
    reduction(max : maxDisplacement2) reduction(| : lost)
    for (Index i = 0; i < n; ++i) {
        const double invM = p.invMass[i];
        const Vec3 force(p.fx[i] + p.fluidX[i], p.fy[i] + p.fluidY[i], p.fz[i] + p.fluidZ[i]);
        const Vec3 v = p.velocity(i) + h * (force * invM + g);
        const Vec3 w = p.spin(i) + h * p.invInertia[i] * Vec3(p.tx[i], p.ty[i], p.tz[i]);
        p.vx[i] = v.x(); p.vy[i] = v.y(); p.vz[i] = v.z();
        p.wx[i] = w.x(); p.wy[i] = w.y(); p.wz[i] = w.z();
        p.x[i] += dt * v.x();
        p.y[i] += dt * v.y();
        p.z[i] += dt * v.z();
        const Vec3 moved(p.x[i] - p.xRef[i], p.y[i] - p.yRef[i], p.z[i] - p.zRef[i]);
        maxDisplacement2 = std::max(maxDisplacement2, moved.squaredNorm());
        lost |= !inside(i);
    }
    if (lost) throwLostParticle();
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
    for (std::size_t k = 0; k < pairs_.size(); ++k) {
        const int i = pairs_.i[k];
        const int j = pairs_.j[k];
        const double overlap = p_.radius[i] + p_.radius[j] - (p_.position(j) - p_.position(i)).norm();
        if (overlap > 0.0) {
            const ContactLaw& law = pairLaws_[pairs_.law[k]];
            energy += 0.5 * law.kn * overlap * overlap + 0.5 * law.kt * pairs_.xi[k].squaredNorm();
        }
    }
    for (std::size_t i = 0; i + 1 < wallContacts_.start.size(); ++i) {
        for (int s = wallContacts_.start[i]; s < wallContacts_.start[i + 1]; ++s) {
            const double overlap = p_.radius[i] - walls_[wallContacts_.wall[s]].distance(p_.position(i));
            if (overlap > 0.0) {
                const ContactLaw& law = wallLaws_[p_.classIndex[i]];
                energy += 0.5 * law.kn * overlap * overlap + 0.5 * law.kt * wallContacts_.xi[s].squaredNorm();
            }
        }
    }
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
            total -= contactForce(c, wallLaws_[p_.classIndex[i]], 0.0).force;
        }
    }
    return total;
}

void SlabSystem::throwLostParticle() const
{
    for (std::size_t i = 0; i < p_.size(); ++i) {
        if (!inside(i)) {
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
