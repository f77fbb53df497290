// The slab mode's engine: System's step with 3-vectors and the 3D contact kernel.

#include "dem/SlabSystem.hpp"
#include "dem/Particles.hpp"
#include "dem/System.hpp"

#include "PairGroups.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include <omp.h>

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
    const int* pi = pairs_.i.data();
    const int* pj = pairs_.j.data();
    const int* law = pairs_.law.data();
    const int* groupStart = pairs_.groupStart.data();
    Vec3* xiT = pairs_.xi.data();
    const double* x = p.x.data();
    const double* y = p.y.data();
    const double* z = p.z.data();
    const double* vx = p.vx.data();
    const double* vy = p.vy.data();
    const double* vz = p.vz.data();
    const double* wx = p.wx.data();
    const double* wy = p.wy.data();
    const double* wz = p.wz.data();
    const double* r = p.radius.data();
    const ContactLaw* laws = pairLaws_.data();
    // Sums over each particle's pairs; the t* hold the sum of nHat x Ft until
    // addWallForcesAndKick multiplies it by the radius (the torque on either partner is
    // r nHat x Ft, see contactForce).
    double* sumFx = p.fx.data();
    double* sumFy = p.fy.data();
    double* sumFz = p.fz.data();
    double* sumTx = p.tx.data();
    double* sumTy = p.ty.data();
    double* sumTz = p.tz.data();

    // A touching pair (found by the group's first pass)
    auto pairForce = [&](Index k, std::size_t& touching, double& maxOverlap) {
        const int i = pi[k];
        const int j = pj[k];
        const Vec3 d(x[j] - x[i], y[j] - y[i], z[j] - z[i]);
        const double dist = std::sqrt(d.x() * d.x() + d.y() * d.y() + d.z() * d.z());
        PairGeometry3 g;
        g.overlap = r[i] + r[j] - dist;
        g.nHat = d / dist;
        g.rI = r[i];
        g.rJ = r[j];
        // Contact points: v_i + w_i x (r_i n) and v_j + w_j x (-r_j n).
        g.vRel = Vec3(vx[i] - vx[j], vy[i] - vy[j], vz[i] - vz[j])
                 + (g.rI * Vec3(wx[i], wy[i], wz[i]) + g.rJ * Vec3(wx[j], wy[j], wz[j])).cross(g.nHat);
        g.xiT = xiT[k];
        const PairForce3 f = contactForce(g, laws[law[k]], historyDt);
        xiT[k] = f.xiT;
        const Vec3 nxF = g.nHat.cross(f.ft);
        sumFx[i] += f.force.x(); sumFy[i] += f.force.y(); sumFz[i] += f.force.z();
        sumFx[j] -= f.force.x(); sumFy[j] -= f.force.y(); sumFz[j] -= f.force.z();
        sumTx[i] += nxF.x(); sumTy[i] += nxF.y(); sumTz[i] += nxF.z();
        sumTx[j] += nxF.x(); sumTy[j] += nxF.y(); sumTz[j] += nxF.z();
        ++touching;
        maxOverlap = std::max(maxOverlap, g.overlap);
    };

    // The groups as sumPairGroups runs them, in two passes as System's: the touching pairs
    // picked out without a branch, then their forces in list order.
    touchingScratch_.resize(pairs_.size());   // (a loaded state's list has no build here)
    int* touchingPairs = touchingScratch_.data();
    auto group = [&](int gr, std::size_t& touching, double& maxOverlap) {
        int* picked = touchingPairs + groupStart[gr];
        int m = 0;
        for (int k = groupStart[gr]; k < groupStart[gr + 1]; ++k) {
            const int i = pi[k];
            const int j = pj[k];
            const double dx = x[j] - x[i];
            const double dy = y[j] - y[i];
            const double dz = z[j] - z[i];
            const double rSum = r[i] + r[j];
            const bool touch = !(dx * dx + dy * dy + dz * dz >= rSum * rSum);   // NaN: touching
            picked[m] = k;
            m += touch;
            double* xi = xiT[k].data();   // separated: the contact's history ends
            xi[0] = touch ? xi[0] : 0.0;
            xi[1] = touch ? xi[1] : 0.0;
            xi[2] = touch ? xi[2] : 0.0;
        }
        for (int q = 0; q < m; ++q) pairForce(picked[q], touching, maxOverlap);
    };
    auto zeroBlock = [&](std::size_t first, std::size_t last) {
        for (double* a : {sumFx, sumFy, sumFz, sumTx, sumTy, sumTz}) {
            std::fill(a + first, a + last, 0.0);
        }
    };
    sumPairGroups(settings_.nThreads, n, zeroBlock, group, contactCount_, maxOverlap_);
}

void SlabSystem::addWallForcesAndKick(double historyDt, bool kick, bool fluid)
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

    std::size_t touching = 0;
    double maxOverlap = maxOverlap_;
#pragma omp parallel num_threads(settings_.nThreads) reduction(+ : touching) \
    reduction(max : maxOverlap)
    {
        // As System's: each thread its own range of particles for both loops; the few
        // particles with wall candidates first (their wall forces added to the pair sums in
        // wall order, their torque made whole), then every particle's kick, vectorised.
        const Index nThreads = omp_get_num_threads();
        const Index thread = omp_get_thread_num();
        const Index first = n * thread / nThreads;
        const Index last = n * (thread + 1) / nThreads;
        for (Index i = first; i < last; ++i) {
            if (wStart[i] == wStart[i + 1]) continue;
            const double ri = p.radius[i];
            Vec3 force(p.fx[i], p.fy[i], p.fz[i]);
            Vec3 torque = ri * Vec3(p.tx[i], p.ty[i], p.tz[i]);
            const Vec3 pos = p.position(i);
            const Vec3 v = p.velocity(i);
            const Vec3 w = p.spin(i);
            for (int s = wStart[i]; s < wStart[i + 1]; ++s) {
                const PlaneWall3& wall = walls[wWall[s]];
                const double overlap = ri - wall.distance(pos);
                if (overlap <= 0.0) {
                    wXi[s].setZero();
                    continue;
                }
                PairGeometry3 c;
                c.overlap = overlap;
                c.nHat = -wall.nHat;
                c.vRel = v + (ri * w).cross(c.nHat);
                c.rI = ri;
                c.rJ = 0.0;
                c.xiT = wXi[s];
                const PairForce3 f = contactForce(c, wallLaws[p.classIndex[i]], historyDt);
                force += f.force;
                torque += f.torqueI;
                wXi[s] = f.xiT;
                ++touching;
                maxOverlap = std::max(maxOverlap, overlap);
            }
            p.fx[i] = force.x(); p.fy[i] = force.y(); p.fz[i] = force.z();
            p.tx[i] = torque.x(); p.ty[i] = torque.y(); p.tz[i] = torque.z();
        }
        if (kick && fluid) {
            kickLoop<true, true>(first, last, h, weight);
        } else if (kick) {
            kickLoop<true, false>(first, last, h, weight);
        } else {
            kickLoop<false, false>(first, last, h, weight);
        }
    }
    contactCount_ += touching;
    maxOverlap_ = maxOverlap;
}

template <bool Kick, bool Fluid>
void SlabSystem::kickLoop(std::ptrdiff_t first, std::ptrdiff_t last, double h, double weight)
{
    SlabParticles& p = p_;
    const int* wStart = wallContacts_.start.data();
    const double gx = settings_.gravity[0];
    const double gy = settings_.gravity[1];
    const double* fx = p.fx.data();
    const double* fy = p.fy.data();
    const double* fz = p.fz.data();
    double* tx = p.tx.data();
    double* ty = p.ty.data();
    double* tz = p.tz.data();
    const double* radius = p.radius.data();
    const double* invMass = p.invMass.data();
    const double* invInertia = p.invInertia.data();
    const double* dragK = p.dragCoefficient.data();
    const double* gasVx = p.gasVx.data();
    const double* gasVy = p.gasVy.data();
    const double* gasVz = p.gasVz.data();
    const double* extraFx = p.extraFx.data();
    const double* extraFy = p.extraFy.data();
    const double* extraFz = p.extraFz.data();
    double* vx = p.vx.data();
    double* vy = p.vy.data();
    double* vz = p.vz.data();
    double* wx = p.wx.data();
    double* wy = p.wy.data();
    double* wz = p.wz.data();
    double* fluidX = p.fluidX.data();
    double* fluidY = p.fluidY.data();
    double* fluidZ = p.fluidZ.data();
    double* meanVx = p.meanVx.data();
    double* meanVy = p.meanVy.data();
    double* meanVz = p.meanVz.data();
#pragma omp simd
    for (Index i = first; i < last; ++i) {
        // Particles with walls have their whole torque already (the loop before): a factor
        // of 1 keeps it exactly, and a select of loaded values vectorises.
        const double ri = radius[i];
        const double scale = wStart[i] == wStart[i + 1] ? ri : 1.0;
        const double txi = scale * tx[i];
        const double tyi = scale * ty[i];
        const double tzi = scale * tz[i];
        tx[i] = txi;
        ty[i] = tyi;
        tz[i] = tzi;
        if constexpr (Kick) {
            const double invM = invMass[i];
            if constexpr (Fluid) {
                // Second half-kick with the drag implicit, as System.
                const double K = dragK[i];
                const double denominator = 1.0 + h * K * invM;
                const double vxNew = (vx[i] + h * ((fx[i] + K * gasVx[i] + extraFx[i]) * invM + gx))
                                     / denominator;
                const double vyNew = (vy[i] + h * ((fy[i] + K * gasVy[i] + extraFy[i]) * invM + gy))
                                     / denominator;
                const double vzNew = (vz[i] + h * ((fz[i] + K * gasVz[i] + extraFz[i]) * invM))
                                     / denominator;
                vx[i] = vxNew;
                vy[i] = vyNew;
                vz[i] = vzNew;
                fluidX[i] = K * (gasVx[i] - vxNew) + extraFx[i];
                fluidY[i] = K * (gasVy[i] - vyNew) + extraFy[i];
                fluidZ[i] = K * (gasVz[i] - vzNew) + extraFz[i];
                meanVx[i] += weight * vxNew;
                meanVy[i] += weight * vyNew;
                meanVz[i] += weight * vzNew;
            } else {
                vx[i] += h * (fx[i] * invM + gx);
                vy[i] += h * (fy[i] * invM + gy);
                vz[i] += h * (fz[i] * invM);
            }
            const double hI = h * invInertia[i];
            wx[i] += hI * txi;
            wy[i] += hI * tyi;
            wz[i] += hI * tzi;
        }
    }
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
    const double gx = settings_.gravity[0];
    const double gy = settings_.gravity[1];
    const Box& b = settings_.box;
    const double depth = settings_.slabDepth;
    SlabParticles& p = p_;
    // Plain pointers: a simd loop, which needs no alias checks.
    double* x = p.x.data();
    double* y = p.y.data();
    double* z = p.z.data();
    double* vx = p.vx.data();
    double* vy = p.vy.data();
    double* vz = p.vz.data();
    double* wx = p.wx.data();
    double* wy = p.wy.data();
    double* wz = p.wz.data();
    const double* fx = p.fx.data();
    const double* fy = p.fy.data();
    const double* fz = p.fz.data();
    const double* tx = p.tx.data();
    const double* ty = p.ty.data();
    const double* tz = p.tz.data();
    const double* fluidX = p.fluidX.data();
    const double* fluidY = p.fluidY.data();
    const double* fluidZ = p.fluidZ.data();
    const double* xRef = p.xRef.data();
    const double* yRef = p.yRef.data();
    const double* zRef = p.zRef.data();
    const double* invMass = p.invMass.data();
    const double* invInertia = p.invInertia.data();

    double maxDisplacement2 = 0.0;
    int lost = 0;
#pragma omp parallel for simd num_threads(settings_.nThreads) schedule(static) \
    reduction(max : maxDisplacement2) reduction(| : lost)
    for (Index i = 0; i < n; ++i) {
        const double invM = invMass[i];
        const double hI = h * invInertia[i];
        vx[i] += h * ((fx[i] + fluidX[i]) * invM + gx);
        vy[i] += h * ((fy[i] + fluidY[i]) * invM + gy);
        vz[i] += h * ((fz[i] + fluidZ[i]) * invM);
        wx[i] += hI * tx[i];
        wy[i] += hI * ty[i];
        wz[i] += hI * tz[i];
        x[i] += dt * vx[i];
        y[i] += dt * vy[i];
        z[i] += dt * vz[i];
        const double dx = x[i] - xRef[i];
        const double dy = y[i] - yRef[i];
        const double dz = z[i] - zRef[i];
        maxDisplacement2 = std::max(maxDisplacement2, dx * dx + dy * dy + dz * dz);
        // Written so that NaN counts as lost too (as inside()).
        lost |= !(x[i] >= b.xMin && x[i] <= b.xMax && y[i] >= b.yMin && y[i] <= b.yMax
                  && z[i] >= 0.0 && z[i] <= depth);
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
