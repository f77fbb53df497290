// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The shared part of the 2D and slab engines (EngineBase.hpp): laws, step structure, the
// CFD step's sub-steps and settling (the neighbour list: EngineNeighbourList.cpp).

#include "dem/EngineBase.hpp"
#include "dem/CoreLoad.hpp"
#include "dem/SlabSystem.hpp"
#include "dem/StateRecord.hpp"
#include "dem/System.hpp"

#include "PairGroups.hpp"
#include "Placement.hpp"
#include "StreamingLoops.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include <omp.h>

namespace dem {

namespace {

using Index = std::ptrdiff_t;   // OpenMP loop index

double smallestDiameter(const Settings& s)
{
    double d = INFINITY;
    for (const auto& c : s.classes) d = std::min(d, dem::smallestDiameter(c));
    return d;
}

double largestDiameter(const Settings& s)
{
    double d = 0.0;
    for (const auto& c : s.classes) d = std::max(d, dem::largestDiameter(c));
    return d;
}

double resolvedSkin(const Settings& s, double startFraction)
{
    return s.neighbourSkin >= 0.0 ? s.neighbourSkin : startFraction * smallestDiameter(s);
}

/// While it lives, every law's sliding friction is the bed's settle friction (if the recipe
/// sets one); the laws' own come back when it goes, a settling that throws included.
/// Only ContactLaw::mu changes: stiffness, damping and rolling resistance stay the laws' own.
class SettleFriction {
public:
    SettleFriction(std::vector<ContactLaw>& pairLaws, std::vector<ContactLaw>& wallLaws,
                   const std::optional<double>& settleFriction)
        : laws_{&pairLaws, &wallLaws}
    {
        if (!settleFriction) return;
        const double mu = *settleFriction;
        for (std::vector<ContactLaw>* laws : laws_) {
            for (ContactLaw& law : *laws) {
                own_.push_back(law.mu);
                law.mu = mu;
            }
        }
    }
    ~SettleFriction()
    {
        auto own = own_.cbegin();
        if (own == own_.cend()) return;
        for (std::vector<ContactLaw>* laws : laws_) {
            for (ContactLaw& law : *laws) law.mu = *own++;
        }
    }
    SettleFriction(const SettleFriction&) = delete;
    SettleFriction& operator=(const SettleFriction&) = delete;

private:
    std::vector<ContactLaw>* laws_[2];   // the pairs' and the walls'
    std::vector<double> own_;            // their own mu, in that order; empty: none changed
};

/// The measured choice's view of the machine: the cores the rest of it leaves free
ThreadChooser::FreeCores machineLoad(const Settings& settings)
{
    if (!settings.measureThreads || settings.nThreads == 1) return {};
    return [load = std::make_shared<CoreLoad>()] { return load->freeCores(); };
}

} // namespace

template <class Derived, class Traits>
EngineBase<Derived, Traits>::EngineBase(const Settings& settings, std::vector<Wall> walls,
                                        double startFraction, bool adaptive)
    : settings_(settings),
      threads_(settings.nThreads),
      threadChooser_(settings.nThreads, machineLoad(settings)),
      nClasses_(static_cast<int>(settings.classes.size())),
      smallestDiameter_(smallestDiameter(settings)),
      largestDiameter_(largestDiameter(settings)),
      cellDiameter_(largestDiameter_),
      skin_(resolvedSkin(settings, startFraction)),
      adaptiveSkin_(adaptive),
      skinMin_(adaptive ? skinMinFraction * smallestDiameter_ : skin_),
      skinMax_(adaptive ? skinMaxFraction * smallestDiameter_ : skin_),
      walls_(std::move(walls)),
      search_(settings.box.xMin, settings.box.xMax, settings.box.yMin, settings.box.yMax,
              cellDiameter_ + skin_)
{
    streamingLoops();   // a bad $DEM_SIMD is an error here, not at the first step
    constexpr double pi = 3.14159265358979323846;
    const ContactSettings& c = settings_.contact;
    // A class's laws take the mass and radius of its mean diameter; the rolling clamp the
    // moment of inertia of its smallest, which the clamp stops fastest (a class of one
    // diameter: the three alike)
    std::vector<double> m(nClasses_), r(nClasses_), inertia(nClasses_);
    for (int k = 0; k < nClasses_; ++k) {
        const double d = meanDiameter(settings_.classes[k]);
        m[k] = settings_.classes[k].density * pi * d * d * d / 6.0;
        r[k] = 0.5 * d;
        const double dSmall = dem::smallestDiameter(settings_.classes[k]);
        const double mSmall = settings_.classes[k].density * pi * dSmall * dSmall * dSmall / 6.0;
        inertia[k] = mSmall * dSmall * dSmall / 10.0;   // a solid sphere, as Particles has it
    }
    // The materials of each class and of the walls, for the laws that read them
    std::vector<ElasticMaterial> material(nClasses_);
    for (int k = 0; k < nClasses_; ++k) {
        material[k] = {settings_.classes[k].youngsModulus, settings_.classes[k].poissonRatio};
    }
    const ElasticMaterial wall{c.wallYoungsModulus, c.wallPoissonRatio};
    for (int a = 0; a < nClasses_; ++a) {
        for (int b = 0; b < nClasses_; ++b) {
            const double mEff = m[a] * m[b] / (m[a] + m[b]);
            const double rEff = r[a] * r[b] / (r[a] + r[b]);
            const ContactCoefficients own = pairCoefficients(c, a, b);
            ContactLaw law = makeContactLaw(
                c, {mEff, rEff, material[a], material[b], own.restitution}, own.friction);
            addRollingResistance(law, own.rollingFriction, rEff,
                                 inertia[a] * inertia[b] / (inertia[a] + inertia[b]), settings_.dt);
            rolling_ = rolling_ || own.rollingFriction > 0.0;
            pairLaws_.push_back(law);
        }
        const ContactCoefficients own = wallCoefficients(c, a);
        ContactLaw law =
            makeContactLaw(c, {m[a], r[a], material[a], wall, own.restitution}, own.friction);
        addRollingResistance(law, own.rollingFriction, r[a], inertia[a], settings_.dt);
        rolling_ = rolling_ || own.rollingFriction > 0.0;
        wallLaws_.push_back(law);
    }
}

template <class Derived, class Traits>
void EngineBase<Derived, Traits>::checkClass(int cls) const
{
    if (cls < 0 || cls >= nClasses_) {
        throw Error("classIndex = " + std::to_string(cls) + " is outside [0, "
                    + std::to_string(nClasses_ - 1) + "]");
    }
}

template <class Derived, class Traits>
double EngineBase<Derived, Traits>::packBed(const BedRecipe& recipe, const SettleProgress& progress)
{
    checkPackBed(p_.size(), recipe);
    const Box& b = settings_.box;
    const Box& region = recipe.region;
    if (!recipe.placed.empty()
        && !(region.xMin >= b.xMin && region.xMax <= b.xMax && region.yMin >= b.yMin
             && region.yMax <= b.yMax)) {
        throw Error("packing region [" + formatValue(region.xMin) + ", " + formatValue(region.xMax)
                    + "] x [" + formatValue(region.yMin) + ", " + formatValue(region.yMax)
                    + "] m is outside the box");
    }
    std::vector<int> drawn;
    for (const LaidParticle& q : layPlacedParticles(settings_, recipe, drawn)) {
        derived().appendAtRest(q.classIndex, q.diameter, q.position);
    }
    std::vector<int> rest(recipe.countPerClass);
    for (std::size_t k = 0; k < rest.size() && k < drawn.size(); ++k) rest[k] -= drawn[k];
    derived().packRest(rest, recipe.region, recipe.seed, drawn);
    double spent = 0.0;
    {
        const SettleFriction during(pairLaws_, wallLaws_, recipe.settleFriction);
        spent = settle(recipe.settleTime, recipe.keTolerance, progress);
    }
    if (recipe.settleFriction) {
        // The forces of the last evaluation, and the tangential springs capped by it, were
        // the settle friction's: evaluated anew with the contacts' own, which the run's first
        // step and a saved bed take
        forcesValid_ = false;
        ensureReady();
    }
    recipe_ = recipe;
    return spent;
}

template <class Derived, class Traits>
void EngineBase<Derived, Traits>::ensureReady()
{
    if (!listValid_) rebuildNeighbourList();
    if (!forcesValid_) {
        // First evaluation at the initial state: no history accumulation (dt = 0).
        derived().computePairForces(0.0);
        derived().addWallForcesAndKick(0.0, false, false);
        forcesValid_ = true;
    }
}

template <class Derived, class Traits>
void EngineBase<Derived, Traits>::step(bool fluid)
{
    ensureReady();
    const double dt = settings_.dt;
    // First half-kick and drift; throws if a particle left the domain.
    const double maxDisplacement2 = derived().drift();

    // Rebuild once some particle may have closed half the skin: no contact can be missed.
    // An adaptive skin above its minimum is also rebuilt (narrower) when it lasts long.
    const bool due = 4.0 * maxDisplacement2 >= skin_ * skin_;
    const bool tooWide = adaptiveSkin_ && skin_ > skinMin_ && lastBuildStep_ >= 0
                         && stepCount_ - lastBuildStep_ >= skinRecheckAfter;
    if (due || tooWide) {
        if (adaptiveSkin_) adaptSkin(maxDisplacement2);
        rebuildNeighbourList();
    }

    derived().computePairForces(dt);
    derived().addWallForcesAndKick(dt, true, fluid);
    ++stepCount_;
}

template <class Derived, class Traits>
template <class Body>
void EngineBase<Derived, Traits>::forEachShare(const Body& body)
{
    // The kick loops' shares (threadShare): each thread keeps its particles in its cache
    const Index n = static_cast<Index>(p_.size());
#pragma omp parallel num_threads(threads_)
    {
        const auto [first, last] = threadShare(n);
        body(first, last);
    }
}

template <class Derived, class Traits>
void EngineBase<Derived, Traits>::setFluidForceAtCurrentVelocity(bool fluid)
{
    const std::vector<double>& K = p_.dragCoefficient;
    forEachShare([&](Index first, Index last) {
        for (const AxisArrays& a : Traits::axes(p_)) {
            for (Index i = first; i < last; ++i) {
                (*a.fluid)[i] = fluid ? K[i] * ((*a.gasV)[i] - (*a.v)[i]) + (*a.extraF)[i] : 0.0;
            }
        }
    });
}

template <class Derived, class Traits>
void EngineBase<Derived, Traits>::advance(double dtOuter)
{
    const long nSub = subStepCount(dtOuter, settings_.dt);
    const bool measured = settings_.measureThreads && settings_.nThreads > 1;
    if (measured) threads_ = threadChooser_.next();
    const auto start = std::chrono::steady_clock::now();
    ensureReady();
    setFluidForceAtCurrentVelocity(true);

    // Trapezoidal weights: the drag is evaluated at v(t0), v(t1), ..., v(tn), and the
    // half-kicks apply the end values for half a sub-step and the inner ones for a whole one.
    forEachShare([&](Index first, Index last) {
        for (const AxisArrays& a : Traits::axes(p_)) {
            for (Index i = first; i < last; ++i) (*a.meanV)[i] = 0.5 * (*a.v)[i];
        }
    });
    for (long s = 1; s <= nSub; ++s) {
        meanWeight_ = s == nSub ? 0.5 : 1.0;
        step(true);
    }
    const double invN = 1.0 / static_cast<double>(nSub);
    const std::vector<double>& K = p_.dragCoefficient;
    forEachShare([&](Index first, Index last) {
        for (const AxisArrays& a : Traits::axes(p_)) {
            for (Index i = first; i < last; ++i) {
                (*a.meanV)[i] *= invN;
                (*a.meanFluid)[i] = K[i] * ((*a.gasV)[i] - (*a.meanV)[i]) + (*a.extraF)[i];
            }
        }
    });
    if (measured) {
        const std::chrono::duration<double> spent = std::chrono::steady_clock::now() - start;
        threadChooser_.record(spent.count());
    }
}

template <class Derived, class Traits>
double EngineBase<Derived, Traits>::settle(double maxTime, double keTolerance,
                                           const SettleProgress& progress)
{
    const std::int64_t first = stepCount_;
    if (p_.size() == 0) return 0.0;
    ensureReady();
    setFluidForceAtCurrentVelocity(false);
    const double n = static_cast<double>(p_.size());
    const auto nSteps = static_cast<std::int64_t>(std::ceil(maxTime / settings_.dt - 1e-9));
    // At rest means below the tolerance and not gaining energy: a packing released from
    // rest starts below any tolerance and is then accelerating.
    constexpr int checkEvery = 100;   // 1 ms at dt = 1e-5 s: cheap next to the steps
    double previous = INFINITY;
    for (std::int64_t k = 0; k < nSteps; ++k) {
        if (k % checkEvery == 0) {
            const double ke = derived().kineticEnergy() / n;
            if (progress) progress(static_cast<double>(k) * settings_.dt, ke);
            if (k > 0 && ke < keTolerance && ke < previous) break;
            previous = ke;
        }
        step(false);
    }
    return static_cast<double>(stepCount_ - first) * settings_.dt;
}

template class EngineBase<System, DiscTraits>;
template class EngineBase<SlabSystem, SphereTraits>;

} // namespace dem
