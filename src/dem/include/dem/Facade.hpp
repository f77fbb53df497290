// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The DEM library as the OpenFOAM side sees it: plain settings structs and plain
// particle arrays. Deliberately free of Eigen so that wmake code can include it.

#include "dem/Diameters.hpp"
#include "dem/Error.hpp"
#include "dem/StepBounds.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace dem {

/// One size class of particles.
struct ParticleClass {
    std::string name;
    double diameter;   ///< m: every particle's (not read with a distribution: meanDiameter)
    double density;    ///< kg/m^3
    double youngsModulus = 0.0;   ///< Pa, > 0 under HertzMindlin (not read by the linear law)
    double poissonRatio = 0.0;    ///< in (-1, 0.5] under HertzMindlin
    /// The particles' diameters drawn from a distribution when a bed is packed (single: all
    /// `diameter`). The class's contact laws take the coefficients of its meanDiameter, the
    /// step bounds its smallestDiameter, the neighbour search its largestDiameter
    /// (Diameters.hpp; docs/theory/dem.md, "Diameter distributions").
    DiameterDistribution distribution{};
};

/// The contact law, chosen once for every contact (model.md): the paper's linear
/// spring-dashpot, or Hertz-Mindlin from the materials' Young's moduli and Poisson's ratios.
enum class ContactLawType { linear, hertzMindlin };

/// "linear" or "HertzMindlin".
std::string contactLawName(ContactLawType law);
/// The law of that name; dem::Error naming the allowed names otherwise.
ContactLawType contactLawFromName(const std::string& name);

/// The coefficients of one pair of classes that replace the global ones of ContactSettings
/// (those not given keep them): LIGGGHTS' per-type-pair coefficients.
struct PairContactSettings {
    int classA = 0;                            ///< index into Settings::classes
    int classB = 0;                            ///< the other class (either order; may be classA)
    std::optional<double> restitution;         ///< in (0, 1]
    std::optional<double> frictionParticle;    ///< sliding friction, >= 0
    std::optional<double> rollingFriction;     ///< rolling resistance mu_r, >= 0
};

/// The coefficients of one class against the walls that replace the global ones.
struct WallContactSettings {
    int classIndex = 0;                        ///< index into Settings::classes
    std::optional<double> restitutionWall;     ///< in (0, 1]
    std::optional<double> frictionWall;        ///< >= 0
    std::optional<double> rollingFrictionWall; ///< >= 0
};

/// Contact coefficients (docs/theory/paper-model.md, "Particles"; docs/model.md).
struct ContactSettings {
    ContactLawType law = ContactLawType::linear;
    double kn = 800.0;                 ///< normal stiffness, N/m
    double kt = -1.0;                  ///< tangential stiffness, N/m; < 0 means 2/7 kn
    /// Tangential damping over the normal one, eta_t/eta_n, >= 0 (1: the paper's one eta).
    double tangentialDampingRatio = 1.0;
    double restitution = 0.97;         ///< particle-particle, in (0, 1]
    double restitutionWall = 0.97;     ///< particle-wall, in (0, 1]
    double frictionParticle = 0.15;    ///< sliding friction particle-particle, >= 0
    double frictionWall = 0.10;        ///< sliding friction particle-wall, >= 0
    /// Rolling resistance mu_r particle-particle, >= 0 (0: none): a torque of at most
    /// mu_r R_r Fn against the relative rolling (docs/theory/dem.md, "Rolling resistance").
    double rollingFriction = 0.0;
    double rollingFrictionWall = 0.0;  ///< rolling resistance particle-wall, >= 0
    double wallYoungsModulus = 0.0;    ///< HertzMindlin: the walls' Young's modulus, Pa, > 0
    double wallPoissonRatio = 0.0;     ///< HertzMindlin: the walls' Poisson's ratio, (-1, 0.5]
    /// HertzMindlin: the largest normal impact speed expected, m/s, > 0. A Hertz contact
    /// shortens as v^-1/5: the step bounds take the contact time at this speed, or at the
    /// bed's own speed scale where that is larger (hertzSpeed).
    double impactSpeed = 1.0;
    /// Per pair of classes and per class on the walls, each at most once: the coefficients
    /// that replace the global ones above (docs/theory/dem.md, "Coefficients per pair").
    std::vector<PairContactSettings> pairs;
    std::vector<WallContactSettings> walls;
};

/// The coefficients one kind of contact runs with: its own where given, else the global ones.
struct ContactCoefficients {
    double restitution;       ///< (0, 1]
    double friction;          ///< sliding friction
    double rollingFriction;   ///< rolling resistance mu_r
};

/// Those of a pair of classes a and b (the same for b and a).
ContactCoefficients pairCoefficients(const ContactSettings& contact, int a, int b);
/// Those of class a against the walls.
ContactCoefficients wallCoefficients(const ContactSettings& contact, int a);

/// The domain: four plane walls x = xMin, x = xMax, y = yMin, y = yMax (m).
struct Box {
    double xMin, xMax, yMin, yMax;
};

/// A plain 3-vector (the slab mode's positions, velocities and spins).
struct Vector3 {
    double x = 0.0, y = 0.0, z = 0.0;
};

/// The shape of a wall of the slab mode (Settings::walls).
enum class WallShape { plane, cylinder };

/// A wall of the slab mode: an infinite plane through `point` whose normal points into the
/// domain, or an infinite cylinder around the axis through `point`, the particles inside it.
struct WallSettings {
    WallShape shape = WallShape::plane;
    Vector3 point;          ///< plane: a point on it; cylinder: a point on the axis, m
    Vector3 normal;         ///< plane: pointing into the domain, of any length > 0
    Vector3 axis;           ///< cylinder: its unit direction (to 1e-6), either sense
    double radius = 0.0;    ///< cylinder: m, >= the largest diameter

    static WallSettings plane(const Vector3& point, const Vector3& normal)
    {
        return {WallShape::plane, point, normal, {}, 0.0};
    }
    static WallSettings cylinder(const Vector3& point, const Vector3& axis, double radius)
    {
        return {WallShape::cylinder, point, {}, axis, radius};
    }
};

/// Everything needed to build a Simulation.
struct Settings {
    std::vector<ParticleClass> classes;
    ContactSettings contact;
    Box box;
    double gravity[2] = {0.0, -9.81};  ///< m/s^2
    double dt = 1e-5;                  ///< DEM step, s
    int nThreads = 1;
    /// With nThreads > 1: each CFD step's sub-steps (advance) run on nThreads or on one
    /// thread, whichever the run's own timing found faster (alternating trials, repeated as
    /// the load changes: ThreadChooser). The results do not depend on it, the speed does.
    bool measureThreads = false;
    /// Verlet skin of the neighbour list built by NBS, m, fixed. < 0 (the default): adaptive
    /// in 2D, chosen at each list build from the fastest particle's displacement per step u
    /// since the last build as sqrt(20 d_min u) (the least cost of builds and candidate
    /// pairs), between 0.1 and 0.8 x the smallest diameter d_min (0.4 to start; saved in
    /// the state, so restarts continue bit for bit); the slab's default is a fixed 0.1 d_min.
    double neighbourSkin = -1.0;
    /// 2: discs in the x-y plane (the paper's model); 3: spheres in a slab between a front
    /// wall z = 0 and a back wall z = slabDepth, with the box's walls around, or in `walls`
    /// (docs/model.md, "The slab mode"). Gravity stays in the x-y plane.
    int dimension = 2;
    /// Depth of the slab in the 3D mode, m, >= the largest diameter; not used in 2D.
    double slabDepth = 0.0;
    /// The slab mode's walls, each a plane or a cylinder (docs/theory/slab-mode.md): empty
    /// (the default) the slab's six, the box's four and the front and back; else these
    /// alone. Whatever the walls, a particle that leaves the box or the slab stops the run.
    /// Empty in 2D, whose walls are the box's.
    std::vector<WallSettings> walls;
};

/// A particle of a bed laid before the rest are packed (BedRecipe::placed): at a given
/// position, or at random on the region's floor.
struct PlacedParticle {
    int classIndex = 0;
    /// Laid at random on the floor: its centre a radius above the region's yMin, x (and z in
    /// 3D) drawn uniform in the region (and the slab) clear of the walls and of the particles
    /// placed before it.
    bool random = false;
    Vector3 position;                  ///< m, when not random (z read in 3D only)
};

/// How a bed was made: the placed particles laid first, then packRandom of the rest of
/// countPerClass in region with seed, then settle(settleTime, keTolerance), with every
/// contact's sliding friction settleFriction if set. Saved with the state
/// (Simulation::packBed), so that a case that reuses the bed can check it was made for its
/// particles (Simulation::loadBed).
struct BedRecipe {
    std::vector<int> countPerClass;    ///< particles of each class, the placed ones included
    Box region;                        ///< packing region, m
    std::uint64_t seed = 1;            ///< of the random packing
    double settleTime = 1.0;           ///< longest settling, s
    double keTolerance = 0.0;          ///< settled below this kinetic energy per particle, J
    /// Laid in this order before the rest, fixed positions and random ones alike; each must
    /// lie in the region (in 3D in the slab) clear of the walls and of the others, and a
    /// class's placed particles count toward, and must not exceed, its count. A class with a
    /// distribution gives its placed particles its first diameters drawn.
    std::vector<PlacedParticle> placed{};
    /// The sliding friction coefficient of every contact (particle pairs, those of
    /// ContactSettings::pairs too, and particle-wall) while the bed settles, >= 0; the
    /// contacts' own once it has settled. Not set: their own throughout. Rolling friction
    /// keeps its own values.
    std::optional<double> settleFriction{};
};

/// Throws dem::Error naming the placed particle (its number, class, position) and the
/// allowed range if `recipe`'s placed particles cannot be laid with these settings as
/// Simulation::packBed lays them: a class outside the classes, more placed particles of a
/// class than its count, a position outside the region clear of its walls, one overlapping
/// another placed particle, no room on the floor for a random one.
void checkPlacements(const Settings& settings, const BedRecipe& recipe);

/// Called while a bed settles: (time spent settling, s; kinetic energy per particle, J).
using SettleProgress = std::function<void(double, double)>;

/// Throws dem::Error naming `path` and the reason (a directory, a parent that is a file,
/// no permission, ...) if Simulation::save could not write a state there; writes nothing
/// (a probe file in the nearest existing directory is created and removed).
void checkStatePath(const std::string& path);

/// The entries of two bed recipes that differ, as "class 'small' count = 600 in the file,
/// 500 here; seed = ..." (classes named after `settings`); empty if none.
std::string bedDifferences(const Settings& settings, const BedRecipe& inFile,
                           const BedRecipe& here);

/// The instruction set the engines' kick and drift loops run with (2D and slab): "avx2"
/// where the CPU has it, else "baseline" (x86-64's SSE2); the environment variable DEM_SIMD =
/// baseline or avx2 chooses. Both give the same bits. Throws dem::Error for a bad DEM_SIMD.
std::string streamingLoopsInUse();

class System;
class SlabSystem;

/// A DEM run: particles, walls, contacts; advanced in CFD steps with fluid forces.
/// Particle index i is the same particle for the whole run (id[i] == i).
/// Settings::dimension selects the engine: 2 the discs (System), 3 the slab (SlabSystem).
/// The members common to both behave alike; those marked "3D" throw dem::Error in 2D, and
/// the 2D addParticle throws in 3D. In 3D, x-y members are the spheres' x-y components and
/// omega() their spin about z.
class Simulation {
public:
    /// Validates the settings (ranges, eq. 7 time-step bound); throws dem::Error.
    explicit Simulation(const Settings& settings);
    ~Simulation();
    Simulation(const Simulation&) = delete;
    Simulation& operator=(const Simulation&) = delete;

    /// Random, well-mixed, non-overlapping packing of countPerClass[k] particles of class k
    /// in `region` (inside the box), clear of the particles already there; reproducible for
    /// a given seed, the diameters of a class with a distribution drawn from it too
    /// (drawClassDiameters).
    void packRandom(const std::vector<int>& countPerClass, const Box& region, std::uint64_t seed);

    /// Packs and settles a bed as `recipe` says (the placed particles, packRandom of the
    /// rest, then settle, with its settleFriction if set) in an empty simulation, and keeps
    /// the recipe: save() records it with the bed. The contacts run with their own friction
    /// after. Returns the time spent settling, s. `progress`, if given, is called as settle()
    /// calls it.
    double packBed(const BedRecipe& recipe, const SettleProgress& progress = {});

    /// Adds one particle of the class's (mean) diameter; throws if outside the box or
    /// overlapping another by more than 1 % of the smaller diameter.
    void addParticle(int classIndex, double x, double y,
                     double vx = 0, double vy = 0, double omega = 0);
    /// 3D: adds one sphere; throws if it pokes through a wall or overlaps another by more
    /// than 1 % of its diameter.
    void addParticle(int classIndex, const Vector3& position, const Vector3& velocity = {},
                     const Vector3& spin = {});

    /// Advances without fluid until the kinetic energy per particle < keTolerance (J) and
    /// falling (checked every 100 steps; a bed released from rest first gains energy), or
    /// until maxTime (s) has passed; returns the time spent, s. `progress`, if given, is
    /// called at each check with the time spent settling (s) and the kinetic energy per
    /// particle (J): a long settling can report how far it is. It does not change the bits.
    double settle(double maxTime, double keTolerance, const SettleProgress& progress = {});

    std::size_t size() const;
    const Settings& settings() const;

    /// @name Read-only particle state, length size()
    ///@{
    const double* x() const;
    const double* y() const;
    const double* vx() const;
    const double* vy() const;
    const double* omega() const;       ///< spin about z, rad/s
    const double* z() const;           ///< 3D
    const double* vz() const;          ///< 3D
    const double* omegaX() const;      ///< 3D: spin about x, rad/s
    const double* omegaY() const;      ///< 3D: spin about y, rad/s
    const double* omegaZ() const;      ///< spin about z, rad/s (= omega())
    const double* diameter() const;
    const double* mass() const;
    const int* classIndex() const;
    const std::int64_t* id() const;
    ///@}

    /// @name Fluid coupling inputs, set before advance() (length size(), zero by default).
    /// Force on i = dragCoefficient[i] (gasVelocity_i - v_i) + extraForce_i, re-evaluated
    /// with the current particle velocity at every DEM sub-step.
    ///@{
    double* dragCoefficient();         ///< N s/m
    double* gasVelocityX();            ///< m/s
    double* gasVelocityY();            ///< m/s
    double* extraForceX();             ///< N
    double* extraForceY();             ///< N
    double* gasVelocityZ();            ///< 3D, m/s
    double* extraForceZ();             ///< 3D, N
    ///@}

    /// Advances by one CFD step of dtOuter = n dt; throws dem::Error if dtOuter/dt is not an
    /// integer (relative tolerance 1e-9) or a particle leaves the box.
    void advance(double dtOuter);

    /// Renumbers the particles in the order of the neighbour-search cells (row by row),
    /// so that neighbours sit close in memory and the contact loops hit the cache. Every
    /// per-particle array (state, inputs, averages) moves along; id() keeps each particle's
    /// identity. The trajectory changes only in the order of round-off. Call it between
    /// CFD steps, before setting the fluid inputs, every few hundred DEM steps.
    void sortByCell();

    /// @name Averages over the sub-steps of the last advance()
    /// meanFluidForce = dragCoefficient (gasVelocity - meanVelocity) + extraForce exactly.
    ///@{
    const double* meanVelocityX() const;
    const double* meanVelocityY() const;
    const double* meanFluidForceX() const;
    const double* meanFluidForceY() const;
    const double* meanVelocityZ() const;    ///< 3D
    const double* meanFluidForceZ() const;  ///< 3D
    ///@}

    double time() const;               ///< s
    std::int64_t stepCount() const;
    double kineticEnergy() const;      ///< translational + rotational, J
    double timeStepBound() const;      ///< eq. 7 bound for the smallest particle, s
    std::size_t contactCount() const;  ///< touching pairs + particle-wall contacts

    /// Elastic energy stored in the contact springs (normal and tangential), J.
    double elasticEnergy() const;
    /// Largest overlap of the last force evaluation (pairs and walls), m.
    double maxOverlap() const;
    /// Number of neighbour-list builds (NBS calls) so far.
    std::int64_t neighbourListBuilds() const;
    /// The Verlet skin of the current neighbour list, m (Settings::neighbourSkin).
    double neighbourSkin() const;
    /// Settings::measureThreads: the CFD steps (advance) run so far on one thread and on
    /// nThreads.
    std::int64_t stepsOnOneThread() const;
    std::int64_t stepsOnAllThreads() const;
    /// The holds on nThreads ended early, their steps slower than one thread's in the trial
    /// before (ThreadChooser::holdsCutShort).
    std::int64_t threadHoldsCutShort() const;
    /// The trials of nThreads not made: the rest of the machine left too few cores free
    /// (ThreadChooser::trialsSkipped).
    std::int64_t threadTrialsSkipped() const;
    /// The team the next CFD step (advance) runs its loops on: nThreads, or with
    /// measureThreads the one ThreadChooser picks for it. A caller's own loops around the
    /// step (the coupling's) follow it, so that a neighbour's load that makes one thread
    /// faster makes it so for them too.
    int nextStepThreads() const;
    /// Heap memory held by particle, contact and search arrays, bytes.
    std::size_t memoryBytes() const;

    /// Writes the complete state, contact history included, to `path` + ".tmp", then
    /// renames it (an earlier state at `path` stays whole if the write fails); creates
    /// missing parent directories; throws dem::Error naming the file and the OS reason.
    void save(const std::string& path) const;
    /// Reads a state written by save(); throws dem::Error naming the file if it is bad or
    /// was written with other settings: damaged (checksum, truncated, bytes appended), of
    /// the other engine (ForeignStateError), of an older version (naming dpmConvertState,
    /// StateConversion.hpp), or with a particle not finite, outside the box or nearly on
    /// top of another.
    void load(const std::string& path);
    /// Reads a bed saved after packBed() and checks that it was made by `recipe` with these
    /// settings; throws dem::Error naming the file and every entry that differs (class,
    /// setting, the file's value and this one), leaving the simulation untouched. A file
    /// without the record (particles not packed, or converted from a version before the
    /// record) is checked on its counts per class only: returns false then, true when fully
    /// checked.
    bool loadBed(const std::string& path, const BedRecipe& recipe);
    /// The recipe of the particles (packBed, or the file they were loaded from); none if
    /// they were placed otherwise.
    const BedRecipe* recipe() const;
    /// A text the caller keeps with the state (what the run was made with: its coupling
    /// models), saved by save(); load() and loadBed() set the file's (empty for a file
    /// converted from a version before the record).
    const std::string& runRecord() const;
    void setRunRecord(const std::string& record);

private:
    SlabSystem& slab(const char* what) const;   // throws in 2D, naming `what`
    /// f(engine) on the engine that is set (Simulation.cpp's one dispatch); const here, a
    /// const engine.
    template <class F> decltype(auto) onEngine(F&& f);
    template <class F> decltype(auto) onEngine(F&& f) const;

    // Exactly one engine is set. Every call branches once on slab_, outside any loop, so
    // the 2D path runs the System's code unchanged.
    std::unique_ptr<System> system_;
    std::unique_ptr<SlabSystem> slab_;
};

} // namespace dem
