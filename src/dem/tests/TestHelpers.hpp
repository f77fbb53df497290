// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Shared set-up of the DEM tests: the paper's particles (docs/theory/paper-model.md, "The case").

#include "dem/Facade.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

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

/// The record tests' bed: 120 small and 40 large particles packed in [0, 0.03] x [0, 0.04] m,
/// seed 42, settled for 2 ms.
inline BedRecipe smallBedRecipe()
{
    BedRecipe r;
    r.countPerClass = {120, 40};
    r.region = {0.0, 0.03, 0.0, 0.04};
    r.seed = 42;
    r.settleTime = 0.002;
    return r;
}

/// A file name in the test's temporary directory.
inline std::string tempPath(const std::string& name) { return testing::TempDir() + name; }

/// A file's whole content.
inline std::string readBytes(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Replaces a file's content with `bytes`.
inline void writeBytes(const std::string& path, const std::string& bytes)
{
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

/// The message of the dem::Error that `call` throws ("" if none).
template <class Call> std::string errorOf(Call&& call)
{
    try {
        call();
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

/// Head-on contact of the linear spring-dashpot with its normal force clamped at zero,
/// written here from the damped oscillator so the tests do not take it from the library:
/// with time in 1/omega0 (omega0 = sqrt(kn/mEff)), zeta = eta/(2 sqrt(mEff kn)) and the
/// overlap x(0) = 0, x'(0) = 1, the particles part when the force x + 2 zeta x' vanishes
/// (Schwager and Poeschel 2007, Granul. Matter 9:465). End of the contact and rebound speed:
struct ClampedContactEnd {
    double time;          ///< in 1/omega0
    double restitution;   ///< -x' at that time
};
inline ClampedContactEnd clampedContactEnd(double zeta)
{
    if (zeta == 0.0) return {pi, 1.0};
    if (std::abs(zeta - 1.0) < 1e-9) {   // x = t exp(-t): x + 2x' = (2 - t) exp(-t)
        return {2.0, std::exp(-2.0)};
    }
    if (zeta < 1.0) {   // x = exp(-zeta t) sin(q t)/q: tan(q t) = -2 zeta q/(1 - 2 zeta^2)
        const double q = std::sqrt(1.0 - zeta * zeta);
        double qt = std::atan(-2.0 * zeta * q / (1.0 - 2.0 * zeta * zeta));
        if (qt <= 0.0) qt += pi;   // the first root after the start
        const double t = qt / q;
        return {t, -std::exp(-zeta * t) * (std::cos(qt) - zeta / q * std::sin(qt))};
    }
    // x = exp(-zeta t) sinh(s t)/s: tanh(s t) = 2 zeta s/(2 zeta^2 - 1)
    const double sq = std::sqrt(zeta * zeta - 1.0);
    const double st = std::atanh(2.0 * zeta * sq / (2.0 * zeta * zeta - 1.0));
    const double t = st / sq;
    return {t, -std::exp(-zeta * t) * (std::cosh(st) - zeta / sq * std::sinh(st))};
}

/// The damping eta that gives restitution e under the clamped law (bisection on zeta: e
/// falls monotonically with it), N s/m.
inline double etaFor(double mEff, double kn, double e)
{
    double low = 0.0, high = 64.0;
    for (int k = 0; k < 200; ++k) {
        const double mid = 0.5 * (low + high);
        (clampedContactEnd(mid).restitution > e ? low : high) = mid;
    }
    return 2.0 * std::sqrt(mEff * kn) * 0.5 * (low + high);
}

/// Duration of the clamped head-on contact at restitution e, s.
inline double contactTime(double mEff, double kn, double e)
{
    const double zeta = etaFor(mEff, kn, e) / (2.0 * std::sqrt(mEff * kn));
    return clampedContactEnd(zeta).time * std::sqrt(mEff / kn);
}

/// The Kolmogorov-Smirnov distance of the values from the uniform distribution on [a, b].
inline double ksUniform(std::vector<double> v, double a, double b)
{
    std::sort(v.begin(), v.end());
    const double n = static_cast<double>(v.size());
    double d = 0.0;
    for (std::size_t i = 0; i < v.size(); ++i) {
        const double f = (v[i] - a) / (b - a);
        d = std::max({d, f - i / n, (i + 1) / n - f});
    }
    return d;
}

} // namespace dem::test
