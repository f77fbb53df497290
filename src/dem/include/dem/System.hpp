#pragma once
// The DEM engine behind the facade: particles, walls, contact laws, the NBS neighbour list
// and the velocity-Verlet stepper.

#include "dem/ContactKernel.hpp"
#include "dem/ContactList.hpp"
#include "dem/ContactLaw.hpp"
#include "dem/Facade.hpp"
#include "dem/NbsSearch.hpp"
#include "dem/Particles.hpp"
#include "dem/PlaneWall.hpp"

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace dem {

/// Checks every setting, throwing dem::Error naming the first bad one.
void validateSettings(const Settings& settings);

/// Eq. 7 time-step bound (2 pi/5) sqrt(m_min/kn) over the classes, s; smallest class in `cls`.
double timeStepBound(const Settings& settings, int* smallestClass = nullptr);

/// The DEM steps of dt in one CFD step dtOuter; dem::Error unless a positive whole number
/// (relative tolerance 1e-9).
long subStepCount(double dtOuter, double dt);

/// The class indices, largest diameter first (equal diameters in their order): the order
/// in which a random packing places them.
std::vector<int> classesLargestFirst(const Settings& settings);

/// Soft-sphere DEM of discs-as-spheres in the x-y plane.
///
/// One step (velocity Verlet, second order):
///   v_half = v + dt/2 a(t);  x += dt v_half;  (rebuild neighbour list if needed)
///   contact forces at x(t+dt) with the dashpots fed by v_half (first order in the
///   damping only; the restitution test bounds the effect);
///   v(t+dt) = v_half + dt/2 a(t+dt), where the linear fluid drag K (u - v(t+dt)) is taken
///   implicitly (trapezoidal in the drag, so stiff drag cannot destabilise the step).
class System {
public:
    explicit System(const Settings& settings);

    const Settings& settings() const { return settings_; }
    Particles& particles() { return p_; }
    const Particles& particles() const { return p_; }
    const std::vector<PlaneWall>& walls() const { return walls_; }

    void addParticle(int cls, double x, double y, double vx, double vy, double omega);
    void packRandom(const std::vector<int>& countPerClass, const Box& region, std::uint64_t seed);
    double packBed(const BedRecipe& recipe);

    void advance(double dtOuter);
    /// Renumbers the particles in the order of the search cells (row by row), so that
    /// neighbours sit close in memory; contact history and forces move with them.
    void sortByCell();
    double settle(double maxTime, double keTolerance);
    /// One DEM step; with fluid = false the fluid inputs are ignored.
    void step(bool fluid);

    double time() const { return static_cast<double>(stepCount_) * settings_.dt; }
    std::int64_t stepCount() const { return stepCount_; }
    double kineticEnergy() const;
    double elasticEnergy() const;
    double timeStepBound() const { return timeStepBound_; }
    std::size_t contactCount() const { return contactCount_; }
    double maxOverlap() const { return maxOverlap_; }
    std::int64_t neighbourListBuilds() const { return listBuilds_; }
    /// The Verlet skin of the current neighbour list, m.
    double neighbourSkin() const { return skin_; }
    std::size_t memoryBytes() const;

    void save(const std::string& path) const;
    void load(const std::string& path);
    bool loadBed(const std::string& path, const BedRecipe& recipe);
    const BedRecipe* recipe() const { return recipe_ ? &*recipe_ : nullptr; }

private:
    void buildLaws();
    void rebuildNeighbourList();
    /// The adaptive skin's choice before a build in step(): from the fastest particle's
    /// displacement since the last build (maxDisplacement2, m^2).
    void adaptSkin(double maxDisplacement2);
    /// Sets the skin and the search cells that fit it.
    void setSkin(double skin);
    void ensureReady();
    /// Sums each particle's pair forces (parallel over blocks of pairs, each pair once, in
    /// an order that does not depend on the thread count).
    void computePairForces(double historyDt);
    /// Adds the wall contacts to the pair sums and does the second half-kick (kick = false:
    /// only the forces, for the first evaluation).
    void addWallForcesAndKick(double historyDt, bool kick, bool fluid);
    /// The second half-kick of particles [first, last).
    template <bool Fluid>
    void kickLoop(std::ptrdiff_t first, std::ptrdiff_t last, double h, double gx, double gy,
                  double weight);
    void setFluidForceAtCurrentVelocity(bool fluid);
    [[noreturn]] void throwLostParticle() const;
    const ContactLaw& pairLaw(int ci, int cj) const { return pairLaws_[ci * nClasses_ + cj]; }

    // The adaptive skin (Settings::neighbourSkin < 0), chosen at each build from the fastest
    // particle's displacement per step u since the last build. A skin s costs a build every
    // s/(2u) steps and candidate pairs in proportion to s, so the cost per step, b s + 2 c u/s,
    // is least at s = sqrt(2 c u/b) = sqrt(skinCostRatio d_min u); the ratio makes 0.6 mm in
    // the solver's bubbling bed (u ~ 1.2e-5 m per step), where fixed skins of 0.45-1.0 mm ran
    // alike and 0.15 mm 30 % slower, while a bed at rest goes to the narrowest skin
    // (docs/performance.md, sessions 9 and 10). Within [0.1, 0.8] d_min.
    static constexpr double skinCostRatio = 20.0;          // 2 c / (b d_min)
    static constexpr std::int64_t skinRecheckAfter = 100;  // steps without a build: build, to narrow
    static constexpr double skinMinFraction = 0.1;         // of d_min
    static constexpr double skinMaxFraction = 0.8;
    static constexpr double skinStartFraction = 0.4;

    Settings settings_;
    int nClasses_;
    double timeStepBound_;
    double skin_;
    bool adaptiveSkin_;                  // Settings::neighbourSkin < 0
    double skinMin_, skinMax_;           // bounds of the adaptive skin, m
    double smallestDiameter_, largestDiameter_;
    std::vector<PlaneWall> walls_;
    std::vector<ContactLaw> pairLaws_;   // nClasses x nClasses
    std::vector<ContactLaw> wallLaws_;   // per class
    Particles p_;
    PairList pairs_;
    WallList wallContacts_;
    NbsSearch search_;
    std::vector<IndexPair> found_;       // scratch of the search
    std::vector<int> rebuildScratch_;    // where each found pair goes in the list
    std::vector<int> blockScratch_;      // the pair block of each particle
    std::vector<int> touchingScratch_;   // the touching pairs of each group, per step

    std::int64_t stepCount_ = 0;
    std::int64_t listBuilds_ = 0;
    std::int64_t lastBuildStep_ = -1;    // stepCount_ at the last build; -1: unknown
    bool listValid_ = false;
    bool forcesValid_ = false;
    std::size_t contactCount_ = 0;
    double maxOverlap_ = 0.0;
    double meanWeight_ = 1.0;           // weight of this sub-step's velocity in the CFD-step mean
    std::optional<BedRecipe> recipe_;   // how the particles were made, if packBed made them

    friend class StateFile;
};

} // namespace dem
