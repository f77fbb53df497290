// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// A size class's diameters (Diameters.hpp): the distributions' checks, moments and draws.

#include "dem/Diameters.hpp"
#include "dem/Error.hpp"
#include "dem/Facade.hpp"
#include "dem/Random.hpp"

#include <algorithm>
#include <cmath>

namespace dem {

namespace {

constexpr double pi = 3.14159265358979323846;

using Type = DiameterDistributionType;

/// The standard normal's density and distribution function.
double phi(double x) { return std::exp(-0.5 * x * x) / std::sqrt(2.0 * pi); }
double Phi(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

/// The probability of the normal between the bounds.
double probabilityInBounds(const DiameterDistribution& d)
{
    const double a = (d.min - d.mean) / d.standardDeviation;
    const double b = (d.max - d.mean) / d.standardDeviation;
    return Phi(b) - Phi(a);
}

/// E[X^k] of the truncated normal by the recursion
/// m_k = mu m_(k-1) + (k-1) s^2 m_(k-2) - s (max^(k-1) phi(beta) - min^(k-1) phi(alpha))/Z,
/// m_0 = 1, m_(-1) = 0 (alpha, beta the bounds in standard deviations, Z their probability).
double truncatedNormalMoment(const DiameterDistribution& d, int k)
{
    const double s = d.standardDeviation;
    const double alpha = (d.min - d.mean) / s;
    const double beta = (d.max - d.mean) / s;
    const double z = Phi(beta) - Phi(alpha);
    double previous = 0.0, current = 1.0;   // m_(j-2), m_(j-1)
    for (int j = 1; j <= k; ++j) {
        const double next = d.mean * current + (j - 1) * s * s * previous
                            - s * (std::pow(d.max, j - 1) * phi(beta)
                                   - std::pow(d.min, j - 1) * phi(alpha)) / z;
        previous = current;
        current = next;
    }
    return current;
}

/// A standard normal by Box-Muller (the cosine branch; 1 - u keeps the logarithm finite).
double standardNormal(Random& random)
{
    const double u1 = 1.0 - random.uniform();
    const double u2 = random.uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * pi * u2);
}

std::string range(double a, double b)
{
    return "[" + formatValue(a) + ", " + formatValue(b) + "]";
}

} // namespace

std::string distributionName(DiameterDistributionType type)
{
    switch (type) {
    case Type::truncatedNormal: return "normal";
    case Type::samples: return "samples";
    case Type::single: break;
    }
    return "single";
}

void validateDistribution(const DiameterDistribution& d, const std::string& what)
{
    const std::string name = what + " diameter";
    if (d.type == Type::truncatedNormal) {
        if (!(d.standardDeviation > 0.0) || !std::isfinite(d.standardDeviation)) {
            throw Error(name + " standardDeviation = " + formatValue(d.standardDeviation)
                        + " m is outside (0, inf)");
        }
        if (!(d.min > 0.0) || !std::isfinite(d.min)) {
            throw Error(name + " min = " + formatValue(d.min) + " m is outside (0, inf)");
        }
        if (!(d.max > d.min) || !std::isfinite(d.max)) {
            throw Error(name + " max = " + formatValue(d.max) + " m is outside (min = "
                        + formatValue(d.min) + " m, inf)");
        }
        if (!(d.mean >= d.min && d.mean <= d.max)) {
            throw Error(name + " mean = " + formatValue(d.mean) + " m is outside "
                        + range(d.min, d.max) + " m (min, max)");
        }
        // A normal almost wholly outside its bounds: the rejection would hardly ever accept
        // (with the mean inside, only for bounds far narrower than 1e-6 standard deviations)
        if (!(probabilityInBounds(d) >= 1e-6)) {
            throw Error(name + " [min, max] = " + range(d.min, d.max) + " m holds "
                        + formatValue(probabilityInBounds(d)) + " of the normal, outside [1e-6, 1]");
        }
    } else if (d.type == Type::samples) {
        if (d.samples.empty()) {
            throw Error(name + " samples: the list is empty; allowed: at least one diameter > 0");
        }
        for (std::size_t q = 0; q < d.samples.size(); ++q) {
            if (!(d.samples[q] > 0.0) || !std::isfinite(d.samples[q])) {
                throw Error(name + " samples: value " + std::to_string(q + 1) + " = "
                            + formatValue(d.samples[q]) + " m is outside (0, inf)");
            }
        }
    }
}

double diameterMoment(const ParticleClass& c, int k)
{
    const DiameterDistribution& d = c.distribution;
    switch (d.type) {
    case Type::truncatedNormal: return truncatedNormalMoment(d, k);
    case Type::samples: {
        double sum = 0.0;
        for (double x : d.samples) sum += std::pow(x, k);
        return sum / static_cast<double>(d.samples.size());
    }
    case Type::single: break;
    }
    return std::pow(c.diameter, k);
}

double meanDiameter(const ParticleClass& c)
{
    return c.distribution.type == Type::single ? c.diameter : diameterMoment(c, 1);
}

double sauterDiameter(const ParticleClass& c)
{
    return c.distribution.type == Type::single ? c.diameter
                                                : diameterMoment(c, 3) / diameterMoment(c, 2);
}

double volumeMeanDiameter(const ParticleClass& c)
{
    return c.distribution.type == Type::single ? c.diameter : std::cbrt(diameterMoment(c, 3));
}

double diameterStandardDeviation(const ParticleClass& c)
{
    if (c.distribution.type == Type::single) return 0.0;
    const double m1 = diameterMoment(c, 1);
    return std::sqrt(std::max(0.0, diameterMoment(c, 2) - m1 * m1));
}

double smallestDiameter(const ParticleClass& c)
{
    const DiameterDistribution& d = c.distribution;
    switch (d.type) {
    case Type::truncatedNormal: return d.min;
    case Type::samples: return *std::min_element(d.samples.begin(), d.samples.end());
    case Type::single: break;
    }
    return c.diameter;
}

double largestDiameter(const ParticleClass& c)
{
    const DiameterDistribution& d = c.distribution;
    switch (d.type) {
    case Type::truncatedNormal: return d.max;
    case Type::samples: return *std::max_element(d.samples.begin(), d.samples.end());
    case Type::single: break;
    }
    return c.diameter;
}

double meanParticleMass(const ParticleClass& c)
{
    return c.density * pi * diameterMoment(c, 3) / 6.0;
}

double drawDiameter(const ParticleClass& c, Random& random)
{
    const DiameterDistribution& d = c.distribution;
    if (d.type == Type::samples) return d.samples[random.below(d.samples.size())];
    if (d.type != Type::truncatedNormal) return c.diameter;
    // Rejection: a normal proposal accepts with the bounds' probability Z; where that is
    // below a half, a uniform proposal on [min, max] accepted with exp(-(x - mean)^2/2 s^2)
    // (the mean lies inside, so the density's peak is 1), which accepts at least 0.4 then
    const bool normalProposal = probabilityInBounds(d) >= 0.5;
    for (;;) {
        if (normalProposal) {
            const double x = d.mean + d.standardDeviation * standardNormal(random);
            if (x >= d.min && x <= d.max) return x;
        } else {
            const double x = random.uniform(d.min, d.max);
            const double t = (x - d.mean) / d.standardDeviation;
            if (random.uniform() < std::exp(-0.5 * t * t)) return x;
        }
    }
}

std::uint64_t diameterSeed(std::uint64_t seed, int k)
{
    // splitmix64 of the seed and the class: streams far apart for neighbouring seeds
    std::uint64_t z = seed + 0x9E3779B97F4A7C15ull * (static_cast<std::uint64_t>(k) + 1);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

std::vector<double> drawClassDiameters(const ParticleClass& c, int k, int n, std::uint64_t seed)
{
    std::vector<double> out(static_cast<std::size_t>(std::max(n, 0)), c.diameter);
    if (c.distribution.type == Type::single) return out;
    Random random(diameterSeed(seed, k));
    for (double& d : out) d = drawDiameter(c, random);
    return out;
}

} // namespace dem
