// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The step checks beyond the contact time (docs/theory/numerics.md, "The DEM step's bound"): the
// dashpot's own stability bound, and Hertz-Mindlin's impact speed against the bed's own.
// An explicit step with a dashpot eta on a contact of effective mass m_eff reverses the
// relative velocity within one step once eta dt/m_eff > 1, and the contact then rebounds
// nearly elastically whatever restitution was asked for: Chung and Ooi's test 3 set-up
// (alumina, d = 5 mm, 3.9 m/s on a rigid wall) at e = 0.001 and t_H/50 (t_H Hertz's elastic
// contact time) rebounds at 0.14 of its speed (the linear law, kn = 1e6 N/m, at its own
// pi sqrt(m/kn)/50: 0.98); at t_H/200 at 0.001. The largest step is the least m_eff/eta over
// the wall and the pair, eta written here from the laws' definitions (docs/theory/dem.md): the
// linear law's 2 zeta sqrt(m_eff kn); Hertz-Mindlin's alpha(e) sqrt(m_eff Kn) delta_max^1/4 at the
// elastic peak overlap of the impact, alpha taken from the library's restitution solver,
// whose own test (Chung and Ooi's test 3) holds it to the input e.

#include "TestHelpers.hpp"

#include "dem/ContactLaw.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace dem;
using namespace dem::test;

namespace {

constexpr double d = 5e-3, density = 4000.0, youngs = 3.8e11, poisson = 0.23, speed = 3.9;

/// Chung and Ooi's test 3: one alumina sphere of class 0, HertzMindlin (impactSpeed 3.9 m/s)
/// or the linear law (kn = 1e6 N/m), restitution e on the floor of a rigid wall, no gravity.
Settings testThree(bool hertz, double e)
{
    Settings s;
    s.classes = {{"alumina", d, density, youngs, poisson}};
    s.box = {-0.1, 0.1, -0.1, 0.1};
    s.gravity[1] = 0.0;
    s.contact.frictionWall = 0.0;
    s.contact.restitution = e;
    s.contact.restitutionWall = e;
    if (hertz) {
        s.contact.law = ContactLawType::hertzMindlin;
        s.contact.wallYoungsModulus = 1e20 * youngs;
        s.contact.wallPoissonRatio = poisson;
        s.contact.impactSpeed = speed;
    } else {
        s.contact.kn = 1e6;
    }
    return s;
}

double mass() { return density * pi * d * d * d / 6.0; }
double eStar() { return youngs / (1.0 - poisson * poisson); }   // on a rigid wall

/// Hertz's elastic contact time at 3.9 m/s (Johnson 1985, 11.4), s.
double hertzTime()
{
    const double r = 0.5 * d;
    const double peak = std::pow(15.0 * mass() * speed * speed / (16.0 * eStar() * std::sqrt(r)), 0.4);
    return 2.94320 * peak / speed;
}

/// The contact time the steps are given in: Hertz's elastic one at 3.9 m/s, or the linear
/// law's undamped half period pi sqrt(m/kn), s.
double contactScale(bool hertz) { return hertz ? hertzTime() : pi * std::sqrt(mass() / 1e6); }

/// m_eff/eta of a wall contact (m_eff = m) or of a pair (m/2, R* = r/2, E* half the wall's).
double stepOf(bool hertz, double e, bool wall)
{
    const double m = wall ? mass() : 0.5 * mass(), r = wall ? 0.5 * d : 0.25 * d;
    if (!hertz) return m / etaFor(m, 1e6, e);
    const double es = wall ? eStar() : 0.5 * eStar();
    const double kn = 4.0 / 3.0 * es * std::sqrt(r);
    const double peak = std::pow(15.0 * m * speed * speed / (16.0 * es * std::sqrt(r)), 0.4);
    return m / (hertzDampingFromRestitution(e) * std::sqrt(m * kn) * std::pow(peak, 0.25));
}

/// The largest step that works: the least m_eff/eta over the wall and the pair, s.
double largestStep(bool hertz, double e) { return std::min(stepOf(hertz, e, true), stepOf(hertz, e, false)); }

/// The rebound speed over the impact speed at step dt.
double rebound(bool hertz, double e, double dt)
{
    Settings s = testThree(hertz, e);
    s.dt = dt;
    Simulation sim(s);
    const double r = 0.5 * d, floor = s.box.yMin;
    sim.addParticle(0, 0.0, floor + r + 10.0 * speed * dt + 1e-9, 0.0, -speed);
    for (int k = 0; k < 100000 && sim.y()[0] < floor + r + 20.0 * speed * dt; ++k) sim.advance(dt);
    return sim.vy()[0] / speed;
}

} // namespace

TEST(DashpotBound, SmallRestitutionAtTooLargeAStepIsRefusedNamingTheLargestThatWorks)
{
    for (bool hertz : {true, false}) {
        const char* law = hertz ? "HertzMindlin" : "linear";
        Settings s = testThree(hertz, 0.001);
        s.dt = contactScale(hertz) / 50.0;
        ASSERT_GT(s.dt, largestStep(hertz, 0.001)) << law;   // the set-up is above the bound
        const std::string message = errorOf([&] { Simulation sim(s); });
        std::printf("  %s: %s\n", law, message.c_str());
        for (const std::string word : {"restitution", "deltaT", "dt = "}) {
            EXPECT_NE(message.find(word), std::string::npos) << law << ": " << message;
        }
        // The bound itself within 1e-6 (the library's is the same m/eta)
        const std::string bound = formatValue(largestStep(hertz, 0.001));
        EXPECT_NE(message.find("(0, " + bound + "] s"), std::string::npos) << law << ": " << message;
        EXPECT_NEAR(dashpotTimeStep(s) / largestStep(hertz, 0.001), 1.0, 1e-6) << law;
        // The largest step works: the rebound within 10 % of e (the step is still coarse
        // next to the damped contact), where t_H/50 gave many times e
        const double atBound = rebound(hertz, 0.001, largestStep(hertz, 0.001));
        EXPECT_NEAR(atBound, 0.001, 1e-4) << law;
    }
}

TEST(DashpotBound, NearTheBoundWarnedAndTheProjectsSettingsPassQuietly)
{
    for (bool hertz : {true, false}) {
        Settings s = testThree(hertz, 0.001);
        s.dt = 0.7 * largestStep(hertz, 0.001);
        const std::vector<std::string> warnings = settingsWarnings(s);
        ASSERT_EQ(warnings.size(), 1u) << hertz;
        EXPECT_NE(warnings[0].find("restitution"), std::string::npos) << warnings[0];
        EXPECT_NE(warnings[0].find("deltaT"), std::string::npos) << warnings[0];
        s.dt = 0.4 * largestStep(hertz, 0.001);
        EXPECT_TRUE(settingsWarnings(s).empty()) << hertz;
    }
    // The tutorials' restitutions (0.9, 0.97) with the paper's particles: the dashpot's
    // bound lies far above the stable bound t_c/4 that the solver holds every case to (m/eta
    // ~ t_c/(2 pi zeta), 4.7 t_c at e = 0.9), so no case the solver runs is refused or
    // warned; at the paper's step 1e-5 s nothing is said.
    for (double e : {0.9, 0.97}) {
        Settings s = paperSettings({0.0, 0.1, 0.0, 0.1});
        s.contact.restitution = e;
        s.contact.restitutionWall = e;
        EXPECT_GT(dashpotTimeStep(s), 10.0 * stableTimeStep(s)) << e;
        EXPECT_TRUE(settingsWarnings(s).empty()) << e;
    }
}

TEST(DashpotBound, HertzImpactSpeedBelowTheBedsOwnIsWarnedAndItsStepChecked)
{
    // A bed under gravity collides at least at its own speed scale sqrt(|g| d_max) (a fall
    // through half a diameter, 0.22 m/s for d = 5 mm): an impactSpeed below it is warned,
    // naming it, and the step bounds are taken at the bed's scale, so a step that is only
    // right for the stated speed is refused naming both speeds.
    Settings s = testThree(true, 0.5);
    s.gravity[1] = -9.81;
    const double bed = std::sqrt(9.81 * d);
    EXPECT_NEAR(bedSpeedScale(s), bed, 1e-12 * bed);
    for (double slow : {1e-3, 1e-9}) {
        s.contact.impactSpeed = slow;
        s.dt = 1e-7;
        const std::vector<std::string> warnings = settingsWarnings(s);
        ASSERT_EQ(warnings.size(), 1u) << slow;
        EXPECT_NE(warnings[0].find("impactSpeed = " + formatValue(slow)), std::string::npos) << warnings[0];
        // Hertz's contact time at the bed's scale (Johnson 1985), not at the stated speed;
        // within 1e-4, Johnson's constant 2.9432 being given to five digits
        const double r = 0.5 * d;
        const double peak = std::pow(15.0 * mass() * bed * bed / (16.0 * eStar() * std::sqrt(r)), 0.4);
        EXPECT_NEAR(pairContactTime(s), 2.94320 * peak / bed, 1e-4 * pairContactTime(s)) << slow;
        // The eq. 7-like bound at the stated speed, not at the bed's: refused
        Settings slowOnly = s;
        slowOnly.gravity[1] = 0.0;
        s.dt = 0.9 * timeStepBound(slowOnly);
        ASSERT_GT(s.dt, timeStepBound(s)) << slow;
        const std::string message = errorOf([&] { Simulation sim(s); });
        EXPECT_NE(message.find("impactSpeed = " + formatValue(slow)), std::string::npos) << message;
        EXPECT_NE(message.find("bed's own speed scale"), std::string::npos) << message;
    }
    // At or above the bed's scale nothing changes: the bounds at impactSpeed, no warning
    s.contact.impactSpeed = 2.0 * bed;
    s.dt = 1e-7;
    EXPECT_TRUE(settingsWarnings(s).empty());
    EXPECT_EQ(hertzSpeed(s), 2.0 * bed);
}
