#pragma once
// The DEM engine of the slab mode (Settings::dimension = 3): spheres between a front wall
// z = 0 and a back wall z = slabDepth and the box's walls around, with the contact kernel,
// the NBS search and the thread-independent pair blocks of the 2D engine.

#include "dem/ContactKernel.hpp"
#include "dem/ContactLaw.hpp"
#include "dem/ContactList.hpp"
#include "dem/Facade.hpp"
#include "dem/NbsSearch.hpp"

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace dem {

/// Infinite plane wall in any orientation.
struct PlaneWall3 {
    Eigen::Vector3d point;   ///< a point on the wall, m
    Eigen::Vector3d nHat;    ///< unit normal pointing into the domain

    /// Signed distance of p from the wall, positive inside the domain, m.
    double distance(const Eigen::Vector3d& p) const { return (p - point).dot(nHat); }
};

/// The walls of a slab: floor, right, ceiling, left (as boxWalls), front z = 0, back z = depth.
std::vector<PlaneWall3> slabWalls(const Box& box, double depth);

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
struct SlabPairList {
    std::vector<int> i, j;
    std::vector<int> law;
    std::vector<Eigen::Vector3d> xi;   ///< tangential spring displacement, m
    std::vector<int> groupStart;
    std::size_t size() const { return i.size(); }
};

/// Particle-wall candidates grouped by particle, as WallList.
struct SlabWallList {
    std::vector<int> start;
    std::vector<int> wall;
    std::vector<Eigen::Vector3d> xi;
    std::size_t size() const { return wall.size(); }
};

/// Soft-sphere DEM of spheres in a slab; the step is System's (velocity Verlet, dashpots fed
/// by the half-step velocity, the drag implicit), with 3-vectors.
class SlabSystem {
public:
    explicit SlabSystem(const Settings& settings);

    const Settings& settings() const { return settings_; }
    SlabParticles& particles() { return p_; }
    const SlabParticles& particles() const { return p_; }
    const std::vector<PlaneWall3>& walls() const { return walls_; }

    /// Adds a wall through `point` with normal `normal` (normalised here) pointing into the
    /// domain; walls added later come after the slab's six.
    void addWall(const Eigen::Vector3d& point, const Eigen::Vector3d& normal);
    /// Throws if the sphere pokes through a wall or overlaps a particle by more than 1 % of d.
    void addParticle(int cls, const Eigen::Vector3d& pos, const Eigen::Vector3d& vel,
                     const Eigen::Vector3d& spin = Eigen::Vector3d::Zero());
    /// Random sequential addition in region x [0, slabDepth], largest class first.
    void packRandom(const std::vector<int>& countPerClass, const Box& region, std::uint64_t seed);
    /// packRandom then settle into an empty slab, as `recipe` says; the recipe is kept and
    /// saved with the state. Returns the settling time spent, s.
    double packBed(const BedRecipe& recipe);

    void step(bool fluid);
    void advance(double dtOuter);
    double settle(double maxTime, double keTolerance);

    double time() const { return static_cast<double>(stepCount_) * settings_.dt; }
    std::int64_t stepCount() const { return stepCount_; }
    double kineticEnergy() const;
    double elasticEnergy() const;
    std::size_t contactCount() const { return contactCount_; }
    double maxOverlap() const { return maxOverlap_; }
    std::int64_t neighbourListBuilds() const { return listBuilds_; }
    double neighbourSkin() const { return skin_; }
    /// Heap memory held by particle, contact and search arrays, bytes.
    std::size_t memoryBytes() const;
    /// Force the particles exert on wall w at the current state (dashpots at the current
    /// velocity, histories as stored), N.
    Eigen::Vector3d wallForce(int w) const;
    /// The search's candidate pairs of the last build (for tests).
    const SlabPairList& pairList() const { return pairs_; }
    void rebuildNeighbourList();

    /// Whole state, contact history included, in a file of its own kind (not the 2D one).
    void save(const std::string& path) const;
    /// Reads a state written by save() with the same settings; throws dem::Error otherwise.
    void load(const std::string& path);
    /// load(), after checking the file's bed against `recipe` (the file's recipe, or its
    /// counts per class if it has none: then returns false); throws naming every entry that
    /// differs, leaving this slab untouched.
    bool loadBed(const std::string& path, const BedRecipe& recipe);
    /// How the particles were made (packBed, or the file they came from); none otherwise.
    const BedRecipe* recipe() const { return recipe_ ? &*recipe_ : nullptr; }

private:
    void buildLaws();
    void ensureReady();
    void computePairForces(double historyDt);
    void addWallForcesAndKick(double historyDt, bool kick, bool fluid);
    void setFluidForceAtCurrentVelocity(bool fluid);
    bool inside(std::size_t i) const;
    [[noreturn]] void throwLostParticle() const;

    Settings settings_;
    int nClasses_;
    double skin_;
    std::vector<PlaneWall3> walls_;
    std::vector<ContactLaw> pairLaws_;
    std::vector<ContactLaw> wallLaws_;
    SlabParticles p_;
    SlabPairList pairs_;
    SlabWallList wallContacts_;
    NbsSearch search_;
    std::vector<IndexPair> found_;

    std::int64_t stepCount_ = 0;
    std::int64_t listBuilds_ = 0;
    bool listValid_ = false;
    bool forcesValid_ = false;
    std::size_t contactCount_ = 0;
    double maxOverlap_ = 0.0;
    double meanWeight_ = 1.0;
    std::optional<BedRecipe> recipe_;
};

} // namespace dem
