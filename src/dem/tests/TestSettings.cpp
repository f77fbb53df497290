// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Every bad setting stops with a dem::Error naming the setting, its value and
// the allowed range.

#include "TestHelpers.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

using namespace dem;
using namespace dem::test;

namespace {

const Box box{0.0, 0.1, 0.0, 0.1};

/// Runs f, expecting a dem::Error whose message contains every one of `parts`.
void expectError(const std::function<void()>& f, std::initializer_list<const char*> parts)
{
    try {
        f();
        ADD_FAILURE() << "no dem::Error";
    } catch (const Error& e) {
        for (const char* part : parts) {
            EXPECT_NE(std::string(e.what()).find(part), std::string::npos)
                << "'" << part << "' not in: " << e.what();
        }
    }
}

void expectBadSetting(const std::function<void(Settings&)>& change,
                      std::initializer_list<const char*> parts)
{
    Settings s = paperSettings(box);
    change(s);
    expectError([&] { Simulation sim(s); }, parts);
}

} // namespace

TEST(Settings, PaperSettingsAreValid)
{
    Simulation sim(paperSettings(box));
    // Eq. 7 for the 1.5 mm particle: (2 pi/5) sqrt(2525 pi 1.5e-3^3/6 / 800) = 9.385e-5 s.
    EXPECT_NEAR(sim.timeStepBound(), 9.385e-5, 0.001e-5);
}

TEST(Settings, BadDiameterDensity)
{
    expectBadSetting([](Settings& s) { s.classes[0].diameter = -1e-3; },
                     {"classes[0]", "small", "diameter", "-0.001", "(0, inf)"});
    expectBadSetting([](Settings& s) { s.classes[1].diameter = 0.0; }, {"large", "diameter", "(0, inf)"});
    expectBadSetting([](Settings& s) { s.classes[1].density = 0.0; }, {"large", "density", "(0, inf)"});
    expectBadSetting([](Settings& s) { s.classes[0].density = -5.0; }, {"density", "-5", "(0, inf)"});
}

TEST(Settings, BadRestitutionFrictionStiffness)
{
    expectBadSetting([](Settings& s) { s.contact.restitution = 1.3; }, {"restitution = 1.3 is outside (0, 1]"});
    expectBadSetting([](Settings& s) { s.contact.restitution = 0.0; }, {"restitution = 0", "(0, 1]"});
    expectBadSetting([](Settings& s) { s.contact.restitutionWall = -0.5; }, {"restitutionWall = -0.5", "(0, 1]"});
    expectBadSetting([](Settings& s) { s.contact.frictionParticle = -0.1; }, {"frictionParticle = -0.1", "[0, inf)"});
    expectBadSetting([](Settings& s) { s.contact.frictionWall = -1.0; }, {"frictionWall = -1", "[0, inf)"});
    expectBadSetting([](Settings& s) { s.contact.kn = 0.0; }, {"kn = 0", "(0, inf)"});
    expectBadSetting([](Settings& s) { s.contact.kt = 0.0; }, {"kt = 0", "(0, inf)"});
}

TEST(Settings, EmptyClassesBoxThreads)
{
    expectBadSetting([](Settings& s) { s.classes.clear(); }, {"classes", "empty"});
    expectBadSetting([](Settings& s) { s.box.xMax = -1.0; }, {"box.xMax = -1", "box.xMin"});
    expectBadSetting([](Settings& s) { s.nThreads = 0; }, {"nThreads = 0", "[1, inf)"});
    expectBadSetting([](Settings& s) { s.dt = 0.0; }, {"dt = 0", "(0, inf)"});
}

TEST(Settings, TimeStepAboveBoundNamesBoundAndSmallestParticle)
{
    expectBadSetting([](Settings& s) { s.dt = 1e-4; },
                     {"dt = 0.0001", "time-step bound", "9.38495e-05", "small", "0.0015"});
    // The smallest particle is the lightest: make the large class light.
    expectBadSetting(
        [](Settings& s) {
            s.classes[1].density = 10.0;
            s.dt = 5e-5;
        },
        {"time-step bound", "large", "0.0025"});
}

TEST(Settings, ParticlesOutsideWallsOrOverlapping)
{
    Simulation sim(paperSettings(box));
    expectError([&] { sim.addParticle(0, -0.01, 0.05); }, {"outside the box", "-0.01"});
    expectError([&] { sim.addParticle(0, 0.0005, 0.05); }, {"outside the box"});   // disc through the wall
    sim.addParticle(0, 0.00075, 0.05);   // touching the wall: fine
    sim.addParticle(1, 0.05, 0.05);
    expectError([&] { sim.addParticle(0, 0.0515, 0.05); }, {"overlaps particle 1", "1 % of the smaller diameter"});
    sim.addParticle(0, 0.05 + 2.0e-3 - 1.0e-5, 0.05);   // 0.67 % of 1.5 mm: tolerated
    expectError([&] { sim.addParticle(2, 0.02, 0.02); }, {"classIndex = 2", "[0, 1]"});
}

TEST(Settings, PackingEmptyClassAndRegion)
{
    Simulation sim(paperSettings(box));
    expectError([&] { sim.packRandom({10, 0}, box, 1); }, {"countPerClass[1]", "large", "= 0", "[1, inf)", "empty size class"});
    expectError([&] { sim.packRandom({10}, box, 1); }, {"countPerClass", "one per size class"});
    expectError([&] { sim.packRandom({10, 10}, {0.0, 0.2, 0.0, 0.1}, 1); }, {"region", "outside the box"});
    expectError([&] { sim.packRandom({100000, 10}, {0.0, 0.01, 0.0, 0.01}, 1); }, {"no room", "small"});
}

TEST(Settings, AdvanceNeedsIntegerSubSteps)
{
    Simulation sim(paperSettings(box));
    sim.addParticle(0, 0.05, 0.05);
    expectError([&] { sim.advance(1.5e-5); }, {"dtOuter = 1.5e-05", "dt = 1e-05", "integer"});
    sim.advance(1e-4);
    EXPECT_EQ(sim.stepCount(), 10);
}

TEST(Settings, LostParticleIsNamed)
{
    Settings s = paperSettings(box);
    Simulation sim(s);
    sim.addParticle(0, 0.05, 0.05);
    sim.addParticle(1, 0.02, 0.05);
    sim.gasVelocityX()[1] = -1e6;   // a silly gas velocity shoots particle 1 through the wall
    sim.dragCoefficient()[1] = 1.0;
    expectError([&] { sim.advance(1e-4); }, {"particle id 1", "left the box"});
}

TEST(Settings, NaNParticleCountsAsLost)
{
    // A NaN position is outside every box: the drift's vectorised box test must see it
    // wherever the particle sits in the arrays (the vector body or the remainder)
    for (const int bad : {0, 17, 38}) {
        Simulation sim(paperSettings(box));
        for (int k = 0; k < 39; ++k) sim.addParticle(0, 0.005 + 0.0022 * k, 0.05);
        sim.gasVelocityX()[bad] = std::nan("");
        sim.dragCoefficient()[bad] = 1.0;
        const std::string named = "particle id " + std::to_string(bad) + " ";
        expectError([&] { sim.advance(1e-4); }, {named.c_str(), "left the box"});
    }
}

TEST(Settings, BadPairAndWallCoefficients)
{
    // The global entries' ranges, each named with its pair or class
    auto pair = [](int a, int b) {
        PairContactSettings p;
        p.classA = a;
        p.classB = b;
        return p;
    };
    expectBadSetting([&](Settings& s) {
        s.contact.pairs = {pair(1, 0)};
        s.contact.pairs[0].restitution = 1.2;
    }, {"contact pair 'large-small' restitution = 1.2 is outside (0, 1]"});
    expectBadSetting([&](Settings& s) {
        s.contact.pairs = {pair(0, 0)};
        s.contact.pairs[0].frictionParticle = -0.1;
    }, {"contact pair 'small-small' frictionParticle = -0.1 is outside [0, inf)"});
    expectBadSetting([&](Settings& s) {
        s.contact.pairs = {pair(0, 1)};
        s.contact.pairs[0].rollingFriction = NAN;
    }, {"contact pair 'small-large' rollingFriction = nan is outside [0, inf)"});
    expectBadSetting([&](Settings& s) {
        s.contact.pairs = {pair(0, 1), pair(1, 0)};
    }, {"contact pair 'small-large' is given twice (as 'small-large' and 'large-small')"});
    expectBadSetting([&](Settings& s) { s.contact.pairs = {pair(0, 2)}; },
                     {"contact pairs[0].classB = 2 is outside [0, 1]"});
    WallContactSettings wall;
    wall.classIndex = 1;
    wall.restitutionWall = 0.0;
    expectBadSetting([&](Settings& s) { s.contact.walls = {wall}; },
                     {"contact wall 'large' restitutionWall = 0 is outside (0, 1]", "infinite damping"});
    wall.restitutionWall.reset();
    wall.frictionWall = -1.0;
    expectBadSetting([&](Settings& s) { s.contact.walls = {wall}; },
                     {"contact wall 'large' frictionWall = -1 is outside [0, inf)"});
    wall.frictionWall.reset();
    wall.rollingFrictionWall = -0.5;
    expectBadSetting([&](Settings& s) { s.contact.walls = {wall}; },
                     {"contact wall 'large' rollingFrictionWall = -0.5 is outside [0, inf)"});
    wall.rollingFrictionWall.reset();
    expectBadSetting([&](Settings& s) { s.contact.walls = {wall, wall}; },
                     {"contact wall 'large' is given twice"});
    wall.classIndex = -1;
    expectBadSetting([&](Settings& s) { s.contact.walls = {wall}; },
                     {"contact walls[0].classIndex = -1 is outside [0, 1]"});
}

TEST(Settings, DashpotBoundTakesThePairsOwnRestitution)
{
    // A pair's own small restitution has the largest damping: the dashpot's bound is that
    // pair's m_eff/eta_n (eta_n from the clamped oscillator of TestHelpers; 1e-9, the
    // bisections' round-off), and a larger step is refused naming the pair's entry
    Settings s = paperSettings(box);
    PairContactSettings p;
    p.classB = 1;
    p.restitution = 0.01;
    s.contact.pairs = {p};
    const double ms = sphereMass(dSmall), ml = sphereMass(dLarge), mEff = ms * ml / (ms + ml);
    const double expected = mEff / etaFor(mEff, s.contact.kn, 0.01);
    EXPECT_NEAR(dashpotTimeStep(s), expected, 1e-9 * expected);
    s.dt = 1.01 * expected;
    expectError([&] { Simulation sim(s); },
                {"dashpot's stability bound at contact pair 'small-large' restitution = 0.01"});
    s.dt = 0.99 * expected;
    EXPECT_NO_THROW(Simulation sim(s));
}
