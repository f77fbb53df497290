// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The 2D DEM engine behind the facade: discs-as-spheres in the x-y plane, on EngineBase (the
// step, the sub-steps, the neighbour list) with the disc's drift, pair and wall forces and
// kick, the packing, the renumbering by cell and the state file.

#include "dem/ContactKernel.hpp"
#include "dem/EngineBase.hpp"
#include "dem/Particles.hpp"
#include "dem/PlaneWall.hpp"

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace dem {

/// What EngineBase needs of the 2D mode: spin, torque and the tangential history are
/// scalars (about z, along tHat = ez x nHat).
struct DiscTraits {
    using Particles = dem::Particles;
    using Wall = PlaneWall;
    using History = double;

    static Eigen::Vector2d position(const Particles& p, std::size_t i)
    {
        return Eigen::Vector2d(p.x[i], p.y[i]);
    }
    static void findPairs(NbsSearch& search, const Particles& p, double skin,
                          std::vector<IndexPair>& found, int nThreads)
    {
        search.findPairs(p.x.data(), p.y.data(), p.radius.data(), p.size(), skin, found, nThreads);
    }
    static bool isZero(double xi) { return xi == 0.0; }
    static double zeroHistory() { return 0.0; }
    /// Symmetric: swapping i and j flips both nHat and the relative velocity, so the
    /// displacement along tHat (vRel . tHat summed) is unchanged.
    static double swapped(double xi) { return xi; }
    static std::array<AxisArrays, 2> axes(Particles& p)
    {
        return {{{&p.x, &p.xRef, &p.vx, &p.gasVx, &p.extraFx, &p.fluidX, &p.meanVx, &p.meanFluidX},
                 {&p.y, &p.yRef, &p.vy, &p.gasVy, &p.extraFy, &p.fluidY, &p.meanVy, &p.meanFluidY}}};
    }
};

/// Soft-sphere DEM of discs-as-spheres in the x-y plane; the step is EngineBase's.
class System : public EngineBase<System, DiscTraits> {
public:
    explicit System(const Settings& settings);

    void addParticle(int cls, double x, double y, double vx, double vy, double omega);
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
    double timeStepBound() const { return timeStepBound_; }
    std::size_t memoryBytes() const;

    void save(const std::string& path) const;
    void load(const std::string& path);
    bool loadBed(const std::string& path, const BedRecipe& recipe);

private:
    friend class EngineBase<System, DiscTraits>;
    friend class StateFile;

    /// First half-kick and drift of every particle; returns the largest squared
    /// displacement since the last list build, m^2; throws if a particle left the box.
    double drift();
    /// Sums each particle's pair forces (parallel over blocks of pairs, each pair once, in
    /// an order that does not depend on the thread count).
    void computePairForces(double historyDt);
    /// Adds the wall contacts to the pair sums and does the second half-kick (kick = false:
    /// only the forces, for the first evaluation).
    void addWallForcesAndKick(double historyDt, bool kick, bool fluid);
    /// The two loops with or without rolling resistance, chosen once per step.
    template <class Law, bool Rolling> void sumPairForces(double historyDt);
    template <class Law, bool Rolling> void addWallForcesAndKickWith(double historyDt, bool kick, bool fluid);
    /// With rolling resistance, after the pair forces: each particle's rolling scale from
    /// its pair and wall contacts (RollingLimit.hpp), then the pairs' rolling torques scaled
    /// and added; the walls' are scaled in the wall loop.
    void limitRollingTorques();
    [[noreturn]] void throwLostParticle() const;
    /// The walls the neighbour list tests (EngineBase): the box's.
    int wallCount() const { return static_cast<int>(walls_.size()); }
    double wallDistance(int w, const Eigen::Vector2d& p) const { return walls_[w].distance(p); }

    static constexpr double skinStartFraction = 0.4;   // of d_min, the adaptive skin's start

    double timeStepBound_;
    std::vector<int> touchingScratch_;   // the touching pairs of each group, per step
    std::vector<int> touchingPerGroup_;  // how many of each group's pairs touch, per step
    std::vector<double> pairRolling_;    // each touching pair's rolling torque, N m (rolling only)
    std::vector<double> rollingScale_;   // each particle's D_i, then s_i (RollingLimit.hpp)
};

} // namespace dem
