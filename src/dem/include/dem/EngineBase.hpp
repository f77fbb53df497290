// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the 2D engine (System, discs) and the slab engine (SlabSystem, spheres) share, written
// once: the contact-law tables, the neighbour list (search, history carried over, pair groups,
// wall candidates, the skin), the step's structure and the CFD step's sub-step loop.
// Templated on the engine (CRTP) and on its Traits: the particle arrays, the wall type, the
// contact history (a scalar along tHat in 2D, a 3-vector in 3D) and the few per-dimension
// expressions. Each engine keeps what differs: the drift, the pair and wall forces with the
// second half-kick (disc against sphere kinematics), the packing and the state file, and
// its walls as the list build tests them (wallCount(), wallDistance(w, x)).
//
// Traits provide:
//   using Particles, Wall, History;
//   static position(p, i)                       Eigen vector of particle i
//   static findPairs(search, p, skin, found, nThreads)
//   static bool isZero(const History&), static zeroHistory()
//   static swapped(const History&)              the history of pair (i, j) seen as (j, i)
//   static axes(p)                              per axis: pointers to x, xRef, v, gasV,
//                                               extraF, fluid, meanV, meanFluid (AxisArrays)

#include "dem/ContactKernel.hpp"
#include "dem/ContactLaw.hpp"
#include "dem/ContactList.hpp"
#include "dem/Facade.hpp"
#include "dem/NbsSearch.hpp"
#include "dem/ThreadChooser.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace dem {

/// Checks every setting, throwing dem::Error naming the first bad one.
void validateSettings(const Settings& settings);

/// The names of a pair of classes' and of a class-wall contact's own coefficients in
/// messages: "contact pair 'small-large'" (in the order of ContactSettings::pairs if given
/// there), "contact wall 'large'".
std::string pairName(const Settings& settings, int a, int b);
std::string wallName(const Settings& settings, int a);

/// The part of validateSettings that checks dt against the step bounds (timeStepBound,
/// dashpotTimeStep), for settings otherwise valid.
void checkTimeStep(const Settings& settings);

/// The DEM steps of dt in one CFD step dtOuter; dem::Error unless a positive whole number
/// (relative tolerance 1e-9).
long subStepCount(double dtOuter, double dt);

/// The class indices, largest (mean) diameter first (equal diameters in their order): the
/// order in which a random packing places them.
std::vector<int> classesLargestFirst(const Settings& settings);

/// The n diameters of class k a random packing of seed `seed` places after the first
/// drawnBefore of the class's drawClassDiameters (the placed particles'), largest first.
std::vector<double> restOfClass(const ParticleClass& c, int k, int drawnBefore, int n,
                                std::uint64_t seed);

/// The arrays of one axis of the particles, for the loops that treat every axis alike.
struct AxisArrays {
    std::vector<double>* x;          ///< position, m
    std::vector<double>* xRef;       ///< position at the last list build, m
    std::vector<double>* v;          ///< velocity, m/s
    std::vector<double>* gasV;       ///< m/s
    std::vector<double>* extraF;     ///< N
    std::vector<double>* fluid;      ///< fluid force at the current velocity, N
    std::vector<double>* meanV;      ///< sub-step mean of the last CFD step, m/s
    std::vector<double>* meanFluid;  ///< N
};

/// The shared part of an engine Derived (System or SlabSystem).
///
/// One step (velocity Verlet, second order):
///   v_half = v + dt/2 a(t);  x += dt v_half;  (rebuild neighbour list if needed)
///   contact forces at x(t+dt) with the dashpots fed by v_half (first order in the
///   damping only; the restitution test bounds the effect);
///   v(t+dt) = v_half + dt/2 a(t+dt), where the linear fluid drag K (u - v(t+dt)) is taken
///   implicitly (trapezoidal in the drag, so stiff drag cannot destabilise the step).
template <class Derived, class Traits>
class EngineBase {
public:
    using ParticleArrays = typename Traits::Particles;
    using Wall = typename Traits::Wall;
    using History = typename Traits::History;

    const Settings& settings() const { return settings_; }
    ParticleArrays& particles() { return p_; }
    const ParticleArrays& particles() const { return p_; }
    const std::vector<Wall>& walls() const { return walls_; }

    /// The recipe's placed particles (layPlacedParticles), Derived::packRest of the rest,
    /// then settle into an empty box as `recipe` says, every law's sliding friction the
    /// recipe's settleFriction meanwhile if set (the laws' own after); the recipe is kept and
    /// saved with the state. Returns the settling time spent, s.
    double packBed(const BedRecipe& recipe, const SettleProgress& progress = {});
    /// One DEM step; with fluid = false the fluid inputs are ignored.
    void step(bool fluid);
    /// The sub-steps of one CFD step of dtOuter, with the sub-step means of the velocity
    /// and the fluid force.
    void advance(double dtOuter);
    /// Steps without fluid until at rest (kinetic energy per particle below keTolerance and
    /// falling) or maxTime; returns the time spent, s. progress(time spent, kinetic energy
    /// per particle) at each check, if given.
    double settle(double maxTime, double keTolerance, const SettleProgress& progress = {});
    void rebuildNeighbourList();
    /// Renumbers the particles in the order of the search cells (row by row), so that
    /// neighbours sit close in memory; contact history and forces move with them.
    void sortByCell();

    double time() const { return static_cast<double>(stepCount_) * settings_.dt; }
    std::int64_t stepCount() const { return stepCount_; }
    std::size_t contactCount() const { return contactCount_; }
    double maxOverlap() const { return maxOverlap_; }
    std::int64_t neighbourListBuilds() const { return listBuilds_; }
    /// The Verlet skin of the current neighbour list, m.
    double neighbourSkin() const { return skin_; }
    /// The threads the next loops run on: Settings::nThreads, or with measureThreads the
    /// team ThreadChooser picked for the current CFD step.
    int threads() const { return threads_; }
    /// The team the next advance() runs on (Simulation::nextStepThreads).
    int nextStepThreads() const
    {
        return settings_.measureThreads && settings_.nThreads > 1 ? threadChooser_.next()
                                                                   : settings_.nThreads;
    }
    /// With measureThreads: the CFD steps advanced on one thread and on nThreads so far.
    const ThreadChooser& threadChooser() const { return threadChooser_; }
    /// The diameter the search's cells are sized by (with the skin): the largest, unless the
    /// largest particles are few (at most largeFraction of all and maxLarge) and more than
    /// largeRatio times any other: the search then tests those against every particle and
    /// sizes the cells by the rest (an intruder in a bed of beads, whose cells would
    /// otherwise hold tens of beads each).
    /// Computed from the particles at each list build and each sort by cell.
    double searchCellDiameter() const;
    static constexpr double largeRatio = 1.5;
    static constexpr double largeFraction = 0.01;
    static constexpr int maxLarge = 64;   // their n tests each stay below the grid's cost
    /// How the particles were made (packBed, or the file they came from); none otherwise.
    const BedRecipe* recipe() const { return recipe_ ? &*recipe_ : nullptr; }
    /// The caller's record of the run (its models), saved with the state; load() sets the file's.
    const std::string& runRecord() const { return runRecord_; }
    void setRunRecord(const std::string& record) { runRecord_ = record; }

protected:
    /// `settings` validated; the skin Settings::neighbourSkin if >= 0, else startFraction
    /// d_min, adaptive if `adaptive`.
    EngineBase(const Settings& settings, std::vector<Wall> walls, double startFraction,
               bool adaptive);

    Derived& derived() { return static_cast<Derived&>(*this); }
    const Derived& derived() const { return static_cast<const Derived&>(*this); }

    void ensureReady();
    /// The adaptive skin's choice before a build in step(): from the fastest particle's
    /// displacement since the last build (maxDisplacement2, m^2).
    void adaptSkin(double maxDisplacement2);
    /// Sets the skin and the search cells that fit it.
    void setSkin(double skin);
    /// Sizes the search cells by searchCellDiameter() of the particles at hand. The list
    /// build and the sort by cell both call it, so that the cells (and so the sort's order)
    /// are a function of the particles and the skin alone: the same after a load as in
    /// the run that saved the state.
    void fitSearchCells();
    void setFluidForceAtCurrentVelocity(bool fluid);
    /// body(Law{}, std::bool_constant<Rolling>{}) with the contact law's policy (withLaw) and
    /// the rolling resistance of the settings: the engines' contact loops are compiled once
    /// per law and chosen here once per loop, not per contact.
    template <class Body>
    void withContactLaw(const Body& body) const
    {
        withLaw(settings_.contact.law, [&](auto law) {
            if (rolling_) body(law, std::true_type{});
            else body(law, std::false_type{});
        });
    }
    /// body(first, last) on each thread for its share of the particles.
    template <class Body>
    void forEachShare(const Body& body);
    void checkClass(int cls) const;
    /// Heap memory of the search and the contact lists, bytes.
    std::size_t listMemoryBytes() const;

    // The adaptive skin (Settings::neighbourSkin < 0 in 2D), chosen at each build from the
    // fastest particle's displacement per step u since the last build. A skin s costs a build
    // every s/(2u) steps and candidate pairs in proportion to s, so the cost per step,
    // b s + 2 c u/s, is least at s = sqrt(2 c u/b) = sqrt(skinCostRatio d_min u); the ratio
    // makes about 0.6 mm in the solver's bubbling bed (u ~ 1.2e-5 m per step) and the
    // narrowest skin in a bed at rest. No fixed skin ran faster (docs/performance.md, NETL's
    // column; DEM_BENCH_SKIN in BenchSolverBed times others). Within [0.1, 0.8] d_min.
    static constexpr double skinCostRatio = 20.0;          // 2 c / (b d_min)
    static constexpr std::int64_t skinRecheckAfter = 100;  // steps without a build: build, to narrow
    static constexpr double skinMinFraction = 0.1;         // of d_min
    static constexpr double skinMaxFraction = 0.8;

    Settings settings_;
    int threads_;                        // the team of the parallel loops (threads())
    ThreadChooser threadChooser_;
    int nClasses_;
    double smallestDiameter_, largestDiameter_;
    double cellDiameter_;                // searchCellDiameter() at the last fitSearchCells()
    double skin_;
    bool adaptiveSkin_;
    double skinMin_, skinMax_;           // bounds of the adaptive skin, m
    std::vector<Wall> walls_;
    std::vector<ContactLaw> pairLaws_;   // nClasses x nClasses
    std::vector<ContactLaw> wallLaws_;   // per class
    bool rolling_ = false;               // some law has rolling resistance: its loops run
    ParticleArrays p_;
    PairListT<History> pairs_;
    WallListT<History> wallContacts_;
    NbsSearch search_;
    std::vector<IndexPair> found_;       // scratch of the search
    std::vector<int> rebuildScratch_;    // where each found pair goes in the list
    std::vector<int> blockScratch_;      // the pair block of each particle

    std::int64_t stepCount_ = 0;
    std::int64_t listBuilds_ = 0;
    std::int64_t lastBuildStep_ = -1;    // stepCount_ at the last build; -1: unknown
    bool listValid_ = false;
    bool forcesValid_ = false;
    std::size_t contactCount_ = 0;
    double maxOverlap_ = 0.0;
    double meanWeight_ = 1.0;           // weight of this sub-step's velocity in the CFD-step mean
    std::optional<BedRecipe> recipe_;   // how the particles were made, if packBed made them
    std::string runRecord_;             // see runRecord()
};

} // namespace dem
