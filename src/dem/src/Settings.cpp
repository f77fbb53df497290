// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "dem/System.hpp"

#include "LawSupport.hpp"
#include "SlabWalls.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <numeric>
#include <sstream>
#include <utility>

namespace dem {

std::string formatValue(double value)
{
    std::ostringstream s;
    s << std::setprecision(6) << value;
    return s.str();
}

// Written as !(value > 0) etc. so that NaN is rejected too.
void requirePositive(double value, const std::string& name)
{
    if (!(value > 0.0) || !std::isfinite(value)) {
        throw Error(name + " = " + formatValue(value) + " is outside (0, inf)");
    }
}

std::string className(const Settings& s, int k)
{
    return "classes[" + std::to_string(k) + "] ('" + s.classes[k].name + "')";
}

namespace {

void requireNonNegative(double value, const std::string& name)
{
    if (!(value >= 0.0) || !std::isfinite(value)) {
        throw Error(name + " = " + formatValue(value) + " is outside [0, inf)");
    }
}

void requireRestitution(double value, const std::string& name)
{
    if (!(value > 0.0 && value <= 1.0)) {
        // The clamped dashpot leaves a rebound at any finite damping (docs/theory/dem.md, "Particles")
        const std::string why = value == 0.0 ? ": e = 0 would need an infinite damping (a "
                                               "normal force clamped at zero rebounds at any "
                                               "finite one); a small e such as 0.01 is "
                                               "representable" : "";
        throw Error(name + " = " + formatValue(value) + " is outside (0, 1]" + why);
    }
}

/// The per-pair and per-wall coefficients: classes in range, each pair and class once (a-b
/// and b-a are one pair), values in the global entries' ranges.
void validateOwnCoefficients(const Settings& s)
{
    const ContactSettings& c = s.contact;
    const int n = static_cast<int>(s.classes.size());
    auto requireClass = [n](int k, const std::string& what) {
        if (k < 0 || k >= n) {
            throw Error(what + " = " + std::to_string(k) + " is outside [0, "
                        + std::to_string(n - 1) + "] (an index of classes)");
        }
    };
    for (std::size_t q = 0; q < c.pairs.size(); ++q) {
        const PairContactSettings& p = c.pairs[q];
        const std::string where = "contact pairs[" + std::to_string(q) + "]";
        requireClass(p.classA, where + ".classA");
        requireClass(p.classB, where + ".classB");
        const std::string name = pairName(s, p.classA, p.classB);
        for (std::size_t r = 0; r < q; ++r) {
            const PairContactSettings& o = c.pairs[r];
            if ((o.classA == p.classA && o.classB == p.classB)
                || (o.classA == p.classB && o.classB == p.classA)) {
                throw Error(name + " is given twice (as '"
                            + s.classes[o.classA].name + "-" + s.classes[o.classB].name
                            + "' and '" + s.classes[p.classA].name + "-"
                            + s.classes[p.classB].name + "'): each pair of classes once");
            }
        }
        if (p.restitution) requireRestitution(*p.restitution, name + " restitution");
        if (p.frictionParticle) requireNonNegative(*p.frictionParticle, name + " frictionParticle");
        if (p.rollingFriction) requireNonNegative(*p.rollingFriction, name + " rollingFriction");
    }
    for (std::size_t q = 0; q < c.walls.size(); ++q) {
        const WallContactSettings& w = c.walls[q];
        requireClass(w.classIndex, "contact walls[" + std::to_string(q) + "].classIndex");
        const std::string name = wallName(s, w.classIndex);
        for (std::size_t r = 0; r < q; ++r) {
            if (c.walls[r].classIndex == w.classIndex) {
                throw Error(name + " is given twice: each class once");
            }
        }
        if (w.restitutionWall) requireRestitution(*w.restitutionWall, name + " restitutionWall");
        if (w.frictionWall) requireNonNegative(*w.frictionWall, name + " frictionWall");
        if (w.rollingFrictionWall) {
            requireNonNegative(*w.rollingFrictionWall, name + " rollingFrictionWall");
        }
    }
}

} // namespace

ContactCoefficients pairCoefficients(const ContactSettings& c, int a, int b)
{
    ContactCoefficients own{c.restitution, c.frictionParticle, c.rollingFriction};
    for (const PairContactSettings& p : c.pairs) {
        if ((p.classA == a && p.classB == b) || (p.classA == b && p.classB == a)) {
            own.restitution = p.restitution.value_or(own.restitution);
            own.friction = p.frictionParticle.value_or(own.friction);
            own.rollingFriction = p.rollingFriction.value_or(own.rollingFriction);
        }
    }
    return own;
}

ContactCoefficients wallCoefficients(const ContactSettings& c, int a)
{
    ContactCoefficients own{c.restitutionWall, c.frictionWall, c.rollingFrictionWall};
    for (const WallContactSettings& w : c.walls) {
        if (w.classIndex == a) {
            own.restitution = w.restitutionWall.value_or(own.restitution);
            own.friction = w.frictionWall.value_or(own.friction);
            own.rollingFriction = w.rollingFrictionWall.value_or(own.rollingFriction);
        }
    }
    return own;
}

std::string pairName(const Settings& s, int a, int b)
{
    for (const PairContactSettings& p : s.contact.pairs) {   // in the order given
        if (p.classA == b && p.classB == a) std::swap(a, b);
        if (p.classA == a && p.classB == b) break;
    }
    return "contact pair '" + s.classes[a].name + "-" + s.classes[b].name + "'";
}

std::string wallName(const Settings& s, int a)
{
    return "contact wall '" + s.classes[a].name + "'";
}

long subStepCount(double dtOuter, double dt)
{
    const double nearest = std::round(dtOuter / dt);
    if (!(nearest >= 1.0) || !(std::abs(nearest * dt - dtOuter) <= 1e-9 * dtOuter)) {
        throw Error("dtOuter = " + formatValue(dtOuter) + " s is outside the positive integer "
                    "multiples of dt = " + formatValue(dt) + " s (relative tolerance 1e-9)");
    }
    return static_cast<long>(nearest);
}

std::vector<int> classesLargestFirst(const Settings& settings)
{
    std::vector<int> order(settings.classes.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int c) {
        return meanDiameter(settings.classes[a]) > meanDiameter(settings.classes[c]);
    });
    return order;
}

void validateSettings(const Settings& s)
{
    if (s.classes.empty()) {
        throw Error("classes is empty: at least one size class (diameter, density) is needed");
    }
    for (std::size_t k = 0; k < s.classes.size(); ++k) {
        const int ki = static_cast<int>(k);
        if (s.classes[k].distribution.type == DiameterDistributionType::single) {
            requirePositive(s.classes[k].diameter, className(s, ki) + ".diameter");
        } else {
            validateDistribution(s.classes[k].distribution, className(s, ki));
        }
        requirePositive(s.classes[k].density, className(s, ki) + ".density");
    }
    const ContactSettings& c = s.contact;
    requirePositive(c.kn, "kn");
    if (c.kt == 0.0 || std::isnan(c.kt) || std::isinf(c.kt)) {
        throw Error("kt = " + formatValue(c.kt) + " is outside (0, inf) (or < 0 for 2/7 kn)");
    }
    requireRestitution(c.restitution, "restitution");
    requireRestitution(c.restitutionWall, "restitutionWall");
    requireNonNegative(c.frictionParticle, "frictionParticle");
    requireNonNegative(c.frictionWall, "frictionWall");
    requireNonNegative(c.tangentialDampingRatio, "tangentialDampingRatio");
    requireNonNegative(c.rollingFriction, "rollingFriction");
    requireNonNegative(c.rollingFrictionWall, "rollingFrictionWall");
    validateOwnCoefficients(s);
    withLaw(c.law, [&](auto law) { decltype(law)::validate(s); });

    const Box& b = s.box;
    if (!(b.xMax > b.xMin) || !std::isfinite(b.xMax - b.xMin)) {
        throw Error("box.xMax = " + formatValue(b.xMax) + " is outside (box.xMin = "
                    + formatValue(b.xMin) + ", inf)");
    }
    if (!(b.yMax > b.yMin) || !std::isfinite(b.yMax - b.yMin)) {
        throw Error("box.yMax = " + formatValue(b.yMax) + " is outside (box.yMin = "
                    + formatValue(b.yMin) + ", inf)");
    }
    if (!std::isfinite(s.gravity[0]) || !std::isfinite(s.gravity[1])) {
        throw Error("gravity = (" + formatValue(s.gravity[0]) + ", " + formatValue(s.gravity[1])
                    + ") is outside the finite vectors");
    }
    if (s.nThreads < 1) {
        throw Error("nThreads = " + std::to_string(s.nThreads) + " is outside [1, inf)");
    }
    if (std::isnan(s.neighbourSkin) || std::isinf(s.neighbourSkin)) {
        throw Error("neighbourSkin = " + formatValue(s.neighbourSkin)
                    + " is outside [0, inf) (or < 0 for the default)");
    }

    if (s.dimension != 2 && s.dimension != 3) {
        throw Error("dimension = " + std::to_string(s.dimension)
                    + " is outside {2, 3} (2: discs in a plane, 3: spheres in a slab)");
    }
    if (s.dimension == 3) {
        double dMax = 0.0;
        for (const auto& c : s.classes) dMax = std::max(dMax, largestDiameter(c));
        if (!(s.slabDepth >= dMax) || !std::isfinite(s.slabDepth)) {
            throw Error("slabDepth = " + formatValue(s.slabDepth) + " m is outside ["
                        + formatValue(dMax) + ", inf): the slab (dimension 3) must hold the "
                        "largest diameter");
        }
    }
    validateWalls(s);

    requirePositive(s.dt, "dt");
    checkTimeStep(s);
}

std::vector<PlaneWall> boxWalls(const Box& box)
{
    return {
        {Eigen::Vector2d(box.xMin, box.yMin), Eigen::Vector2d(0.0, 1.0)},    // floor
        {Eigen::Vector2d(box.xMax, box.yMin), Eigen::Vector2d(-1.0, 0.0)},   // right
        {Eigen::Vector2d(box.xMin, box.yMax), Eigen::Vector2d(0.0, -1.0)},   // ceiling
        {Eigen::Vector2d(box.xMin, box.yMin), Eigen::Vector2d(1.0, 0.0)},    // left
    };
}

} // namespace dem
