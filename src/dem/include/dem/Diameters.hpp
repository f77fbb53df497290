// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The diameters of one size class: one diameter for every particle, or a distribution each
// particle's diameter is drawn from when a bed is packed (docs/theory/dem.md, "Diameter
// distributions"), with the statistics the rest of the code takes of it. Plain C++17 (the
// facade includes it).

#include <cstdint>
#include <string>
#include <vector>

namespace dem {

/// How the particles of a class get their diameters.
enum class DiameterDistributionType {
    single,            ///< every particle has ParticleClass::diameter
    truncatedNormal,   ///< a normal of `mean` and `standardDeviation` cut to [min, max]
    samples            ///< one of `samples`, each equally likely
};

/// A class's distribution of diameters, m.
struct DiameterDistribution {
    DiameterDistributionType type = DiameterDistributionType::single;
    double mean = 0.0;                ///< truncatedNormal: the untruncated normal's mean, m
    double standardDeviation = 0.0;   ///< truncatedNormal: the untruncated normal's, m, > 0
    double min = 0.0;                 ///< truncatedNormal: the smallest diameter drawn, m
    double max = 0.0;                 ///< truncatedNormal: the largest diameter drawn, m
    std::vector<double> samples;      ///< samples: the diameters drawn from, m, > 0
};

/// "single", "normal" or "samples" (the dictionary's words).
std::string distributionName(DiameterDistributionType type);

struct ParticleClass;
class Random;

/// Throws dem::Error naming `what` (e.g. "classes[0] ('glass')"), the entry and its allowed
/// range if the distribution is not one that can be drawn: standardDeviation > 0, min in
/// (0, max), mean in [min, max], the bounds holding at least 1e-6 of the normal's
/// probability; samples not empty and each > 0.
void validateDistribution(const DiameterDistribution& d, const std::string& what);

/// E[d^k] of the class's diameters, k = 1, 2 or 3 (m^k): d^k for one diameter; the
/// truncated normal's exact moment; the mean of the samples' d^k.
double diameterMoment(const ParticleClass& c, int k);
/// The number mean E[d] (m): the class's diameter, or its distribution's mean. The contact
/// laws' coefficients of a class are those of this diameter.
double meanDiameter(const ParticleClass& c);
/// The Sauter mean E[d^3]/E[d^2] (m): the class in the fluidization correlations.
double sauterDiameter(const ParticleClass& c);
/// The volume mean E[d^3]^(1/3) (m): a particle of the class's mean volume and mass.
double volumeMeanDiameter(const ParticleClass& c);
/// The standard deviation of the class's diameters (m): 0 for one diameter.
double diameterStandardDeviation(const ParticleClass& c);
/// The smallest and the largest diameter a particle of the class can have (m).
double smallestDiameter(const ParticleClass& c);
double largestDiameter(const ParticleClass& c);
/// The mean mass density pi/6 E[d^3] of a particle of the class (kg).
double meanParticleMass(const ParticleClass& c);

/// Draws one diameter of the class (m): the class's diameter without drawing for a single
/// one; else from `random` (truncatedNormal: by rejection, from a Box-Muller normal or, for
/// bounds narrower than the normal, a uniform proposal; samples: one at random).
double drawDiameter(const ParticleClass& c, Random& random);

/// The seed of class k's diameters drawn for a bed of seed `seed`: a stream of its own per
/// class (splitmix64 of the two), apart from the positions' stream.
std::uint64_t diameterSeed(std::uint64_t seed, int k);

/// n diameters of class k for a bed of seed `seed`, in the order drawn; n times the class's
/// diameter for a single one.
std::vector<double> drawClassDiameters(const ParticleClass& c, int k, int n, std::uint64_t seed);

} // namespace dem
