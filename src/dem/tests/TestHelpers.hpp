// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Shared set-up of the DEM tests: the paper's particles (docs/theory/paper-model.md, "The case").

#include "dem/Facade.hpp"

#include <cmath>

namespace dem::test {

constexpr double pi = 3.14159265358979323846;
constexpr double dSmall = 1.5e-3;    // m, paper
constexpr double dLarge = 2.5e-3;    // m, paper
constexpr double rho = 2525.0;       // kg/m^3, paper

inline double sphereMass(double d) { return rho * pi * d * d * d / 6.0; }

/// Paper classes and contact settings in the given box, no gravity.
inline Settings paperSettings(const Box& box, double dt = 1e-5)
{
    Settings s;
    s.classes = {{"small", dSmall, rho}, {"large", dLarge, rho}};
    s.box = box;
    s.gravity[0] = 0.0;
    s.gravity[1] = 0.0;
    s.dt = dt;
    return s;
}

/// Contact duration of a linear spring-dashpot, written here from model.md so the tests do
/// not take it from the library: t_c = pi / sqrt(kn/mEff - (eta/(2 mEff))^2),
/// eta = 2 sqrt(mEff kn) |ln e| / sqrt(pi^2 + ln^2 e).
inline double etaFor(double mEff, double kn, double e)
{
    const double l = std::log(e);
    return 2.0 * std::sqrt(mEff * kn) * std::abs(l) / std::sqrt(pi * pi + l * l);
}
inline double contactTime(double mEff, double kn, double e)
{
    const double a = etaFor(mEff, kn, e) / (2.0 * mEff);
    return pi / std::sqrt(kn / mEff - a * a);
}

} // namespace dem::test
