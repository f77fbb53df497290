// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// A bed records every contact setting that shapes it (StateRecord.cpp's settings key): the
// contact law, the tangential damping ratio, the rolling friction and the moduli. A bed
// packed with others is refused naming each; the moduli only count under HertzMindlin.

#include "TestHelpers.hpp"

#include <gtest/gtest.h>

#include <cstdio>
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
