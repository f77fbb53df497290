// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The DEM step's bounds (docs/theory/numerics.md, "The DEM step's bound"): the contact time of the
// stiffest contact, the dashpot's own stability, and the impact speed a Hertz contact is
// sized for; the check validateSettings makes of them and the warnings near them.

#include "dem/ContactLaw.hpp"
#include "dem/EngineBase.hpp"
#include "dem/System.hpp"

#include <algorithm>
#include <cmath>

namespace dem {

namespace {

constexpr double pi = 3.14159265358979323846;

/// The mass of a sphere of the class's density and diameter d.
double sphereMass(const ParticleClass& c, double d)
{
    return c.density * pi * d * d * d / 6.0;
}

/// The lightest particle of the class: of its smallest diameter.
double classMass(const ParticleClass& c) { return sphereMass(c, smallestDiameter(c)); }

/// The particle the class's contact laws are made for: of its mean diameter (the engines'
/// laws, EngineBase.cpp).
double lawMass(const ParticleClass& c) { return sphereMass(c, meanDiameter(c)); }

std::string className(const Settings& s, int k)
{
    return "classes[" + std::to_string(k) + "] ('" + s.classes[k].name + "')";
}

/// One kind of contact: a pair of classes or a class on a wall. A class with a diameter
/// distribution runs its laws made for its mean diameter (mEffLaw, rEff) with particles as
/// light as its smallest (m, mEff): the bounds are those of the smallest particles.
struct ContactKind {
    int a, b;            ///< the classes (b = a on a wall)
    int lighter;         ///< the lighter class
    double m;            ///< its lightest particle's mass, kg
    double mEff;         ///< effective mass of the lightest particles, kg
    double mEffLaw;      ///< effective mass the law's damping is made for, kg
    double rEff;         ///< effective radius of the law, m
    double eStar;        ///< Hertz's effective modulus, Pa (HertzMindlin)
    bool wall;
};

/// body(kind) for every pair of classes and every class on a wall.
template <class Body> void forEachContactKind(const Settings& s, const Body& body)
{
    const ContactSettings& c = s.contact;
    const bool hertz = c.law == ContactLawType::hertzMindlin;
    const std::size_t n = s.classes.size();
    for (std::size_t a = 0; a < n; ++a) {
        const ParticleClass& ca = s.classes[a];
        const double ma = classMass(ca);
        const double la = lawMass(ca);
        const double ra = 0.5 * meanDiameter(ca);
        for (std::size_t b = a; b < n; ++b) {
            const ParticleClass& cb = s.classes[b];
            const double mb = classMass(cb);
            const double lb = lawMass(cb);
            const double rb = 0.5 * meanDiameter(cb);
            const double eStar = hertz ? effectiveYoungsModulus(ca.youngsModulus, ca.poissonRatio,
                                                                cb.youngsModulus, cb.poissonRatio)
                                       : 0.0;
            body(ContactKind{static_cast<int>(a), static_cast<int>(b),
                             static_cast<int>(ma <= mb ? a : b), std::min(ma, mb),
                             ma * mb / (ma + mb), la * lb / (la + lb), ra * rb / (ra + rb), eStar,
                             false});
        }
        const double eStar = hertz ? effectiveYoungsModulus(ca.youngsModulus, ca.poissonRatio,
                                                            c.wallYoungsModulus, c.wallPoissonRatio)
                                   : 0.0;
        body(ContactKind{static_cast<int>(a), static_cast<int>(a), static_cast<int>(a), ma, ma,
                         la, ra, eStar, true});
    }
}

/// The restitution of a kind of contact and the entry that gives it: the global one, or the
/// pair's or the wall's own.
std::pair<std::string, double> restitutionOf(const Settings& s, const ContactKind& k)
{
    const ContactSettings& c = s.contact;
    if (k.wall) {
        const double e = wallCoefficients(c, k.a).restitution;
        return {e == c.restitutionWall ? "restitutionWall" : wallName(s, k.a) + " restitutionWall", e};
    }
    const double e = pairCoefficients(c, k.a, k.b).restitution;
    return {e == c.restitution ? "restitution" : pairName(s, k.a, k.b) + " restitution", e};
}

/// Hertz's peak overlap of a head-on impact at speed v, m.
double hertzPeakOverlap(const ContactKind& k, double v)
{
    return std::pow(15.0 * k.mEff * v * v / (16.0 * k.eStar * std::sqrt(k.rEff)), 0.4);
}

/// The normal damping of a kind at its largest: the linear law's eta_n, or Hertz-Mindlin's
/// at the elastic peak overlap of an impact at hertzSpeed (damping lowers the peak), N s/m;
/// the law's (made for mEffLaw), the peak overlap of the lightest particles.
double largestNormalDamping(const Settings& s, const ContactKind& k)
{
    const ContactSettings& c = s.contact;
    const double e = restitutionOf(s, k).second;
    if (c.law != ContactLawType::hertzMindlin) return dampingFromRestitution(k.mEffLaw, c.kn, e);
    const double hertzKn = 4.0 / 3.0 * k.eStar * std::sqrt(k.rEff);
    const double delta = hertzPeakOverlap(k, hertzSpeed(s));
    return hertzDampingFromRestitution(e) * std::sqrt(k.mEffLaw * hertzKn)
           * std::sqrt(std::sqrt(delta));
}

/// The kind of contact with the smallest mEff/eta_n and that step (dashpotTimeStep).
std::pair<ContactKind, double> dashpotLimited(const Settings& s)
{
    ContactKind worst{};
    double step = INFINITY;
    forEachContactKind(s, [&](const ContactKind& k) {
        const double eta = largestNormalDamping(s, k);
        if (eta > 0.0 && k.mEff / eta < step) {
            step = k.mEff / eta;
            worst = k;
        }
    });
    return {worst, step};
}

/// Above this fraction of dashpotTimeStep the bounce loses accuracy (measured, TestStepBound:
/// at 0.6-0.7 a restitution of 0.01 comes out 0.0092-0.0102): warned.
constexpr double dashpotWarnFraction = 0.5;

} // namespace

double bedSpeedScale(const Settings& settings)
{
    double d = 0.0;
    for (const ParticleClass& c : settings.classes) d = std::max(d, largestDiameter(c));
    return std::sqrt(std::hypot(settings.gravity[0], settings.gravity[1]) * d);
}

double hertzSpeed(const Settings& settings)
{
    return std::max(settings.contact.impactSpeed, bedSpeedScale(settings));
}

double timeStepBound(const Settings& settings, int* smallestClass)
{
    int kMin = 0;
    double bound = INFINITY;
    if (settings.contact.law == ContactLawType::hertzMindlin) {
        const double v = hertzSpeed(settings);
        forEachContactKind(settings, [&](const ContactKind& k) {
            const double stiffness = 2.0 * k.eStar * std::sqrt(k.rEff * hertzPeakOverlap(k, v));
            const double b = 2.0 * pi / 5.0 * std::sqrt(k.m / stiffness);
            if (b < bound) {
                bound = b;
                kMin = k.lighter;
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
        const double v = hertzSpeed(settings);
        forEachContactKind(settings, [&](const ContactKind& k) {
            tc = std::min(tc, hertzContactTime(k.mEff, k.rEff, k.eStar, v));
        });
        return tc;
    }
    int k = 0;
    timeStepBound(settings, &k);
    // A pair of the class's lightest particles, with the damping of its law
    const double mEff = 0.5 * classMass(settings.classes[k]);
    const double mEffLaw = 0.5 * lawMass(settings.classes[k]);
    const double e = pairCoefficients(c, k, k).restitution;
    return linearContactDuration(mEff, c.kn, dampingFromRestitution(mEffLaw, c.kn, e));
}

// Measured with the paper's particles (TestStepBound; docs/theory/numerics.md): at dt = t_c/10 a
// head-on pair's restitution is within 1 %; at 0.25 t_c within 5 % and a settling bed comes
// to rest; above 0.4 t_c the bed does not (0.45 t_c: overlaps double; 0.55 t_c, just under
// eq. 7's bound: particles thrown out of the box).
double safeTimeStep(const Settings& settings) { return 0.1 * pairContactTime(settings); }
double stableTimeStep(const Settings& settings) { return 0.25 * pairContactTime(settings); }

double dashpotTimeStep(const Settings& settings) { return dashpotLimited(settings).second; }

void checkTimeStep(const Settings& s)
{
    const ContactSettings& c = s.contact;
    const bool hertz = c.law == ContactLawType::hertzMindlin;
    int kMin = 0;
    const double bound = timeStepBound(s, &kMin);
    if (s.dt > bound) {
        const bool bedScale = hertz && c.impactSpeed < bedSpeedScale(s);
        const std::string stiffness = hertz
            ? "(2 pi/5) sqrt(m/S), S Hertz's stiffness at the peak overlap of an impact at "
              + (bedScale ? "the bed's own speed scale sqrt(|g| d_max) = " + formatValue(bedSpeedScale(s))
                                + " m/s (above impactSpeed = " + formatValue(c.impactSpeed)
                                + " m/s: a bed under gravity collides at least that fast)"
                          : "impactSpeed = " + formatValue(c.impactSpeed) + " m/s") + ","
            : "(2 pi/5) sqrt(m_min/kn) = " + formatValue(bound) + " s (paper eq. 7)";
        throw Error("dt = " + formatValue(s.dt) + " s is outside (0, " + formatValue(bound)
                    + "]: the time-step bound " + stiffness + " of the smallest particle, "
                    + className(s, kMin) + " of diameter "
                    + formatValue(smallestDiameter(s.classes[kMin])) + " m");
    }
    // An explicit step with a dashpot eta on a contact of effective mass mEff reverses the
    // relative velocity within one step when eta dt/mEff > 1: the contact then rebounds
    // nearly elastically whatever restitution asked for (docs/theory/numerics.md, "The DEM step's bound")
    const auto [kind, dashpot] = dashpotLimited(s);
    if (s.dt > dashpot) {
        const auto [entry, e] = restitutionOf(s, kind);
        throw Error("dt = " + formatValue(s.dt) + " s (the DEM step, deltaT) is above the "
                    "dashpot's stability bound at " + entry + " = " + formatValue(e) + ": the "
                    "normal damping eta of a " + className(s, kind.lighter)
                    + (kind.wall ? " contact on a wall" : " pair contact") + " reverses the "
                    "relative velocity within one step (eta dt/m_eff = "
                    + formatValue(s.dt / dashpot) + " > 1) and the contact rebounds nearly "
                    "elastically; allowed: dt in (0, " + formatValue(dashpot) + "] s, the largest "
                    "step that works at this " + entry + ", or a larger " + entry);
    }
}

std::vector<std::string> settingsWarnings(const Settings& s)
{
    std::vector<std::string> out;
    const ContactSettings& c = s.contact;
    const auto [kind, dashpot] = dashpotLimited(s);
    if (s.dt > dashpotWarnFraction * dashpot) {
        const auto [entry, e] = restitutionOf(s, kind);
        out.push_back("dt = " + formatValue(s.dt) + " s (the DEM step, deltaT) is near the "
                      "dashpot's stability bound " + formatValue(dashpot) + " s at " + entry
                      + " = " + formatValue(e)
                      + " (eta dt/m_eff = " + formatValue(s.dt / dashpot) + "): the rebound of "
                      "strongly damped contacts is off by up to 10 %; a step of at most "
                      + formatValue(dashpotWarnFraction * dashpot) + " s is accurate");
    }
    if (c.law == ContactLawType::hertzMindlin && c.impactSpeed < bedSpeedScale(s)) {
        out.push_back("impactSpeed = " + formatValue(c.impactSpeed) + " m/s is below the bed's "
                      "own speed scale sqrt(|g| d_max) = " + formatValue(bedSpeedScale(s))
                      + " m/s, the speed of a fall through half the largest diameter: the step "
                      "bounds take the contact time at " + formatValue(bedSpeedScale(s))
                      + " m/s; set impactSpeed to the fastest impact expected");
    }
    return out;
}

} // namespace dem
