// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "dem/ContactLaw.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>

namespace dem {

namespace {
constexpr double pi = 3.14159265358979323846;
}

double restitutionOfDampingRatio(double zeta)
{
    // x'' + 2 zeta x' + x = 0 from x = 0, x' = 1 (time in 1/omega_0) until the force
    // x + 2 zeta x' vanishes; e = -x' then (Schwager and Poeschel 2007)
    if (zeta <= 0.0) return 1.0;
    if (zeta < 1.0) {
        const double w = std::sqrt(1.0 - zeta * zeta);
        const double phase = pi - std::atan2(2.0 * zeta * w, 1.0 - 2.0 * zeta * zeta);
        return std::exp(-zeta * phase / w) * (zeta / w * std::sin(phase) - std::cos(phase));
    }
    if (zeta == 1.0) return std::exp(-2.0);
    // Overdamped: x ~ exp(r1 t) - exp(r2 t), r1 r2 = 1, r1 = -1/(zeta + s) without cancellation
    const double s = std::sqrt(zeta * zeta - 1.0);
    const double r2 = -zeta - s;
    const double r1 = 1.0 / r2;
    // (1 + 2 zeta r1) exp(r1 t) = (1 + 2 zeta r2) exp(r2 t), with 1 + 2 zeta r1 = -r1^2
    const double t = std::log((1.0 + 2.0 * zeta * r2) / (-r1 * r1)) / (2.0 * s);
    return -(r1 * std::exp(r1 * t) - r2 * std::exp(r2 * t)) / (2.0 * s);
}

double dampingFromRestitution(double mEff, double kn, double e)
{
    // e falls monotonically with zeta, from 1 at 0 to 0 as zeta -> inf: bisection
    double low = 0.0, high = 1.0;
    while (restitutionOfDampingRatio(high) > e && high < 1e12) high *= 2.0;
    for (int k = 0; k < 200 && high - low > 1e-15 * high; ++k) {
        const double mid = 0.5 * (low + high);
        (restitutionOfDampingRatio(mid) > e ? low : high) = mid;
    }
    return 2.0 * std::sqrt(mEff * kn) * 0.5 * (low + high);
}

ContactLaw makeContactLaw(double mEff, double kn, double kt, double e, double mu,
                          double tangentialDampingRatio)
{
    ContactLaw law;
    law.kn = kn;
    law.kt = kt < 0.0 ? 2.0 / 7.0 * kn : kt;
    law.etaN = dampingFromRestitution(mEff, kn, e);
    law.etaT = tangentialDampingRatio * law.etaN;
    law.mu = mu;
    return law;
}

double linearContactDuration(double mEff, double kn, double etaN)
{
    // The first zero of the force x + 2 zeta x' after the start (time in 1/omega_0)
    const double zeta = etaN / (2.0 * std::sqrt(mEff * kn));
    double t;
    if (zeta < 1.0) {
        const double w = std::sqrt(1.0 - zeta * zeta);
        t = (pi - std::atan2(2.0 * zeta * w, 1.0 - 2.0 * zeta * zeta)) / w;
    } else if (zeta == 1.0) {
        t = 2.0;
    } else {
        const double s = std::sqrt(zeta * zeta - 1.0);
        const double r2 = -zeta - s;
        const double r1 = 1.0 / r2;
        t = std::log((1.0 + 2.0 * zeta * r2) / (-r1 * r1)) / (2.0 * s);
    }
    return t * std::sqrt(mEff / kn);
}

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

ContactLaw makeHertzMindlinLaw(double mEff, double rEff, double eStar, double gStar, double e,
                               double mu, double tangentialDampingRatio)
{
    ContactLaw law{};
    const double alpha = hertzDampingFromRestitution(e);
    law.hertzKn = 4.0 / 3.0 * eStar * std::sqrt(rEff);
    law.hertzEtaN = alpha * std::sqrt(mEff * law.hertzKn);
    law.mindlinKt = 8.0 * gStar * std::sqrt(rEff);
    // eta_n = alpha sqrt(2/3 mEff S_n) with S_n = dF_n/d delta = 2 E* sqrt(R* delta): the
    // same form with Mindlin's S_t = 8 G* sqrt(R* delta)
    law.mindlinEtaT = tangentialDampingRatio * alpha * std::sqrt(2.0 / 3.0 * mEff * law.mindlinKt);
    law.mu = mu;
    return law;
}

double hertzContactTime(double mEff, double rEff, double eStar, double v)
{
    // t_c = 2 (delta_max/v) int_0^1 dx/sqrt(1 - x^5/2) = (4/5) B(2/5, 1/2) delta_max/v
    const double factor = 0.8 * std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);
    const double deltaMax = std::pow(15.0 * mEff * v * v / (16.0 * eStar * std::sqrt(rEff)), 0.4);
    return factor * deltaMax / v;
}

void addRollingResistance(ContactLaw& law, double muR, double rRolling, double iEff, double dt)
{
    law.rollingTorquePerForce = muR * rRolling;
    law.rollingTorquePerSpin = iEff / (rollingStopSteps * dt);
}

} // namespace dem
