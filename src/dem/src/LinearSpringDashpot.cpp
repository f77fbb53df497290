// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The linear spring-dashpot (LinearSpringDashpot.hpp): its damping from the restitution, its
// contact duration and its step bounds.

#include "dem/LinearSpringDashpot.hpp"

#include "LawSupport.hpp"

#include <cmath>

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

LinearSpringDashpot::Coefficients LinearSpringDashpot::make(double mEff, double kn, double kt,
                                                           double e,
                                                           double tangentialDampingRatio)
{
    Coefficients law;
    law.kn = kn;
    law.kt = kt < 0.0 ? 2.0 / 7.0 * kn : kt;
    law.etaN = dampingFromRestitution(mEff, kn, e);
    law.etaT = tangentialDampingRatio * law.etaN;
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

double LinearSpringDashpot::timeStepBound(const Settings& s, int* smallestClass)
{
    int kMin = 0;
    double mMin = INFINITY;
    for (std::size_t k = 0; k < s.classes.size(); ++k) {
        const double m = classMass(s.classes[k]);
        if (m < mMin) {
            mMin = m;
            kMin = static_cast<int>(k);
        }
    }
    if (smallestClass) *smallestClass = kMin;
    return 2.0 * pi / 5.0 * std::sqrt(mMin / s.contact.kn);
}

std::string LinearSpringDashpot::timeStepBoundText(const Settings&, double bound)
{
    return "(2 pi/5) sqrt(m_min/kn) = " + formatValue(bound) + " s (paper eq. 7)";
}

double LinearSpringDashpot::contactTime(const Settings& s)
{
    const ContactSettings& c = s.contact;
    int k = 0;
    timeStepBound(s, &k);
    // A pair of the class's lightest particles, with the damping of its law
    const double mEff = 0.5 * classMass(s.classes[k]);
    const double mEffLaw = 0.5 * lawMass(s.classes[k]);
    const double e = pairCoefficients(c, k, k).restitution;
    return linearContactDuration(mEff, c.kn, dampingFromRestitution(mEffLaw, c.kn, e));
}

double LinearSpringDashpot::normalDamping(const Settings& s, const ContactKind& k,
                                          double restitution)
{
    return dampingFromRestitution(k.mEffLaw, s.contact.kn, restitution);
}

} // namespace dem
