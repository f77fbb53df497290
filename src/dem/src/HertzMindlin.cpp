// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Hertz-Mindlin (HertzMindlin.hpp): its damping from the restitution, the effective moduli, its
// contact time, its entries' checks and its step bounds at the impact speed.

#include "dem/HertzMindlin.hpp"
#include "dem/StepBounds.hpp"

#include "LawSupport.hpp"

#include <cmath>
#include <map>
#include <mutex>

namespace dem {

namespace {

constexpr double pi = 3.14159265358979323846;

/// Hertz's effective modulus of a kind of contact, Pa.
double effectiveModulus(const ContactKind& k)
{
    return effectiveYoungsModulus(k.first.youngsModulus, k.first.poissonRatio,
                                  k.second.youngsModulus, k.second.poissonRatio);
}

/// Hertz's peak overlap of a head-on impact at speed v of a kind of modulus eStar, m.
double peakOverlap(const ContactKind& k, double eStar, double v)
{
    return std::pow(15.0 * k.mEff * v * v / (16.0 * eStar * std::sqrt(k.rEff)), 0.4);
}

} // namespace

double hertzRestitutionOfDamping(double alpha)
{
    // RK4 on (x, v) in the units delta*, delta*/v0; the step fine enough for the x^1/4 of
    // the first steps (e to 1e-6 against a step half as long)
    const double h = 5e-5;
    auto accel = [alpha](double x, double v) {
        const double xp = std::max(x, 0.0);
        return -std::max(xp * std::sqrt(xp) + alpha * std::sqrt(std::sqrt(xp)) * v, 0.0);
    };
    // The contact ends when the force x^1/4 (x^5/4 + alpha v) vanishes (or the overlap)
    auto pressed = [alpha](double x, double v) {
        return x > 0.0 && x * std::sqrt(std::sqrt(x)) + alpha * v > 0.0;
    };
    double x = 0.0, v = 1.0;
    for (long k = 0; k < 100000000L; ++k) {
        const double k1x = v, k1v = accel(x, v);
        const double k2x = v + 0.5 * h * k1v, k2v = accel(x + 0.5 * h * k1x, v + 0.5 * h * k1v);
        const double k3x = v + 0.5 * h * k2v, k3v = accel(x + 0.5 * h * k2x, v + 0.5 * h * k2v);
        const double k4x = v + h * k3v, k4v = accel(x + h * k3x, v + h * k3v);
        const double xNew = x + h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
        const double vNew = v + h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
        if (k > 0 && !pressed(xNew, vNew)) {
            // Where the force crosses zero between the steps (v' = 0 there: v is flat)
            const double f0 = x * std::sqrt(std::sqrt(x)) + alpha * v;
            const double xq = std::max(xNew, 0.0);
            const double f1 = xq * std::sqrt(std::sqrt(xq)) + alpha * vNew;
            const double w = f0 > f1 ? f0 / (f0 - f1) : 1.0;
            return -(v + w * (vNew - v));
        }
        x = xNew;
        v = vNew;
    }
    return 0.0;
}

double hertzDampingFromRestitution(double e)
{
    // Bisection (e falls monotonically with alpha), once per e: cached
    static std::mutex mutex;
    static std::map<double, double> solved;
    const std::lock_guard<std::mutex> lock(mutex);
    if (const auto it = solved.find(e); it != solved.end()) return it->second;
    double alpha = 0.0;
    if (e < 1.0) {
        double low = 0.0, high = 1.0;
        while (hertzRestitutionOfDamping(high) > e && high < 1e6) high *= 2.0;
        for (int k = 0; k < 48 && high - low > 1e-12 * high; ++k) {
            const double mid = 0.5 * (low + high);
            (hertzRestitutionOfDamping(mid) > e ? low : high) = mid;
        }
        alpha = 0.5 * (low + high);
    }
    solved[e] = alpha;
    return alpha;
}

double effectiveYoungsModulus(double e1, double nu1, double e2, double nu2)
{
    return 1.0 / ((1.0 - nu1 * nu1) / e1 + (1.0 - nu2 * nu2) / e2);
}

double effectiveShearModulus(double e1, double nu1, double e2, double nu2)
{
    const double g1 = e1 / (2.0 * (1.0 + nu1));
    const double g2 = e2 / (2.0 * (1.0 + nu2));
    return 1.0 / ((2.0 - nu1) / g1 + (2.0 - nu2) / g2);
}

HertzMindlin::Coefficients HertzMindlin::make(double mEff, double rEff, double eStar,
                                             double gStar, double e,
                                             double tangentialDampingRatio)
{
    Coefficients law;
    const double alpha = hertzDampingFromRestitution(e);
    law.hertzKn = 4.0 / 3.0 * eStar * std::sqrt(rEff);
    law.hertzEtaN = alpha * std::sqrt(mEff * law.hertzKn);
    law.mindlinKt = 8.0 * gStar * std::sqrt(rEff);
    // eta_n = alpha sqrt(2/3 mEff S_n) with S_n = dF_n/d delta = 2 E* sqrt(R* delta): the
    // same form with Mindlin's S_t = 8 G* sqrt(R* delta)
    law.mindlinEtaT = tangentialDampingRatio * alpha * std::sqrt(2.0 / 3.0 * mEff * law.mindlinKt);
    return law;
}

HertzMindlin::Coefficients HertzMindlin::coefficients(const ContactSettings& c,
                                                      const ContactPartners& p)
{
    const ElasticMaterial& i = p.first;
    const ElasticMaterial& j = p.second;
    return make(p.mEff, p.rEff,
                effectiveYoungsModulus(i.youngsModulus, i.poissonRatio, j.youngsModulus,
                                       j.poissonRatio),
                effectiveShearModulus(i.youngsModulus, i.poissonRatio, j.youngsModulus,
                                      j.poissonRatio),
                p.restitution, c.tangentialDampingRatio);
}

double hertzContactTime(double mEff, double rEff, double eStar, double v)
{
    // t_c = 2 (delta_max/v) int_0^1 dx/sqrt(1 - x^5/2) = (4/5) B(2/5, 1/2) delta_max/v
    const double factor = 0.8 * std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);
    const double deltaMax = std::pow(15.0 * mEff * v * v / (16.0 * eStar * std::sqrt(rEff)), 0.4);
    return factor * deltaMax / v;
}

void HertzMindlin::validate(const Settings& s)
{
    const ContactSettings& c = s.contact;
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

double HertzMindlin::timeStepBound(const Settings& s, int* smallestClass)
{
    int kMin = 0;
    double bound = INFINITY;
    const double v = hertzSpeed(s);
    forEachContactKind(s, [&](const ContactKind& k) {
        const double eStar = effectiveModulus(k);
        const double stiffness = 2.0 * eStar * std::sqrt(k.rEff * peakOverlap(k, eStar, v));
        const double b = 2.0 * pi / 5.0 * std::sqrt(k.m / stiffness);
        if (b < bound) {
            bound = b;
            kMin = k.lighter;
        }
    });
    if (smallestClass) *smallestClass = kMin;
    return bound;
}

std::string HertzMindlin::timeStepBoundText(const Settings& s, double)
{
    const ContactSettings& c = s.contact;
    const bool bedScale = c.impactSpeed < bedSpeedScale(s);
    return "(2 pi/5) sqrt(m/S), S Hertz's stiffness at the peak overlap of an impact at "
           + (bedScale ? "the bed's own speed scale sqrt(|g| d_max) = " + formatValue(bedSpeedScale(s))
                             + " m/s (above impactSpeed = " + formatValue(c.impactSpeed)
                             + " m/s: a bed under gravity collides at least that fast)"
                       : "impactSpeed = " + formatValue(c.impactSpeed) + " m/s") + ",";
}

double HertzMindlin::contactTime(const Settings& s)
{
    double tc = INFINITY;
    const double v = hertzSpeed(s);
    forEachContactKind(s, [&](const ContactKind& k) {
        tc = std::min(tc, hertzContactTime(k.mEff, k.rEff, effectiveModulus(k), v));
    });
    return tc;
}

double HertzMindlin::normalDamping(const Settings& s, const ContactKind& k, double restitution)
{
    const double eStar = effectiveModulus(k);
    const double hertzKn = 4.0 / 3.0 * eStar * std::sqrt(k.rEff);
    const double delta = peakOverlap(k, eStar, hertzSpeed(s));
    return hertzDampingFromRestitution(restitution) * std::sqrt(k.mEffLaw * hertzKn)
           * std::sqrt(std::sqrt(delta));
}

std::vector<std::string> HertzMindlin::warnings(const Settings& s)
{
    const ContactSettings& c = s.contact;
    if (!(c.impactSpeed < bedSpeedScale(s))) return {};
    return {"impactSpeed = " + formatValue(c.impactSpeed) + " m/s is below the bed's "
            "own speed scale sqrt(|g| d_max) = " + formatValue(bedSpeedScale(s))
            + " m/s, the speed of a fall through half the largest diameter: the step "
              "bounds take the contact time at " + formatValue(bedSpeedScale(s))
            + " m/s; set impactSpeed to the fastest impact expected"};
}

} // namespace dem
