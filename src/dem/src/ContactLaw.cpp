// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "dem/ContactLaw.hpp"

#include <cmath>

namespace dem {

namespace {
constexpr double pi = 3.14159265358979323846;
}

double dampingFromRestitution(double mEff, double kn, double e)
{
    const double lnE = std::log(e);
    return 2.0 * std::sqrt(mEff * kn) * std::abs(lnE) / std::sqrt(pi * pi + lnE * lnE);
}

ContactLaw makeContactLaw(double mEff, double kn, double kt, double e, double mu)
{
    ContactLaw law;
    law.kn = kn;
    law.kt = kt < 0.0 ? 2.0 / 7.0 * kn : kt;
    law.etaN = dampingFromRestitution(mEff, kn, e);
    law.etaT = law.etaN;
    law.mu = mu;
    return law;
}

void addRollingResistance(ContactLaw& law, double muR, double rRolling, double iEff, double dt)
{
    law.rollingTorquePerForce = muR * rRolling;
    law.rollingTorquePerSpin = iEff / (rollingStopSteps * dt);
}

double contactDuration(double mEff, double kn, double etaN)
{
    const double a = etaN / (2.0 * mEff);
    return pi / std::sqrt(kn / mEff - a * a);
}

} // namespace dem
