// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The DEM engine of the slab mode (Settings::dimension = 3): spheres between a front wall
// z = 0 and a back wall z = slabDepth and the box's walls around, or within the planes and
// cylinders of Settings::walls, with the contact kernel, on EngineBase as the 2D engine
// (step, sub-steps, neighbour list), with the sphere's drift, pair and wall forces and kick,
// the packing and the state file.

#include "dem/ContactKernel.hpp"
#include "dem/CylinderWall.hpp"
#include "dem/EngineBase.hpp"
#include "dem/PlaneWall.hpp"

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace dem {

/// The walls of a slab: floor, right, ceiling, left (as boxWalls), front z = 0, back z = depth.
std::vector<PlaneWall3> slabWalls(const Box& box, double depth);

/// The plane walls of the settings: the slab's six if Settings::walls is empty, else its
/// planes in their order (normals made unit).
std::vector<PlaneWall3> planeWalls(const Settings& settings);
/// The cylinder walls of Settings::walls in their order (axes made unit).
std::vector<CylinderWall> cylinderWalls(const Settings& settings);

/// Per-particle arrays of the slab, structure of arrays as Particles.
struct SlabParticles {
    std::vector<double> x, y, z;              ///< position, m
    std::vector<double> vx, vy, vz;           ///< velocity, m/s
    std::vector<double> wx, wy, wz;           ///< spin, rad/s
    std::vector<double> radius, diameter, mass, invMass;
    std::vector<double> invInertia;           ///< 1/(kg m^2), I = m d^2/10
    std::vector<int> classIndex;
    std::vector<std::int64_t> id;
    std::vector<double> fx, fy, fz;           ///< contact force of the last evaluation, N
    std::vector<double> tx, ty, tz;           ///< contact torque, N m
    std::vector<double> fluidX, fluidY, fluidZ;   ///< fluid force at the current velocity, N
    std::vector<double> xRef, yRef, zRef;     ///< position at the last neighbour-list build
    std::vector<double> dragCoefficient;      ///< N s/m
    std::vector<double> gasVx, gasVy, gasVz;  ///< m/s
    std::vector<double> extraFx, extraFy, extraFz;   ///< N
    std::vector<double> meanVx, meanVy, meanVz;      ///< sub-step mean of the last CFD step
    std::vector<double> meanFluidX, meanFluidY, meanFluidZ;

    std::size_t size() const { return x.size(); }
    Eigen::Vector3d position(std::size_t i) const { return {x[i], y[i], z[i]}; }
    Eigen::Vector3d velocity(std::size_t i) const { return {vx[i], vy[i], vz[i]}; }
    Eigen::Vector3d spin(std::size_t i) const { return {wx[i], wy[i], wz[i]}; }

    void append(int cls, double diam, double density, const Eigen::Vector3d& pos,
                const Eigen::Vector3d& vel, const Eigen::Vector3d& spin);

    template <class F> void forEachArray(F&& f)
    {
        f(x); f(y); f(z); f(vx); f(vy); f(vz); f(wx); f(wy); f(wz);
        f(radius); f(diameter); f(mass); f(invMass); f(invInertia); f(classIndex); f(id);
        f(fx); f(fy); f(fz); f(tx); f(ty); f(tz); f(fluidX); f(fluidY); f(fluidZ);
        f(xRef); f(yRef); f(zRef); f(dragCoefficient); f(gasVx); f(gasVy); f(gasVz);
        f(extraFx); f(extraFy); f(extraFz); f(meanVx); f(meanVy); f(meanVz);
        f(meanFluidX); f(meanFluidY); f(meanFluidZ);
    }
    template <class F> void forEachArray(F&& f) const
    {
        const_cast<SlabParticles*>(this)->forEachArray([&](const auto& a) { f(a); });
    }
};

/// Pair candidates with their 3-vector tangential history; order and groups as PairList.
using SlabPairList = PairListT<Eigen::Vector3d>;
/// Particle-wall candidates grouped by particle, as WallList.
using SlabWallList = WallListT<Eigen::Vector3d>;

/// What EngineBase needs of the slab: spin, torque and the tangential history are 3-vectors.
struct SphereTraits {
    using Particles = SlabParticles;
    using Wall = PlaneWall3;
    using History = Eigen::Vector3d;

    static Eigen::Vector3d position(const Particles& p, std::size_t i) { return p.position(i); }
    static void findPairs(NbsSearch& search, const Particles& p, double skin,
                          std::vector<IndexPair>& found, int nThreads)
    {
        search.findPairs(p.x.data(), p.y.data(), p.z.data(), p.radius.data(), p.size(), skin,
                         found, nThreads);
    }
    static bool isZero(const Eigen::Vector3d& xi) { return xi.isZero(0.0); }
    static Eigen::Vector3d zeroHistory() { return Eigen::Vector3d::Zero(); }
    /// Odd: the displacement sums v_i - v_j at the contact point, which a swap negates.
    static Eigen::Vector3d swapped(const Eigen::Vector3d& xi) { return -xi; }
    static std::array<AxisArrays, 3> axes(Particles& p)
    {
        return {{{&p.x, &p.xRef, &p.vx, &p.gasVx, &p.extraFx, &p.fluidX, &p.meanVx, &p.meanFluidX},
                 {&p.y, &p.yRef, &p.vy, &p.gasVy, &p.extraFy, &p.fluidY, &p.meanVy, &p.meanFluidY},
                 {&p.z, &p.zRef, &p.vz, &p.gasVz, &p.extraFz, &p.fluidZ, &p.meanVz, &p.meanFluidZ}}};
    }
};

/// Soft-sphere DEM of spheres in a slab; the step is EngineBase's (velocity Verlet, dashpots
/// fed by the half-step velocity, the drag implicit), with 3-vectors. Its skin is
/// Settings::neighbourSkin, or adaptive as System's if that is negative.
class SlabSystem : public EngineBase<SlabSystem, SphereTraits> {
public:
    explicit SlabSystem(const Settings& settings);

    /// Adds a plane wall through `point` with normal `normal` (normalised here) pointing into
    /// the domain, after the planes of the settings (walls()).
    void addWall(const Eigen::Vector3d& point, const Eigen::Vector3d& normal);
    /// Throws if the sphere pokes through a wall or overlaps a particle by more than 1 % of d.
    void addParticle(int cls, const Eigen::Vector3d& pos, const Eigen::Vector3d& vel,
                     const Eigen::Vector3d& spin = Eigen::Vector3d::Zero());
    /// Random sequential addition in region x [0, slabDepth], largest class first.
    void packRandom(const std::vector<int>& countPerClass, const Box& region, std::uint64_t seed);
    /// packRandom with each class's diameters after the first drawnBefore[k] of its stream
    /// (those of the placed particles, which count toward a class: a count may be 0 then).
    void packRest(const std::vector<int>& countPerClass, const Box& region, std::uint64_t seed,
                  const std::vector<int>& drawnBefore);
    /// Appends a particle of class cls and diameter d at rest at `position` (packBed's placed
    /// particles, checked there).
    void appendAtRest(int cls, double d, const Vector3& position);

    double kineticEnergy() const;
    double elasticEnergy() const;
    /// Heap memory held by particle, contact and search arrays, bytes.
    std::size_t memoryBytes() const;
    /// Force the particles exert on wall w at the current state (dashpots at the current
    /// velocity, histories as stored), N.
    Eigen::Vector3d wallForce(int w) const;

    /// The cylinder walls (cylinderWalls of the settings).
    const std::vector<CylinderWall>& cylinders() const { return cylinders_; }
    /// The walls of the contact lists and of wallForce: the planes (walls()) as w = 0, 1,
    /// ..., then the cylinders.
    int wallCount() const { return static_cast<int>(walls_.size() + cylinders_.size()); }
    /// Where p stands against wall w: the one geometry of every wall loop.
    WallSide wallSide(int w, const Eigen::Vector3d& p) const
    {
        const int planes = static_cast<int>(walls_.size());
        return w < planes ? planeSide(walls_[w], p) : cylinders_[w - planes].side(p);
    }
    /// wallSide(w, p).distance, alone (the list build's and the touching test's).
    double wallDistance(int w, const Eigen::Vector3d& p) const
    {
        const int planes = static_cast<int>(walls_.size());
        return w < planes ? walls_[w].distance(p) : cylinders_[w - planes].distance(p);
    }
    /// The search's candidate pairs of the last build (for tests).
    const SlabPairList& pairList() const { return pairs_; }

    /// Whole state, contact history included, in a file of its own kind (not the 2D one).
    void save(const std::string& path) const;
    /// Reads a state written by save() with the same settings; throws dem::Error otherwise.
    void load(const std::string& path);
    /// load(), after checking the file's bed against `recipe` (the file's recipe, or its
    /// counts per class if it has none: then returns false); throws naming every entry that
    /// differs, leaving this slab untouched.
    bool loadBed(const std::string& path, const BedRecipe& recipe);

private:
    friend class EngineBase<SlabSystem, SphereTraits>;

    double drift();
    void computePairForces(double historyDt);
    void addWallForcesAndKick(double historyDt, bool kick, bool fluid);
    /// The two loops with or without rolling resistance, chosen once per step.
    template <class Law, bool Rolling> void sumPairForces(double historyDt);
    template <class Law, bool Rolling> void addWallForcesAndKickWith(double historyDt, bool kick, bool fluid);
    [[noreturn]] void throwLostParticle() const;

    struct WallPick {
        int slot;       // in the wall list
        int particle;
    };
    /// The touching wall contacts picked[0, m) without rolling resistance, in batches by
    /// the vectorised kernel, added in their order.
    template <class Law>
    void batchedWallForces(const WallPick* picked, int m, double historyDt,
                           std::size_t& touching, double& maxOverlap);

    /// With rolling resistance, after the pair forces: as System's (RollingLimit.hpp).
    void limitRollingTorques();

    std::vector<CylinderWall> cylinders_;   // after the planes in the wall index (wallCount)
    std::vector<int> touchingScratch_;   // the touching pairs of each group, per step
    std::vector<WallPick> wallPicks_;    // the touching wall contacts, per step
    std::vector<int> touchingPerGroup_;  // how many of each group's pairs touch, per step
    std::vector<Eigen::Vector3d> pairRolling_;   // each touching pair's rolling torque, N m
    std::vector<double> rollingScale_;   // each particle's D_i, then s_i (RollingLimit.hpp)
};

} // namespace dem
