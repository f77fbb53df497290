// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// A bed records every contact setting that shapes it (StateRecord.cpp's settings key): the
// contact law, the tangential damping ratio, the rolling friction, the moduli and the
// coefficients of pairs and walls of their own. A bed packed with others is refused naming
// each; the moduli only count under HertzMindlin.

#include "TestHelpers.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>

using namespace dem;
using namespace dem::test;

namespace {

Settings settings()
{
    Settings s = paperSettings({0.0, 0.03, 0.0, 0.1});
    s.gravity[1] = -9.81;
    return s;
}

/// The paper's particles and walls under HertzMindlin, of Young's modulus 1e7 Pa and
/// Poisson's ratio 0.3 (dt = 1e-5 s is below the law's bound, 7e-5 s).
Settings hertzSettings()
{
    Settings s = settings();
    s.contact.law = ContactLawType::hertzMindlin;
    for (ParticleClass& c : s.classes) {
        c.youngsModulus = 1e7;
        c.poissonRatio = 0.3;
    }
    s.contact.wallYoungsModulus = 1e7;
    s.contact.wallPoissonRatio = 0.3;
    return s;
}

/// The message of loading, for a bed of `smallBedRecipe()`, the bed packed under `made` into a
/// simulation of `used`.
std::string loadedUnder(const Settings& made, const Settings& used, const std::string& name)
{
    const std::string path = tempPath(name);
    Simulation packed(made);
    packed.packBed(smallBedRecipe());
    packed.save(path);
    Simulation sim(used);
    const std::string what = errorOf([&] { sim.loadBed(path, smallBedRecipe()); });
    std::remove(path.c_str());
    return what;
}

} // namespace

// Every contact setting that shapes a bed is in its record: a bed packed with another law,
// rolling friction, tangential damping or Young's modulus is refused naming it.
TEST(ContactRecord, AnotherContactLawRollingFrictionOrModulusIsNamed)
{
    std::string what = loadedUnder(hertzSettings(), settings(), "bedHertz.state");
    EXPECT_NE(what.find("other settings: contact law = HertzMindlin in the file, linear here"),
              std::string::npos)
        << what;

    Settings rolling = settings();
    rolling.contact.rollingFriction = 0.025;
    what = loadedUnder(rolling, settings(), "bedRolling.state");
    EXPECT_NE(what.find("other settings: contact rollingFriction = 0.025 in the file, 0 here"),
              std::string::npos)
        << what;

    Settings damping = settings();
    damping.contact.tangentialDampingRatio = 0.5;
    damping.contact.rollingFrictionWall = 0.01;
    what = loadedUnder(damping, settings(), "bedDamping.state");
    EXPECT_NE(what.find("contact tangentialDampingRatio = 0.5 in the file, 1 here; contact "
                        "rollingFrictionWall = 0.01 in the file, 0 here"),
              std::string::npos)
        << what;

    Settings stiffer = hertzSettings();
    stiffer.classes[0].youngsModulus = 2e7;
    stiffer.contact.wallPoissonRatio = 0.25;
    what = loadedUnder(hertzSettings(), stiffer, "bedModulus.state");
    EXPECT_NE(what.find("contact wallPoissonRatio = 0.3 in the file, 0.25 here; class 'small' "
                        "youngsModulus = 1e+07 in the file, 2e+07 here"),
              std::string::npos)
        << what;

    // The linear law does not read the moduli: a bed of the same linear settings loads
    Settings unread = settings();
    unread.classes[1].youngsModulus = 5e9;
    EXPECT_EQ(loadedUnder(unread, settings(), "bedUnread.state"), "");
}

// HertzMindlin does not read the linear law's kn (its stiffness comes from the moduli; its kt
// must stay the default): a bed of the same Hertz settings but another kn loads, as a
// linear bed does with other moduli; a law change is still named.
TEST(ContactRecord, HertzMindlinBedLoadsWithAnotherLinearStiffness)
{
    Settings softer = hertzSettings();
    softer.contact.kn = 200.0;
    EXPECT_EQ(loadedUnder(hertzSettings(), softer, "bedHertzKn.state"), "");
    Settings linear = settings();
    linear.contact.kn = 200.0;
    const std::string what = loadedUnder(hertzSettings(), linear, "bedHertzToLinear.state");
    EXPECT_NE(what.find("contact law = HertzMindlin in the file, linear here"), std::string::npos) << what;
    EXPECT_NE(what.find("contact kn"), std::string::npos) << what;   // the linear side reads kn
}

namespace {

Settings inEngine(Settings s, int dimension)
{
    s.dimension = dimension;
    s.slabDepth = dimension == 3 ? 0.0075 : 0.0;
    return s;
}

/// `s` with the pair small-large's own restitution e (and rolling friction muR, if > 0).
Settings withPair(Settings s, double e, double muR = 0.0)
{
    PairContactSettings p;
    p.classB = 1;
    p.restitution = e;
    if (muR > 0.0) p.rollingFriction = muR;
    s.contact.pairs = {p};
    return s;
}

} // namespace

// A pair's and a class-wall contact's own coefficients are in the record: a bed or a restart
// made with others is refused naming the pair or the wall and the entry, in both engines; a
// change of a global entry that the pairs with their own do not take is named once, as that
// entry.
TEST(ContactRecord, AnotherPairOrWallCoefficientIsNamed)
{
    for (int dimension : {2, 3}) {
        SCOPED_TRACE(dimension == 2 ? "2D" : "slab");
        const Settings base = inEngine(settings(), dimension);
        std::string what = loadedUnder(withPair(base, 0.9), withPair(base, 0.8), "bedPair.state");
        EXPECT_NE(what.find("other settings: contact pair 'small-large' restitution = 0.9 in the "
                            "file, 0.8 here"),
                  std::string::npos)
            << what;
        what = loadedUnder(withPair(base, 0.9, 0.025), base, "bedPairGone.state");
        EXPECT_NE(what.find("other settings: contact pair 'small-large' restitution = 0.9 in the "
                            "file, 0.97 here; contact pair 'small-large' rollingFriction = 0.025 "
                            "in the file, 0 here"),
                  std::string::npos)
            << what;

        Settings wall = base;
        WallContactSettings w;
        w.classIndex = 1;
        w.frictionWall = 0.3;
        wall.contact.walls = {w};
        what = loadedUnder(base, wall, "bedWall.state");
        EXPECT_NE(what.find("other settings: contact wall 'large' frictionWall = 0.1 in the file, "
                            "0.3 here"),
                  std::string::npos)
            << what;

        Settings otherGlobal = withPair(base, 0.9);
        otherGlobal.contact.restitution = 0.95;
        what = loadedUnder(withPair(base, 0.9), otherGlobal, "bedGlobal.state");
        EXPECT_NE(what.find("other settings: contact restitution = 0.97 in the file, 0.95 here"),
                  std::string::npos)
            << what;
        EXPECT_EQ(what.find("contact pair"), std::string::npos) << what;

        // A restart is refused alike
        const std::string path = tempPath("restartPair.state");
        Simulation run(withPair(base, 0.9));
        run.packBed(smallBedRecipe());
        run.advance(0.0005);
        run.save(path);
        Simulation other(withPair(base, 0.85));
        what = errorOf([&] { other.load(path); });
        EXPECT_NE(what.find("state file '" + path + "' was written with other settings: contact "
                            "pair 'small-large' restitution = 0.9 in the file, 0.85 here"),
                  std::string::npos)
            << what;
        Simulation same(withPair(base, 0.9));
        EXPECT_EQ(errorOf([&] { same.load(path); }), "");
        std::remove(path.c_str());
    }
}

// Pairs and walls given the global values are the global coefficients: the file is the bytes
// of one written without them, and the two load each other's.
TEST(ContactRecord, OwnCoefficientsEqualToTheGlobalOnesWriteTheSameFile)
{
    for (int dimension : {2, 3}) {
        SCOPED_TRACE(dimension == 2 ? "2D" : "slab");
        const Settings base = inEngine(settings(), dimension);
        Settings same = withPair(base, base.contact.restitution);
        WallContactSettings w;
        w.frictionWall = base.contact.frictionWall;
        same.contact.walls = {w};
        const std::string a = tempPath("bedWithout.state"), b = tempPath("bedWith.state");
        Simulation without(base), with(same);
        without.packBed(smallBedRecipe());
        with.packBed(smallBedRecipe());
        without.save(a);
        with.save(b);
        EXPECT_TRUE(readBytes(a) == readBytes(b));
        EXPECT_EQ(loadedUnder(base, same, "bedSame.state"), "");
        EXPECT_EQ(loadedUnder(same, base, "bedSame.state"), "");
        std::remove(a.c_str());
        std::remove(b.c_str());
    }
}
