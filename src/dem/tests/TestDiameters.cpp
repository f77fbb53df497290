// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// A class's diameter distribution: the truncated normal's draws against its textbook mean
// and variance (Johnson, Kotz and Balakrishnan 1994, "Continuous univariate distributions"
// vol. 1, section 10.1: mean mu + s (phi(a) - phi(b))/Z, variance s^2 [1 + (a phi(a) -
// b phi(b))/Z - ((phi(a) - phi(b))/Z)^2], a and b the bounds in standard deviations, Z the
// probability between them; the numbers below evaluated outside the code), the samples'
// draws from the list alone, reproducible for a seed; the packing's particles carry their
// drawn diameters and masses, the step bound is the smallest particle's, and a bed packed
// with another distribution is refused naming it.

#include "TestHelpers.hpp"
#include "dem/Random.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

using namespace dem;
using namespace dem::test;

namespace {

/// A class of glass beads whose diameters follow a normal of mean mu and standard deviation
/// s truncated to [a, b], m.
ParticleClass normalClass(double mu, double s, double a, double b)
{
    ParticleClass c{"glass", 0.0, 2522.0};
    c.distribution.type = DiameterDistributionType::truncatedNormal;
    c.distribution.mean = mu;
    c.distribution.standardDeviation = s;
    c.distribution.min = a;
    c.distribution.max = b;
    return c;
}

struct Moments {
    double mean, variance, fourth;   // the sample's mean, variance, 4th central moment
};

Moments momentsOf(const std::vector<double>& d)
{
    double mean = 0.0;
    for (double x : d) mean += x;
    mean /= static_cast<double>(d.size());
    double m2 = 0.0, m4 = 0.0;
    for (double x : d) {
        const double e = (x - mean) * (x - mean);
        m2 += e;
        m4 += e * e;
    }
    return {mean, m2 / static_cast<double>(d.size() - 1), m4 / static_cast<double>(d.size())};
}

/// 20000 draws' mean within 3 standard errors of `mean` and variance within 3 of its own
/// standard error sqrt((mu4 - s^4)/n) of `variance`, all within [a, b].
void expectDraws(const ParticleClass& c, double mean, double variance)
{
    constexpr int n = 20000;
    const std::vector<double> d = drawClassDiameters(c, 0, n, 7);
    ASSERT_EQ(d.size(), static_cast<std::size_t>(n));
    const auto [lo, hi] = std::minmax_element(d.begin(), d.end());
    EXPECT_GE(*lo, c.distribution.min);
    EXPECT_LE(*hi, c.distribution.max);
    const Moments m = momentsOf(d);
    EXPECT_NEAR(m.mean, mean, 3.0 * std::sqrt(variance / n));
    EXPECT_NEAR(m.variance, variance, 3.0 * std::sqrt((m.fourth - variance * variance) / n));
}

} // namespace

TEST(Diameters, TruncatedNormalMomentsAreTheTextbooks)
{
    // Bounds -0.67 and +2.33 standard deviations from the mean: mean 3.219247353869e-3 m,
    // variance 4.233322009339e-8 m^2; E[d^2] 1.040588674548e-5 m^2 and E[d^3]
    // 3.377628124993e-8 m^3 by quadrature of the density (200001 points)
    const ParticleClass c = normalClass(3.1e-3, 3e-4, 2.9e-3, 3.8e-3);
    EXPECT_NEAR(meanDiameter(c), 3.219247353869e-3, 1e-14);
    EXPECT_NEAR(diameterStandardDeviation(c), std::sqrt(4.233322009339e-8), 1e-12);
    EXPECT_NEAR(diameterMoment(c, 2) / 1.040588674548e-5, 1.0, 1e-9);
    EXPECT_NEAR(diameterMoment(c, 3) / 3.377628124993e-8, 1.0, 1e-9);
    EXPECT_NEAR(sauterDiameter(c), 3.377628124993e-8 / 1.040588674548e-5, 1e-12);
    EXPECT_NEAR(volumeMeanDiameter(c), std::cbrt(3.377628124993e-8), 1e-12);
    EXPECT_EQ(smallestDiameter(c), 2.9e-3);
    EXPECT_EQ(largestDiameter(c), 3.8e-3);
    EXPECT_NEAR(meanParticleMass(c), 2522.0 * pi / 6.0 * 3.377628124993e-8, 1e-15);
}

TEST(Diameters, TruncatedNormalDrawsHaveItsMeanAndVariance)
{
    // Asymmetric bounds, the normal proposal (Z = 0.738)
    expectDraws(normalClass(3.1e-3, 3e-4, 2.9e-3, 3.8e-3), 3.219247353869e-3, 4.233322009339e-8);
    // Bounds narrower than the normal, the uniform proposal (Z = 0.119): mean
    // 3.049626125187e-3 m, variance 7.477440489700e-9 m^2
    expectDraws(normalClass(3.0e-3, 1e-3, 2.9e-3, 3.2e-3), 3.049626125187e-3, 7.477440489700e-9);
    // NETL's glass beads (LaMarche et al. 2022: 3101 um, standard deviation 187 um), cut at
    // 2.6 and 3.6 mm: mean 3.100939755128e-3 m, variance 3.286221012138e-8 m^2
    expectDraws(normalClass(3.101e-3, 1.87e-4, 2.6e-3, 3.6e-3), 3.100939755128e-3,
                3.286221012138e-8);
}

TEST(Diameters, DrawsAreReproducibleForASeedAndDifferForAnother)
{
    const ParticleClass c = normalClass(3.101e-3, 1.87e-4, 2.6e-3, 3.6e-3);
    EXPECT_EQ(drawClassDiameters(c, 0, 500, 3), drawClassDiameters(c, 0, 500, 3));
    EXPECT_NE(drawClassDiameters(c, 0, 500, 3), drawClassDiameters(c, 0, 500, 4));
    EXPECT_NE(drawClassDiameters(c, 0, 500, 3), drawClassDiameters(c, 1, 500, 3));   // its own stream
    // The first draws do not depend on how many follow
    const std::vector<double> many = drawClassDiameters(c, 0, 500, 3);
    const std::vector<double> few = drawClassDiameters(c, 0, 10, 3);
    EXPECT_TRUE(std::equal(few.begin(), few.end(), many.begin()));
    // One diameter: no drawing
    const ParticleClass single{"small", 1.5e-3, 2525.0};
    EXPECT_EQ(drawClassDiameters(single, 0, 3, 3), std::vector<double>(3, 1.5e-3));
}

TEST(Diameters, SamplesAreDrawnFromTheListAloneEachAlike)
{
    ParticleClass c{"glass", 0.0, 2522.0};
    c.distribution.type = DiameterDistributionType::samples;
    c.distribution.samples = {3.122905969e-3, 3.401633067e-3, 3.231156477e-3, 3.022561658e-3,
                              2.991820915e-3};
    constexpr int n = 20000;
    const std::vector<double> d = drawClassDiameters(c, 0, n, 11);
    std::map<double, int> seen;
    for (double x : d) ++seen[x];
    ASSERT_EQ(seen.size(), c.distribution.samples.size());
    for (double x : c.distribution.samples) {
        // Each a binomial of p = 1/5: within 4 standard deviations of n/5
        ASSERT_EQ(seen.count(x), 1u);
        EXPECT_NEAR(seen[x], n / 5.0, 4.0 * std::sqrt(n * 0.2 * 0.8));
    }
    double mean = 0.0;
    for (double x : c.distribution.samples) mean += x;
    EXPECT_NEAR(meanDiameter(c), mean / 5.0, 1e-15);
    EXPECT_EQ(smallestDiameter(c), 2.991820915e-3);
    EXPECT_EQ(largestDiameter(c), 3.401633067e-3);
}

TEST(Diameters, BadDistributionsAreNamedWithTheirRange)
{
    auto message = [](const ParticleClass& c) {
        return errorOf([&] { validateDistribution(c.distribution, "classes[0] ('glass')"); });
    };
    const std::string sd = message(normalClass(3.1e-3, -1e-4, 2.6e-3, 3.6e-3));
    EXPECT_NE(sd.find("classes[0] ('glass') diameter standardDeviation = -0.0001 m is outside (0, inf)"),
              std::string::npos)
        << sd;
    const std::string bounds = message(normalClass(3.1e-3, 1e-4, 3.6e-3, 3.6e-3));
    EXPECT_NE(bounds.find("diameter max = 0.0036 m is outside (min = 0.0036 m, inf)"),
              std::string::npos)
        << bounds;
    const std::string mean = message(normalClass(4e-3, 1e-4, 2.6e-3, 3.6e-3));
    EXPECT_NE(mean.find("diameter mean = 0.004 m is outside [0.0026, 0.0036] m"), std::string::npos)
        << mean;
    ParticleClass empty{"glass", 0.0, 2522.0};
    empty.distribution.type = DiameterDistributionType::samples;
    const std::string list = message(empty);
    EXPECT_NE(list.find("diameter samples: the list is empty; allowed: at least one diameter > 0"),
              std::string::npos)
        << list;
    empty.distribution.samples = {3e-3, 0.0};
    EXPECT_NE(message(empty).find("samples: value 2 = 0 m is outside (0, inf)"), std::string::npos);

    // The engine checks them too
    Settings s = paperSettings({0.0, 0.03, 0.0, 0.03});
    s.classes[1] = normalClass(2.5e-3, 0.0, 2.0e-3, 3.0e-3);
    const std::string engine = errorOf([&] { Simulation sim(s); });
    EXPECT_NE(engine.find("classes[1] ('glass') diameter standardDeviation = 0 m is outside (0, inf)"),
              std::string::npos)
        << engine;
}

namespace {

/// Glass beads of NETL's distribution (large) beside the paper's small class.
Settings distributedSettings(int dimension)
{
    Settings s = paperSettings({0.0, 0.03, 0.0, 0.06});
    s.classes[1] = normalClass(3.101e-3, 1.87e-4, 2.6e-3, 3.6e-3);
    s.gravity[1] = -9.81;
    s.dimension = dimension;
    s.slabDepth = dimension == 3 ? 0.008 : 0.0;
    return s;
}

BedRecipe distributedRecipe()
{
    BedRecipe r;
    r.countPerClass = {60, 80};
    r.region = {0.0, 0.03, 0.0, 0.06};
    r.seed = 5;
    r.settleTime = 0.0;   // the packing as it was placed
    return r;
}

} // namespace

TEST(Diameters, APackedBedCarriesItsDrawnDiametersAndMasses)
{
    for (int dimension : {2, 3}) {
        SCOPED_TRACE("dimension " + std::to_string(dimension));
        const Settings s = distributedSettings(dimension);
        Simulation sim(s);
        const BedRecipe r = distributedRecipe();
        sim.packBed(r);
        ASSERT_EQ(sim.size(), 140u);
        std::vector<double> glass;
        for (std::size_t i = 0; i < sim.size(); ++i) {
            const double d = sim.diameter()[i];
            const ParticleClass& c = s.classes[sim.classIndex()[i]];
            EXPECT_NEAR(sim.mass()[i], c.density * pi * d * d * d / 6.0, 1e-12 * sim.mass()[i]);
            if (sim.classIndex()[i] == 1) glass.push_back(d);
            else {
                EXPECT_EQ(d, dSmall);
            }
        }
        // The class's draws for the bed's seed, whatever order the packing numbered them in
        std::vector<double> drawn = drawClassDiameters(s.classes[1], 1, 80, r.seed);
        std::sort(drawn.begin(), drawn.end());
        std::sort(glass.begin(), glass.end());
        EXPECT_EQ(glass, drawn);
        EXPECT_GT(glass.back() - glass.front(), 2e-4);   // not one diameter
        // No two overlap
        for (std::size_t i = 0; i < sim.size(); ++i) {
            for (std::size_t j = i + 1; j < sim.size(); ++j) {
                const double dx = sim.x()[i] - sim.x()[j], dy = sim.y()[i] - sim.y()[j];
                const double dz = dimension == 3 ? sim.z()[i] - sim.z()[j] : 0.0;
                const double reach = 0.5 * (sim.diameter()[i] + sim.diameter()[j]);
                EXPECT_GE(dx * dx + dy * dy + dz * dz, reach * reach * (1.0 - 1e-12));
            }
        }
        // Reproducible
        Simulation again(s);
        again.packBed(r);
        EXPECT_TRUE(std::equal(sim.diameter(), sim.diameter() + sim.size(), again.diameter()));
        EXPECT_TRUE(std::equal(sim.x(), sim.x() + sim.size(), again.x()));
    }
}

TEST(Diameters, TheStepBoundIsTheSmallestParticles)
{
    // Eq. 7, (2 pi/5) sqrt(m_min/kn), with the lightest glass bead (2.6 mm) once the small
    // class is gone: the bound the bed's own lightest particle sets
    Settings s = distributedSettings(2);
    s.classes.erase(s.classes.begin());
    const double mMin = 2522.0 * pi * 2.6e-3 * 2.6e-3 * 2.6e-3 / 6.0;
    EXPECT_NEAR(timeStepBound(s), 2.0 * pi / 5.0 * std::sqrt(mMin / s.contact.kn), 1e-15);
    // A step just above it is refused, naming the smallest diameter
    s.dt = 1.001 * timeStepBound(s);
    const std::string e = errorOf([&] { Simulation sim(s); });
    EXPECT_NE(e.find("classes[0] ('glass') of diameter 0.0026 m"), std::string::npos) << e;
    // The bed's speed scale from the largest, sqrt(|g| d_max)
    EXPECT_NEAR(bedSpeedScale(s), std::sqrt(9.81 * 3.6e-3), 1e-15);
}

TEST(Diameters, ABedOfAnotherDistributionIsRefusedNamingIt)
{
    for (int dimension : {2, 3}) {
        SCOPED_TRACE("dimension " + std::to_string(dimension));
        const std::string path = tempPath("distributed" + std::to_string(dimension) + ".state");
        const Settings s = distributedSettings(dimension);
        {
            Simulation sim(s);
            sim.packBed(distributedRecipe());
            sim.save(path);
        }
        Simulation same(s);
        EXPECT_TRUE(same.loadBed(path, distributedRecipe()));

        Settings wider = s;
        wider.classes[1].distribution.standardDeviation = 2.5e-4;
        Simulation refused(wider);
        const std::string e = errorOf([&] { refused.loadBed(path, distributedRecipe()); });
        EXPECT_NE(e.find("class 'glass' diameter standardDeviation = 0.000187 in the file, "
                         "0.00025 here"),
                  std::string::npos)
            << e;

        Settings single = s;
        single.classes[1].distribution = DiameterDistribution{};
        single.classes[1].diameter = 3.1e-3;
        Simulation one(single);
        const std::string o = errorOf([&] { one.loadBed(path, distributedRecipe()); });
        EXPECT_NE(o.find("class 'glass' diameter distribution = normal in the file, none (one "
                         "diameter) here"),
                  std::string::npos)
            << o;

        Settings listed = s;
        listed.classes[1].distribution.type = DiameterDistributionType::samples;
        listed.classes[1].distribution.samples = {3.0e-3, 3.2e-3};
        Simulation samples(listed);
        const std::string l = errorOf([&] { samples.loadBed(path, distributedRecipe()); });
        EXPECT_NE(l.find("class 'glass' diameter distribution = normal in the file, samples here"),
                  std::string::npos)
            << l;
        std::remove(path.c_str());
    }
}
