// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The Hertz-Mindlin contact law (contactLaw HertzMindlin; docs/theory/dem.md, "The Hertz-Mindlin law")
// in both engines, against Hertz's theory of elastic impact (Johnson 1985, Contact
// Mechanics, sections 4.2 and 11.4): the force-overlap F = 4/3 E* sqrt(R*) delta^3/2, the
// peak overlap delta_max = (15 mEff v^2/(16 E* sqrt(R*)))^2/5 and the contact time
// 2.9432 delta_max/v of an elastic impact; Mindlin and Deresiewicz's (1953) tangential
// stiffness 8 G* sqrt(R* delta) below the Coulomb limit; the input restitution at any
// impact speed (Tsuji et al. 1992: with a damping proportional to delta^1/4 the
// restitution does not depend on the speed); and the library's step bounds for the law.
// The reference numbers are computed here from E, nu, R and m, not taken from the library.

#include "TestHelpers.hpp"

#include "dem/ContactKernel.hpp"
#include "dem/ContactLaw.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cfenv>
#include <cmath>
#include <string>

using namespace dem;
using namespace dem::test;

namespace {

// Glass-like spheres on a steel-like wall
constexpr double youngs = 6.3e10, poisson = 0.24;
constexpr double wallYoungs = 2.0e11, wallPoisson = 0.29;

Settings hertzSettings(int dimension, double dt, double e, double mu = 0.0)
{
    Settings s = paperSettings({0.0, 0.1, 0.0, 0.02}, dt);
    for (ParticleClass& c : s.classes) {
        c.youngsModulus = youngs;
        c.poissonRatio = poisson;
    }
    s.contact.law = ContactLawType::hertzMindlin;
    s.contact.wallYoungsModulus = wallYoungs;
    s.contact.wallPoissonRatio = wallPoisson;
    s.contact.restitution = e;
    s.contact.restitutionWall = e;
    s.contact.frictionParticle = mu;
    s.contact.frictionWall = mu;
    s.contact.impactSpeed = 2.0;
    s.dimension = dimension;
    s.slabDepth = dimension == 3 ? 0.01 : 0.0;
    return s;
}

double eStarOf(double e1, double nu1, double e2, double nu2)
{
    return 1.0 / ((1.0 - nu1 * nu1) / e1 + (1.0 - nu2 * nu2) / e2);
}

struct HertzImpact {
    double mEff, rEff, eStar;
    double peakOverlap(double v) const
    {
        return std::pow(15.0 * mEff * v * v / (16.0 * eStar * std::sqrt(rEff)), 0.4);
    }
    // 2 int_0^1 dx/sqrt(1 - x^5/2) = 2.9432752 (Johnson 1985, eq. 11.24's integral, by quadrature)
    double contactTime(double v) const { return 2.9432752 * peakOverlap(v) / v; }
};

/// Two small spheres (wall = false) or a small sphere on the floor (wall = true).
HertzImpact impactOf(bool wall)
{
    const double m = sphereMass(dSmall);
    const double r = 0.5 * dSmall;
    return wall ? HertzImpact{m, r, eStarOf(youngs, poisson, wallYoungs, wallPoisson)}
                : HertzImpact{0.5 * m, 0.5 * r, eStarOf(youngs, poisson, youngs, poisson)};
}

struct Measured {
    double restitution;
    double peakOverlap;   // m
    double contactTime;   // s, while the overlap is positive and the particles approach or press
};

/// A head-on impact at normal speed v: two small spheres, or one on the floor.
Measured headOn(int dimension, bool wall, double v, double e, double dt)
{
    Simulation sim(hertzSettings(dimension, dt, e));
    const double r = 0.5 * dSmall;
    const double gap = 3.0 * v * dt;
    auto add = [&](double x, double y, double vx, double vy) {
        if (dimension == 2) {
            sim.addParticle(0, x, y, vx, vy);
        } else {
            sim.addParticle(0, Vector3{x, y, 0.005}, Vector3{vx, vy, 0.0});
        }
    };
    if (wall) {
        add(0.05, r + gap, 0.0, -v);
    } else {
        add(0.05 - r - 0.5 * gap, 0.01, 0.5 * v, 0.0);
        add(0.05 + r + 0.5 * gap, 0.01, -0.5 * v, 0.0);
    }
    auto overlap = [&] {
        return wall ? r - sim.y()[0] : 2.0 * r - (sim.x()[1] - sim.x()[0]);
    };
    auto separation = [&] { return wall ? sim.vy()[0] : sim.vx()[1] - sim.vx()[0]; };
    double peak = 0.0, inContact = 0.0, last = 0.0;
    for (long k = 0; k < 10000000L; ++k) {
        sim.advance(dt);
        const double o = overlap();
        peak = std::max(peak, o);
        // Overlap interpolated across the steps where it starts and ends
        if (o > 0.0 && last <= 0.0) inContact += dt * o / (o - last);
        else if (o > 0.0) inContact += dt;
        else if (last > 0.0) { inContact += dt * last / (last - o); break; }
        last = o;
    }
    return {separation() / v, peak, inContact};
}

const char* engineName(int dimension) { return dimension == 2 ? "2D" : "slab"; }

} // namespace

TEST(HertzMindlin, ForceOverlapIsHertzAndTangentialStiffnessIsMindlin)
{
    // The kernel at rest (no damping) at overlaps 1e-7 to 1e-5 m: F_n = 4/3 E* sqrt(R*)
    // delta^3/2, and a tangential displacement xi below the Coulomb limit pulls back with
    // 8 G* sqrt(R* delta) xi, G* from 1/G* = 2 (2 - nu)/G; beyond it mu F_n. Within 1e-12.
    const double m = sphereMass(dSmall);
    const double rEff = 0.25 * dSmall;
    const double eStar = eStarOf(youngs, poisson, youngs, poisson);
    const double g = youngs / (2.0 * (1.0 + poisson));
    const double gStar = g / (2.0 * (2.0 - poisson));
    const double mu = 0.3;
    const ContactLaw law = makeHertzMindlinLaw(0.5 * m, rEff, effectiveYoungsModulus(youngs, poisson, youngs, poisson),
                                               effectiveShearModulus(youngs, poisson, youngs, poisson), 1.0, mu);
    for (double delta : {1e-7, 1e-6, 1e-5}) {
        PairGeometry3 c;
        c.overlap = delta;
        c.nHat = Eigen::Vector3d(0.0, 1.0, 0.0);
        c.vRel = Eigen::Vector3d(1e-3, 0.0, 0.0);
        c.rI = c.rJ = 0.5 * dSmall;
        c.xiT = Eigen::Vector3d::Zero();
        c.omegaRel = Eigen::Vector3d::Zero();
        const double fn = 4.0 / 3.0 * eStar * std::sqrt(rEff) * delta * std::sqrt(delta);
        const double dt = 1e-9;   // a tangential step of 1e-12 m: far below the limit
        const PairForce3 f = contactForce<3, HertzMindlin>(c, law, dt);
        EXPECT_NEAR(-f.force.y(), fn, 1e-12 * fn) << "delta = " << delta;
        const double ft = -8.0 * gStar * std::sqrt(rEff * delta) * 1e-3 * dt;
        EXPECT_NEAR(f.force.x(), ft, 1e-12 * std::abs(ft)) << "delta = " << delta;
        const PairForce3 sliding = contactForce<3, HertzMindlin>(c, law, 1.0);
        EXPECT_NEAR(sliding.force.x(), -mu * fn, 1e-12 * mu * fn) << "delta = " << delta;
        // The 2D kernel gives the same
        PairGeometry g2;
        g2.overlap = delta;
        g2.nHat = Eigen::Vector2d(0.0, 1.0);
        g2.vRel = Eigen::Vector2d(1e-3, 0.0);
        g2.rI = g2.rJ = 0.5 * dSmall;
        g2.xiT = 0.0;
        g2.omegaRel = 0.0;
        const PairForce f2 = contactForce<2, HertzMindlin>(g2, law, dt);
        EXPECT_NEAR(-f2.force.y(), fn, 1e-12 * fn);
        EXPECT_NEAR(f2.force.x(), ft, 1e-12 * std::abs(ft));
    }
}

TEST(HertzMindlin, ElasticImpactHasHertzPeakOverlapAndContactTime)
{
    // e = 1 at 0.1 and 2 m/s, dt = t_c/400: the peak overlap within 0.5 % and the contact time
    // within 0.5 % of Hertz's, for a pair and on a wall, in both engines
    for (int dimension : {2, 3}) {
        for (bool wall : {false, true}) {
            const HertzImpact h = impactOf(wall);
            for (double v : {0.1, 2.0}) {
                const double tc = h.contactTime(v);
                const Measured got = headOn(dimension, wall, v, 1.0, tc / 400.0);
                const std::string what = std::string(engineName(dimension)) + (wall ? " wall" : " pair")
                                         + " v = " + std::to_string(v);
                EXPECT_NEAR(got.peakOverlap / h.peakOverlap(v), 1.0, 0.005) << what;
                EXPECT_NEAR(got.contactTime / tc, 1.0, 0.005) << what;
                EXPECT_NEAR(got.restitution, 1.0, 0.005) << what;
            }
        }
    }
}

TEST(HertzMindlin, RestitutionIsTheInputAtEverySpeed)
{
    // e = 0.9, 0.5, 0.2 at 0.1 and 2 m/s (the damping ~ delta^1/4 makes e independent of the
    // speed), dt = t_c/400 of the elastic impact: within 0.5 % of the input, pair and wall,
    // both engines
    for (int dimension : {2, 3}) {
        for (bool wall : {false, true}) {
            const HertzImpact h = impactOf(wall);
            for (double e : {0.9, 0.5, 0.2}) {
                for (double v : {0.1, 2.0}) {
                    const Measured got = headOn(dimension, wall, v, e, h.contactTime(v) / 400.0);
                    EXPECT_NEAR(got.restitution, e, 0.005 * e)
                        << engineName(dimension) << (wall ? " wall" : " pair") << " e = " << e
                        << " v = " << v;
                }
            }
        }
    }
}

TEST(HertzMindlin, StepBoundsAreTheLawsAtTheImpactSpeed)
{
    // pairContactTime: the shortest elastic Hertz contact at impactSpeed (2 m/s here) over the
    // pairs and the walls (here a small sphere on the stiffer wall), within 1e-6. At
    // the safe bound (t_c/10) a head-on pair at that speed keeps e within 1 % and its peak
    // overlap within 2 %; at the stable bound (t_c/4) e within 5 %.
    const Settings s = hertzSettings(2, 1e-9, 0.9);
    const double tc = std::min(impactOf(false).contactTime(2.0), impactOf(true).contactTime(2.0));
    EXPECT_NEAR(pairContactTime(s) / tc, 1.0, 1e-6);
    EXPECT_NEAR(safeTimeStep(s) / tc, 0.1, 1e-6);
    EXPECT_GT(timeStepBound(s), stableTimeStep(s));
    for (int dimension : {2, 3}) {
        const Measured safe = headOn(dimension, false, 2.0, 0.9, safeTimeStep(s));
        EXPECT_NEAR(safe.restitution, 0.9, 0.01 * 0.9) << engineName(dimension);
        const Measured fine = headOn(dimension, false, 2.0, 0.9, tc / 1000.0);
        EXPECT_NEAR(safe.peakOverlap / fine.peakOverlap, 1.0, 0.02) << engineName(dimension);
        const Measured stable = headOn(dimension, false, 2.0, 0.9, stableTimeStep(s));
        EXPECT_NEAR(stable.restitution, 0.9, 0.05 * 0.9) << engineName(dimension);
        std::printf("%s: e at t_c/10 %.4f, at t_c/4 %.4f (input 0.9)\n", engineName(dimension),
                    safe.restitution, stable.restitution);
    }
}

TEST(HertzMindlin, RollingResistanceCombines)
{
    // The rolling torque's limit is mu_r R_r F_n with Hertz's F_n (docs/theory/dem.md, "Rolling
    // resistance"): on the kernel at overlap 1e-6 m, within 1e-12
    const double m = sphereMass(dSmall);
    const double r = 0.5 * dSmall;
    ContactLaw law = makeHertzMindlinLaw(m, r, effectiveYoungsModulus(youngs, poisson, wallYoungs, wallPoisson),
                                         effectiveShearModulus(youngs, poisson, wallYoungs, wallPoisson), 1.0, 0.5);
    const double muR = 0.1;
    addRollingResistance(law, muR, r, m * dSmall * dSmall / 10.0, 1e-6);
    PairGeometry g;
    g.overlap = 1e-6;
    g.nHat = Eigen::Vector2d(0.0, -1.0);
    g.vRel = Eigen::Vector2d::Zero();
    g.rI = r;
    g.rJ = 0.0;
    g.xiT = 0.0;
    g.omegaRel = 1e3;   // fast: the torque at its limit
    const PairForce f = contactForce<2, HertzMindlin, true>(g, law, 1e-6);
    const double fn = 4.0 / 3.0 * eStarOf(youngs, poisson, wallYoungs, wallPoisson) * std::sqrt(r) * 1e-9;
    EXPECT_NEAR(f.rollingTorque, -muR * r * fn, 1e-12 * muR * r * fn);
}

TEST(HertzMindlin, BadMaterialsAndEntriesRefusedNamingThem)
{
    auto message = [](const Settings& s) {
        try {
            Simulation sim(s);
        } catch (const Error& err) {
            return std::string(err.what());
        }
        return std::string("accepted");
    };
    Settings s = hertzSettings(2, 1e-8, 0.9);
    s.classes[1].youngsModulus = 0.0;
    EXPECT_EQ(message(s), "classes[1] ('large').youngsModulus = 0 is outside (0, inf)");
    s = hertzSettings(2, 1e-8, 0.9);
    s.contact.wallPoissonRatio = 0.6;
    EXPECT_EQ(message(s), "wallPoissonRatio = 0.6 is outside (-1, 0.5] (contactLaw HertzMindlin)");
    s = hertzSettings(2, 1e-8, 0.9);
    s.contact.kt = 100.0;
    EXPECT_NE(message(s).find("kt = 100 is the linear law's tangential stiffness"), std::string::npos);
    EXPECT_EQ(contactLawFromName("HertzMindlin"), ContactLawType::hertzMindlin);
    EXPECT_EQ(contactLawFromName("linear"), ContactLawType::linear);
    try {
        contactLawFromName("hertz");
        ADD_FAILURE() << "'hertz' accepted";
    } catch (const Error& err) {
        EXPECT_EQ(std::string(err.what()), "contactLaw 'hertz' is not one of: linear, HertzMindlin");
    }
}

TEST(HertzMindlin, ContactAtZeroOverlapRaisesNoInvalidOperation)
{
    // A pair whose d^2 is one ulp below (r_i + r_j)^2 counts as touching while its distance
    // rounds to r_i + r_j: the overlap is 0, so kt = Kt' sqrt(0) = 0 and the Coulomb limit
    // is 0. The kernel must raise no FE_INVALID there (the solver traps it), in 2D and 3D,
    // and give no force, the history carried on by the step's tangential displacement.
    const double m = sphereMass(dSmall), r = 0.5 * dSmall, dt = 1e-7;
    const ContactLaw law = makeHertzMindlinLaw(0.5 * m, 0.5 * r, eStarOf(youngs, poisson, youngs, poisson),
                                               1e10, 0.5, 0.3);
    volatile double zero = 0.0;   // not folded at compile time
    const double vt = 0.01, xi = 2e-9;
    PairGeometry g2{zero, {1.0, 0.0}, {0.2, vt}, r, r, xi, 0.0};
    std::feclearexcept(FE_ALL_EXCEPT);
    const PairForce f2 = contactForce<2, HertzMindlin>(g2, law, dt);
    EXPECT_FALSE(std::fetestexcept(FE_INVALID)) << "2D";
    EXPECT_EQ(f2.force.squaredNorm(), 0.0);
    EXPECT_EQ(f2.xiT, xi + vt * dt);

    PairGeometry3 g3;
    g3.overlap = zero;
    g3.nHat = Eigen::Vector3d(1.0, 0.0, 0.0);
    g3.vRel = Eigen::Vector3d(0.2, vt, 0.0);
    g3.rI = r;
    g3.rJ = r;
    g3.xiT = Eigen::Vector3d(0.0, xi, 0.0);
    g3.omegaRel.setZero();
    std::feclearexcept(FE_ALL_EXCEPT);
    const PairForce3 f3 = contactForce<3, HertzMindlin>(g3, law, dt);
    EXPECT_FALSE(std::fetestexcept(FE_INVALID)) << "3D";
    EXPECT_EQ(f3.force.squaredNorm(), 0.0);
}
