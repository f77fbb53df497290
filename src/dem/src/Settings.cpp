// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "dem/ContactLaw.hpp"
#include "dem/System.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <numeric>
#include <sstream>

namespace dem {

std::string formatValue(double value)
{
    std::ostringstream s;
    s << std::setprecision(6) << value;
    return s.str();
}

namespace {

// Written as !(value > 0) etc. so that NaN is rejected too.
void requirePositive(double value, const std::string& name)
{
    if (!(value > 0.0) || !std::isfinite(value)) {
        throw Error(name + " = " + formatValue(value) + " is outside (0, inf)");
    }
}

void requireNonNegative(double value, const std::string& name)
{
    if (!(value >= 0.0) || !std::isfinite(value)) {
        throw Error(name + " = " + formatValue(value) + " is outside [0, inf)");
    }
}

void requireRestitution(double value, const std::string& name)
{
    if (!(value > 0.0 && value <= 1.0)) {
        // The clamped dashpot leaves a rebound at any finite damping (model.md, "Particles")
        const std::string why = value == 0.0 ? ": e = 0 would need an infinite damping (a "
                                               "normal force clamped at zero rebounds at any "
                                               "finite one); a small e such as 0.01 is "
                                               "representable" : "";
        throw Error(name + " = " + formatValue(value) + " is outside (0, 1]" + why);
    }
}

std::string className(const Settings& s, int k)
{
    return "classes[" + std::to_string(k) + "] ('" + s.classes[k].name + "')";
}

} // namespace

namespace {

constexpr double pi = 3.14159265358979323846;

double classMass(const ParticleClass& c)
{
    return c.density * pi * c.diameter * c.diameter * c.diameter / 6.0;
}

/// body(lighter class, its mass, mEff, R*, E*) for every pair of classes and every class on
/// a wall, the kinds of Hertz contact.
template <class Body>
void forEachHertzContact(const Settings& s, const Body& body)
{
    const ContactSettings& c = s.contact;
    const std::size_t n = s.classes.size();
    for (std::size_t a = 0; a < n; ++a) {
        const ParticleClass& ca = s.classes[a];
        const double ma = classMass(ca);
        const double ra = 0.5 * ca.diameter;
        for (std::size_t b = a; b < n; ++b) {
            const ParticleClass& cb = s.classes[b];
            const double mb = classMass(cb);
            const double rb = 0.5 * cb.diameter;
            body(static_cast<int>(ma <= mb ? a : b), std::min(ma, mb), ma * mb / (ma + mb),
                 ra * rb / (ra + rb),
                 effectiveYoungsModulus(ca.youngsModulus, ca.poissonRatio, cb.youngsModulus,
                                        cb.poissonRatio));
        }
        body(static_cast<int>(a), ma, ma, ra,
             effectiveYoungsModulus(ca.youngsModulus, ca.poissonRatio, c.wallYoungsModulus,
                                    c.wallPoissonRatio));
    }
}

} // namespace

std::string contactLawName(ContactLawType law)
{
    return law == ContactLawType::hertzMindlin ? "HertzMindlin" : "linear";
}

ContactLawType contactLawFromName(const std::string& name)
{
    for (ContactLawType law : {ContactLawType::linear, ContactLawType::hertzMindlin}) {
        if (name == contactLawName(law)) return law;
    }
    throw Error("contactLaw '" + name + "' is not one of: linear, HertzMindlin");
}

double timeStepBound(const Settings& settings, int* smallestClass)
{
    int kMin = 0;
    double bound = INFINITY;
    if (settings.contact.law == ContactLawType::hertzMindlin) {
        const double v = settings.contact.impactSpeed;
        forEachHertzContact(settings, [&](int k, double m, double mEff, double rEff, double eStar) {
            const double deltaMax = std::pow(15.0 * mEff * v * v / (16.0 * eStar * std::sqrt(rEff)), 0.4);
            const double stiffness = 2.0 * eStar * std::sqrt(rEff * deltaMax);
            const double b = 2.0 * pi / 5.0 * std::sqrt(m / stiffness);
            if (b < bound) {
                bound = b;
                kMin = k;
            }
        });
    } else {
        double mMin = INFINITY;
        for (std::size_t k = 0; k < settings.classes.size(); ++k) {
            const double m = classMass(settings.classes[k]);
            if (m < mMin) {
                mMin = m;
                kMin = static_cast<int>(k);
            }
        }
        bound = 2.0 * pi / 5.0 * std::sqrt(mMin / settings.contact.kn);
    }
    if (smallestClass) *smallestClass = kMin;
    return bound;
}

double pairContactTime(const Settings& settings)
{
    const ContactSettings& c = settings.contact;
    if (c.law == ContactLawType::hertzMindlin) {
        double tc = INFINITY;
        forEachHertzContact(settings, [&](int, double, double mEff, double rEff, double eStar) {
            tc = std::min(tc, hertzContactTime(mEff, rEff, eStar, c.impactSpeed));
        });
        return tc;
    }
    int k = 0;
    timeStepBound(settings, &k);
    const double mEff = 0.5 * classMass(settings.classes[k]);
    return linearContactDuration(mEff, c.kn, dampingFromRestitution(mEff, c.kn, c.restitution));
}

// Measured with the paper's particles (TestStepBound; docs/model.md): at dt = t_c/10 a
// head-on pair's restitution is within 1 %; at 0.25 t_c within 5 % and a settling bed comes
// to rest; above 0.4 t_c the bed does not (0.45 t_c: overlaps double; 0.55 t_c, just under
// eq. 7's bound: particles thrown out of the box).
double safeTimeStep(const Settings& settings) { return 0.1 * pairContactTime(settings); }
double stableTimeStep(const Settings& settings) { return 0.25 * pairContactTime(settings); }

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
        return settings.classes[a].diameter > settings.classes[c].diameter;
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
        requirePositive(s.classes[k].diameter, className(s, ki) + ".diameter");
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
    if (c.law == ContactLawType::hertzMindlin) {
        // The moduli of every material; kt is the linear law's (Mindlin's comes from them)
        auto requireMaterial = [](double youngs, double poisson, const std::string& youngsName,
                                  const std::string& poissonName) {
            requirePositive(youngs, youngsName);
            if (!(poisson > -1.0 && poisson <= 0.5)) {
                throw Error(poissonName + " = " + formatValue(poisson)
                            + " is outside (-1, 0.5] (contactLaw HertzMindlin)");
            }
        };
        for (std::size_t k = 0; k < s.classes.size(); ++k) {
            const std::string name = className(s, static_cast<int>(k));
            requireMaterial(s.classes[k].youngsModulus, s.classes[k].poissonRatio,
                            name + ".youngsModulus", name + ".poissonRatio");
        }
        requireMaterial(c.wallYoungsModulus, c.wallPoissonRatio, "wallYoungsModulus",
                        "wallPoissonRatio");
        requirePositive(c.impactSpeed, "impactSpeed");
        if (c.kt >= 0.0) {
            throw Error("kt = " + formatValue(c.kt) + " is the linear law's tangential stiffness: "
                        "contactLaw HertzMindlin takes Mindlin's from youngsModulus and "
                        "poissonRatio (remove kt)");
        }
    }

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
        for (const auto& c : s.classes) dMax = std::max(dMax, c.diameter);
        if (!(s.slabDepth >= dMax) || !std::isfinite(s.slabDepth)) {
            throw Error("slabDepth = " + formatValue(s.slabDepth) + " m is outside ["
                        + formatValue(dMax) + ", inf): the slab (dimension 3) must hold the "
                        "largest diameter");
        }
    }

    requirePositive(s.dt, "dt");
    int kMin = 0;
    const double bound = timeStepBound(s, &kMin);
    if (s.dt > bound) {
        const std::string stiffness = c.law == ContactLawType::hertzMindlin
            ? "(2 pi/5) sqrt(m/S), S Hertz's stiffness at the peak overlap of an impact at "
              "impactSpeed = " + formatValue(c.impactSpeed) + " m/s,"
            : "(2 pi/5) sqrt(m_min/kn) = " + formatValue(bound) + " s (paper eq. 7)";
        throw Error("dt = " + formatValue(s.dt) + " s is outside (0, " + formatValue(bound)
                    + "]: the time-step bound " + stiffness + " of the smallest particle, "
                    + className(s, kMin) + " of diameter "
                    + formatValue(s.classes[kMin].diameter) + " m");
    }
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
