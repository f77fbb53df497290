// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The facade dem::Simulation in the slab mode: it drives the slab engine bit for
// bit, restarts and runs on 2 threads bit for bit, exposes the 3D coupling arrays, and keeps
// the 2D and 3D members apart.

#include "TestHelpers.hpp"
#include "dem/SlabSystem.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <cmath>
#include <memory>
#include <string>
#include <unistd.h>

using namespace dem;
using namespace dem::test;

namespace {

Settings slabFacadeSettings(int threads)
{
    Settings s = paperSettings({0.0, 0.02, 0.0, 0.04});
    s.gravity[1] = -9.81;
    s.dimension = 3;
    s.slabDepth = 0.0075;   // 3 large diameters
    s.nThreads = threads;
    return s;
}

const std::vector<int> counts = {120, 40};
const Box region = {0.0, 0.02, 0.0, 0.015};

/// Fluid inputs of every kind, the z-components included, varying from particle to particle.
void setFluid(double* drag, double* gx, double* gy, double* gz, double* fx, double* fy,
              double* fz, std::size_t n)
{
    for (std::size_t i = 0; i < n; ++i) {
        const double s = static_cast<double>(i % 7) / 7.0;
        drag[i] = 1e-4 * (1.0 + s);
        gx[i] = 0.05 * s;
        gy[i] = 0.3 + 0.1 * s;
        gz[i] = -0.02 + 0.04 * s;
        fx[i] = 1e-6 * s;
        fy[i] = 2e-6;
        fz[i] = -1e-6 * s;
    }
}

void setFluid(Simulation& sim)
{
    setFluid(sim.dragCoefficient(), sim.gasVelocityX(), sim.gasVelocityY(), sim.gasVelocityZ(),
             sim.extraForceX(), sim.extraForceY(), sim.extraForceZ(), sim.size());
}

void setFluid(SlabSystem& sim)
{
    SlabParticles& p = sim.particles();
    setFluid(p.dragCoefficient.data(), p.gasVx.data(), p.gasVy.data(), p.gasVz.data(),
             p.extraFx.data(), p.extraFy.data(), p.extraFz.data(), p.size());
}

/// Packed, settled briefly, then `cfdSteps` CFD steps of 10 DEM steps with the fluid on.
std::unique_ptr<Simulation> facadeRun(int threads, int cfdSteps)
{
    auto sim = std::make_unique<Simulation>(slabFacadeSettings(threads));
    sim->packRandom(counts, region, 5);
    sim->settle(0.15, 0.0);   // landed on the floor
    for (int k = 0; k < cfdSteps; ++k) {
        setFluid(*sim);
        sim->advance(1e-4);
    }
    return sim;
}

/// The arrays the facade exposes in 3D, by name.
std::vector<std::pair<const char*, const double*>> arrays(const Simulation& s)
{
    return {{"x", s.x()}, {"y", s.y()}, {"z", s.z()}, {"vx", s.vx()}, {"vy", s.vy()},
            {"vz", s.vz()}, {"omegaX", s.omegaX()}, {"omegaY", s.omegaY()},
            {"omegaZ", s.omegaZ()}, {"meanVelocityX", s.meanVelocityX()},
            {"meanVelocityY", s.meanVelocityY()}, {"meanVelocityZ", s.meanVelocityZ()},
            {"meanFluidForceX", s.meanFluidForceX()}, {"meanFluidForceY", s.meanFluidForceY()},
            {"meanFluidForceZ", s.meanFluidForceZ()}};
}

void expectSameBits(const Simulation& a, const Simulation& b, const char* what)
{
    ASSERT_EQ(a.size(), b.size()) << what;
    ASSERT_EQ(a.stepCount(), b.stepCount()) << what;
    const auto aa = arrays(a);
    const auto bb = arrays(b);
    for (std::size_t k = 0; k < aa.size(); ++k) {
        EXPECT_EQ(std::memcmp(aa[k].second, bb[k].second, a.size() * sizeof(double)), 0)
            << what << ": " << aa[k].first << " differs";
    }
}

std::string tempPath(const char* name)
{
    return (std::filesystem::temp_directory_path()
            / (std::string(name) + "-" + std::to_string(::getpid()))).string();
}

} // namespace

TEST(SlabFacade, SameBitsAsTheSlabEngineDrivenDirectly)
{
    const auto facade = facadeRun(1, 20);
    SlabSystem direct(slabFacadeSettings(1));
    direct.packRandom(counts, region, 5);
    direct.settle(0.15, 0.0);
    for (int k = 0; k < 20; ++k) {
        setFluid(direct);
        direct.advance(1e-4);
    }
    const SlabParticles& p = direct.particles();
    ASSERT_EQ(facade->size(), p.size());
    ASSERT_EQ(facade->stepCount(), direct.stepCount());
    const std::pair<const char*, const std::vector<double>*> expected[] = {
        {"x", &p.x}, {"y", &p.y}, {"z", &p.z}, {"vx", &p.vx}, {"vy", &p.vy}, {"vz", &p.vz},
        {"omegaX", &p.wx}, {"omegaY", &p.wy}, {"omegaZ", &p.wz},
        {"meanVelocityX", &p.meanVx}, {"meanVelocityY", &p.meanVy}, {"meanVelocityZ", &p.meanVz},
        {"meanFluidForceX", &p.meanFluidX}, {"meanFluidForceY", &p.meanFluidY},
        {"meanFluidForceZ", &p.meanFluidZ}};
    const auto got = arrays(*facade);
    for (std::size_t k = 0; k < got.size(); ++k) {
        ASSERT_STREQ(got[k].first, expected[k].first);
        EXPECT_EQ(std::memcmp(got[k].second, expected[k].second->data(), p.size() * sizeof(double)), 0)
            << got[k].first << " differs";
    }
    EXPECT_EQ(facade->kineticEnergy(), direct.kineticEnergy());
    EXPECT_EQ(facade->contactCount(), direct.contactCount());
    EXPECT_EQ(facade->memoryBytes(), direct.memoryBytes());
    // The sub-step mean force is exactly drag (gas - mean velocity) + extra force (Facade.hpp),
    // here for the z-components the slab adds.
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double want = p.dragCoefficient[i] * (p.gasVz[i] - p.meanVz[i]) + p.extraFz[i];
        EXPECT_NEAR(facade->meanFluidForceZ()[i], want, 1e-12 * (std::abs(want) + 1e-9)) << i;
    }
}

TEST(SlabFacade, OneAndTwoThreadsGiveTheSameBits)
{
    const auto one = facadeRun(1, 20);
    const auto two = facadeRun(2, 20);
    std::printf("  %zu contacts\n", one->contactCount());
    EXPECT_GT(one->contactCount(), 50u);   // the pair loops are exercised
    expectSameBits(*one, *two, "1 vs 2 threads");
}

TEST(SlabFacade, SaveAndLoadContinueBitForBit)
{
    auto sim = facadeRun(2, 5);
    const std::string path = tempPath("demSlabFacadeState");
    sim->save(path);
    Simulation copy(sim->settings());
    copy.load(path);
    expectSameBits(*sim, copy, "after load");
    for (int k = 0; k < 100; ++k) {   // 1000 DEM steps with the fluid on
        setFluid(*sim);
        setFluid(copy);
        sim->advance(1e-4);
        copy.advance(1e-4);
    }
    expectSameBits(*sim, copy, "100 CFD steps after load");
    std::filesystem::remove(path);
}

// A slab state loaded with other settings names each setting that differs, as the disc
// engine's does; a box a last digit apart (another mesh of the same bed) is the same box.
TEST(SlabFacade, StateWithOtherSettingsNamesThem)
{
    auto sim = facadeRun(1, 2);
    const std::string path = tempPath("demSlabOtherSettings");
    sim->save(path);

    Settings other = sim->settings();
    other.contact.frictionParticle = 0.25;
    other.slabDepth = 0.008;
    Simulation refused(other);
    std::string what;
    try {
        refused.load(path);
    } catch (const Error& e) {
        what = e.what();
    }
    EXPECT_NE(what.find("was written with other settings"), std::string::npos) << what;
    EXPECT_NE(what.find("contact frictionParticle = 0.15 in the file, 0.25 here"),
              std::string::npos) << what;
    EXPECT_NE(what.find("slabDepth = 0.0075 m in the file, 0.008 m here"), std::string::npos)
        << what;

    // The contact law and rolling friction, as the disc engine's (TestBedRecord)
    Settings hertz = sim->settings();
    hertz.contact.law = ContactLawType::hertzMindlin;
    for (ParticleClass& c : hertz.classes) {
        c.youngsModulus = 1e7;
        c.poissonRatio = 0.3;
    }
    hertz.contact.wallYoungsModulus = 1e7;
    hertz.contact.wallPoissonRatio = 0.3;
    hertz.contact.rollingFriction = 0.025;
    Simulation otherLaw(hertz);
    what.clear();
    try {
        otherLaw.load(path);
    } catch (const Error& e) {
        what = e.what();
    }
    EXPECT_NE(what.find("contact law = linear in the file, HertzMindlin here; contact "
                        "rollingFriction = 0 in the file, 0.025 here; contact wallYoungsModulus "
                        "= 0 in the file, 1e+07 here"),
              std::string::npos)
        << what;

    // The box and the depth a last digit apart (a mesh numbered otherwise): the same bed
    Settings nearly = sim->settings();
    nearly.box.xMax = std::nextafter(nearly.box.xMax, 1.0);
    nearly.slabDepth = std::nextafter(std::nextafter(nearly.slabDepth, 1.0), 1.0);
    Simulation loaded(nearly);
    EXPECT_NO_THROW(loaded.load(path));
    EXPECT_EQ(loaded.size(), sim->size());
    std::filesystem::remove(path);
}

TEST(SlabFacade, BedRecordAndCountsPerClass)
{
    // packBed keeps its recipe and save() records it: loadBed checks
    // every entry of it (returns true), refuses a bed made otherwise naming the entry, and
    // leaves the slab as it was; addParticle makes the particles no longer the recipe's.
    Simulation sim(slabFacadeSettings(1));
    const BedRecipe recipe{counts, region, 5, 0.01, 0.0};
    sim.packBed(recipe);
    ASSERT_NE(sim.recipe(), nullptr);
    EXPECT_EQ(sim.recipe()->countPerClass, counts);
    const std::string path = tempPath("demSlabFacadeBed");
    sim.save(path);

    Simulation other(slabFacadeSettings(1));
    other.addParticle(0, {0.01, 0.01, 0.003});
    EXPECT_EQ(other.recipe(), nullptr);
    BedRecipe otherMix = recipe;
    otherMix.countPerClass = {100, 40};
    BedRecipe otherSeed = recipe;
    otherSeed.seed = 6;
    for (const auto& [wrong, entry] : {std::pair{otherMix, "small"}, std::pair{otherSeed, "seed"}}) {
        try {
            other.loadBed(path, wrong);
            ADD_FAILURE() << "a bed made otherwise was accepted (" << entry << ")";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(entry), std::string::npos) << e.what();
        }
    }
    EXPECT_EQ(other.size(), 1u);
    EXPECT_TRUE(other.loadBed(path, recipe));
    ASSERT_NE(other.recipe(), nullptr);
    EXPECT_EQ(other.recipe()->seed, 5u);
    expectSameBits(sim, other, "loadBed");
    other.addParticle(0, {0.01, 0.035, 0.003});   // above the settled bed
    EXPECT_EQ(other.recipe(), nullptr);
    std::filesystem::remove(path);
}

TEST(SlabFacade, MembersOfOneModeRefusedInTheOther)
{
    Settings s2 = slabFacadeSettings(1);
    s2.dimension = 2;
    Simulation discs(s2);
    discs.addParticle(0, 0.01, 0.01);
    EXPECT_THROW(discs.z(), Error);
    EXPECT_THROW(discs.gasVelocityZ(), Error);
    EXPECT_THROW(discs.meanFluidForceZ(), Error);
    EXPECT_THROW(discs.addParticle(0, Vector3{0.01, 0.02, 0.003}), Error);

    Simulation slab(slabFacadeSettings(1));
    EXPECT_THROW(slab.addParticle(0, 0.01, 0.01), Error);
    slab.addParticle(1, {0.01, 0.01, 0.003}, {0.0, 0.1, -0.2}, {1.0, 2.0, 3.0});
    EXPECT_EQ(slab.z()[0], 0.003);
    EXPECT_EQ(slab.vz()[0], -0.2);
    EXPECT_EQ(slab.omegaX()[0], 1.0);
    EXPECT_EQ(slab.omegaY()[0], 2.0);
    EXPECT_EQ(slab.omega()[0], 3.0);
    EXPECT_NEAR(slab.mass()[0], sphereMass(dLarge), 1e-12 * sphereMass(dLarge));
    // Eq. 7 written here: 2 pi / 5 sqrt(m_small / kn).
    EXPECT_NEAR(slab.timeStepBound(), 2.0 * pi / 5.0 * std::sqrt(sphereMass(dSmall) / 800.0),
                1e-12);
    EXPECT_GT(slab.memoryBytes(), 0u);
    // A sphere poking through the front wall is refused.
    EXPECT_THROW(slab.addParticle(0, {0.015, 0.01, 0.0005}), Error);
}
