// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The DEM step's bounds (docs/theory/numerics.md, "The DEM step's bound"): each law's contact
// time of the stiffest contact (its policy's), the dashpot's own stability, and the check
// validateSettings makes of them and the warnings near them.

#include "dem/ContactLaw.hpp"
#include "dem/EngineBase.hpp"
#include "dem/System.hpp"

#include "LawSupport.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace dem {

namespace {

constexpr double pi = 3.14159265358979323846;

/// The mass of a sphere of the class's density and diameter d.
double sphereMass(const ParticleClass& c, double d)
{
    return c.density * pi * d * d * d / 6.0;
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

/// The kind of contact with the smallest mEff/eta_n, eta_n the law's at its largest, and
/// that step (dashpotTimeStep).
std::pair<ContactKind, double> dashpotLimited(const Settings& s)
{
    return withLaw(s.contact.law, [&](auto law) {
        ContactKind worst{};
        double step = INFINITY;
        forEachContactKind(s, [&](const ContactKind& k) {
            const double e = restitutionOf(s, k).second;
            const double eta = decltype(law)::normalDamping(s, k, e);
            if (eta > 0.0 && k.mEff / eta < step) {
                step = k.mEff / eta;
                worst = k;
            }
        });
        return std::pair<ContactKind, double>{worst, step};
    });
}

/// Above this fraction of dashpotTimeStep the bounce loses accuracy (measured, TestStepBound:
/// at 0.6-0.7 a restitution of 0.01 comes out 0.0092-0.0102): warned.
constexpr double dashpotWarnFraction = 0.5;

} // namespace

double classMass(const ParticleClass& c) { return sphereMass(c, smallestDiameter(c)); }

double lawMass(const ParticleClass& c) { return sphereMass(c, meanDiameter(c)); }

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
    return withLaw(settings.contact.law, [&](auto law) {
        return decltype(law)::timeStepBound(settings, smallestClass);
    });
}

double pairContactTime(const Settings& settings)
{
    return withLaw(settings.contact.law,
                   [&](auto law) { return decltype(law)::contactTime(settings); });
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
    int kMin = 0;
    const double bound = timeStepBound(s, &kMin);
    if (s.dt > bound) {
        const std::string stiffness = withLaw(s.contact.law, [&](auto law) {
            return decltype(law)::timeStepBoundText(s, bound);
        });
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
    const std::vector<std::string> law =
        withLaw(s.contact.law, [&](auto policy) { return decltype(policy)::warnings(s); });
    out.insert(out.end(), law.begin(), law.end());
    return out;
}

} // namespace dem
