// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The order of the restitution's error in the DEM step (README.md, "Restitution and the DEM
// step"): head-on impacts (a pair and the floor, both engines, both laws) at dt = t_c/25,
// t_c/50, t_c/100, t_c/200, the observed order log2(err(dt)/err(dt/2)) against the
// integrator's; and e at the paper's step, 1e-5 s.
//
// Expected order 1. The step is velocity Verlet (half-kick, drift, forces, half-kick) with
// the dashpot fed the half-step velocity v(t - dt/2) = v - (dt/2) x'' + O(dt^2): to O(dt^2)
// the scheme integrates (m - eta dt/2) x'' = -kn x - eta x', a mass m (1 - zeta w dt)
// (w = sqrt(kn/m)), so the damping ratio is zeta (1 + zeta w dt/2) and e changes by L/N,
// N = t_c/dt, L = (w t_c) zeta^2/2 de/dzeta ("lag"). And the first force, sampled at the
// first step with an overlap, acts from half a step before it: a contact that starts a
// fraction phi of a step after a step misses the dashpot's impulse eta v0 dt (1/2 - phi),
// its speed is as if 1 + zeta w dt (1 - 2 phi) times higher, and e changes by
// A (1 - 2 phi)/N, A = (w t_c) zeta e ("onset", 0 averaged over phi).
// Both first order; the parting adds none: the clamped force reaches zero continuously.
// The Hertz law's dashpot starts at zero (delta^1/4): its onset error is O(dt^5/4), and
// the lag keeps the law first order.

#include "verification/VerificationHelpers.hpp"

#include <cstdio>

using namespace dem;
using namespace dem::verification;

namespace {

enum class Law { linear, hertzMindlin };

const char* lawName(Law law) { return law == Law::linear ? "linear" : "HertzMindlin"; }

// Linear: the paper's small particles (kn 800 N/m, docs/theory/paper-model.md) at 0.5 m/s.
// HertzMindlin: Chung & Ooi's test-3 Al oxide (E 3.8e11 Pa, nu 0.23) at 3.9 m/s.
struct Impactor {
    double d, rho, speed;
};
const Impactor paperSmall{1.5e-3, 2525.0, 0.5};
const Impactor alOxide{5e-3, 4000.0, 3.9};
constexpr double knPaper = 800.0, youngsOxide = 3.8e11, poissonOxide = 0.23;

/// Contact time of the impact: the clamped linear contact's at e, or Hertz's elastic one at
/// the impact speed, s.
double referenceContactTime(Law law, bool wall, double e)
{
    if (law == Law::linear) {
        const double m = sphereMass(paperSmall.d, paperSmall.rho);
        return contactTime(wall ? m : 0.5 * m, knPaper, e);
    }
    const double m = sphereMass(alOxide.d, alOxide.rho), r = 0.5 * alOxide.d;
    const double nu2 = poissonOxide * poissonOxide;
    const double eStar = wall ? youngsOxide / (1.0 - nu2) : youngsOxide / (2.0 * (1.0 - nu2));
    return hertzImpactDuration(wall ? m : 0.5 * m, wall ? r : 0.5 * r, eStar, alOxide.speed);
}

/// Rebound over impact speed of a head-on impact on the floor (wall) or of two equal
/// spheres, at dt = t_c/steps; the contact starts `phase` of a step after a step.
double restitution(Law law, int dimension, bool wall, double e, double steps, double phase)
{
    const Impactor& p = law == Law::linear ? paperSmall : alOxide;
    const double size = 20.0 * p.d;
    Settings s = oneClass(p.d, p.rho, {-size, size, -size, size}, dimension, 3.0 * p.d, 1.0);
    s.dt = referenceContactTime(law, wall, e) / steps;
    if (law == Law::linear) {
        s.contact.kn = knPaper;
    } else {
        setHertzMindlin(s, youngsOxide, poissonOxide);
        s.contact.impactSpeed = p.speed;
    }
    s.contact.restitution = e;
    s.contact.restitutionWall = e;
    Simulation sim(s);
    const double r = 0.5 * p.d, gap = (10.0 + phase) * p.speed * s.dt, z = 1.5 * p.d;
    if (wall) {
        place(sim, 0, {0.0, s.box.yMin + r + gap, z}, {0.0, -p.speed, 0.0}, Vec3::Zero());
    } else {
        place(sim, 0, {-r - 0.5 * gap, 0.0, z}, {0.5 * p.speed, 0.0, 0.0}, Vec3::Zero());
        place(sim, 0, {r + 0.5 * gap, 0.0, z}, {-0.5 * p.speed, 0.0, 0.0}, Vec3::Zero());
    }
    auto overlap = [&]() {
        return wall ? r - (sim.y()[0] - s.box.yMin) : p.d - (sim.x()[1] - sim.x()[0]);
    };
    bool touched = false;
    for (long k = 0; k < 100L * static_cast<long>(steps); ++k) {
        sim.advance(s.dt);
        touched = touched || overlap() > 0.0;
        if (touched && overlap() <= 0.0) break;
    }
    return (wall ? sim.vy()[0] : sim.vx()[1] - sim.vx()[0]) / p.speed;
}

/// The linear law's first-order error derived above, e(t_c/N) - e = (A (1 - 2 phi) + L)/N,
/// from the clamped oscillator of TestHelpers.hpp (not the library).
struct FirstOrder {
    double onset;   ///< A = (w t_c) zeta e
    double lag;     ///< L = (w t_c) zeta^2/2 de/dzeta
    double at(double phase) const { return onset * (1.0 - 2.0 * phase) + lag; }
};
FirstOrder linearFirstOrder(double mEff, double kn, double e)
{
    const double zeta = test::etaFor(mEff, kn, e) / (2.0 * std::sqrt(mEff * kn));
    const double h = 1e-6 * zeta;
    const double dedzeta = (test::clampedContactEnd(zeta + h).restitution
                            - test::clampedContactEnd(zeta - h).restitution) / (2.0 * h);
    const double wtc = test::clampedContactEnd(zeta).time;
    return {wtc * zeta * e, 0.5 * wtc * zeta * zeta * dedzeta};
}

constexpr double stepsPerContact[] = {25.0, 50.0, 100.0, 200.0};

/// e(t_c/N) - e at the four steps, printed with the observed orders.
struct Refinement {
    double err[4];
    double order(int k) const { return std::log2(err[k] / err[k + 1]); }
};
Refinement refine(Law law, int dimension, bool wall, double e, double phase)
{
    Refinement r;
    for (int k = 0; k < 4; ++k) {
        r.err[k] = restitution(law, dimension, wall, e, stepsPerContact[k], phase) - e;
    }
    std::printf("  %-12s %-4s %s e %.2f phase %.1f: e_DEM - e %+.2e %+.2e %+.2e %+.2e at t_c/25-"
                "t_c/200, order %.3f %.3f %.3f\n", lawName(law), engineName(dimension),
                wall ? "wall" : "pair", e, phase, r.err[0], r.err[1], r.err[2], r.err[3],
                r.order(0), r.order(1), r.order(2));
    return r;
}

} // namespace

TEST(RestitutionStepOrder, LinearLawIsFirstOrderWithTheDerivedCoefficient)
{
    // Order 1 within 0.1 at e = 0.2-0.8 for every step halving (at e = 0.97 the first-order
    // part is so small, A = 0.029, L = -4e-4, that at t_c/25 the second-order one moves the
    // ratio by 0.2: printed). The coefficient, extrapolated free of the second-order part
    // (2 N err(t_c/200) - N/2 err(t_c/100), N = 200), equals A (1 - 2 phi) + L within 1 % of A
    // (the third-order remainder) at every e.
    const double m = sphereMass(paperSmall.d, paperSmall.rho);
    for (int dimension : {2, 3}) {
        for (bool wall : {true, false}) {
            for (double e : {0.2, 0.5, 0.8, 0.97}) {
                const FirstOrder derived = linearFirstOrder(wall ? m : 0.5 * m, knPaper, e);
                for (double phase : {0.1, 0.5, 0.9}) {
                    const Refinement r = refine(Law::linear, dimension, wall, e, phase);
                    const std::string where = std::string(engineName(dimension))
                                              + (wall ? " wall" : " pair") + " e "
                                              + std::to_string(e) + " phase " + std::to_string(phase);
                    if (e <= 0.8) {
                        for (int k = 0; k < 3; ++k) EXPECT_NEAR(r.order(k), 1.0, 0.1) << where << " step " << k;
                    }
                    const double extrapolated = 2.0 * 200.0 * r.err[3] - 100.0 * r.err[2];
                    std::printf("    first-order coefficient %+.5f, derived %+.5f\n", extrapolated,
                                derived.at(phase));
                    EXPECT_NEAR(extrapolated, derived.at(phase), 0.01 * derived.onset) << where;
                }
            }
        }
    }
}

TEST(RestitutionStepOrder, HertzMindlinIsFirstOrder)
{
    // The lag's order 1 and, for a contact starting in a step's second half (phi >= 1/2),
    // the onset's 5/4 of the same sign: the observed order lies in [1, 1.25], here within 0.1,
    // at e = 0.2-0.8 from t_c/50 on (at t_c/25 the elastic second-order error, 3e-4 at
    // e = 0.97, moves the ratio by up to 0.45 at e = 0.8). phi = 0.1 and e = 0.97 printed:
    // there the onset and the lag partly cancel, and the order tends to 1 as dt^1/4 does.
    for (int dimension : {2, 3}) {
        for (bool wall : {true, false}) {
            for (double e : {0.2, 0.5, 0.8, 0.97}) {
                for (double phase : {0.1, 0.5, 0.9}) {
                    const Refinement r = refine(Law::hertzMindlin, dimension, wall, e, phase);
                    if (e > 0.8 || phase < 0.5) continue;
                    for (int k = 1; k < 3; ++k) {
                        EXPECT_GE(r.order(k), 1.0 - 0.1) << engineName(dimension) << " e " << e;
                        EXPECT_LE(r.order(k), 1.25 + 0.1) << engineName(dimension) << " e " << e;
                    }
                }
            }
        }
    }
}

namespace {

/// e of a head-on impact of the paper's classes a and b (b < 0: the floor) at 0.5 m/s and
/// its DEM step, 1e-5 s, the contact starting `phase` of a step after a step.
double paperImpact(int a, int b, double phase)
{
    const double dt = 1e-5, v0 = 0.5;
    Settings s = test::paperSettings({-0.05, 0.05, -0.05, 0.05}, dt);
    Simulation sim(s);
    const double ra = 0.5 * s.classes[a].diameter;
    const double rb = b < 0 ? 0.0 : 0.5 * s.classes[b].diameter;
    const double gap = (10.0 + phase) * v0 * dt;
    if (b < 0) {
        sim.addParticle(a, 0.0, s.box.yMin + ra + gap, 0.0, -v0);
    } else {
        sim.addParticle(a, -ra - 0.5 * gap, 0.0, 0.5 * v0);
        sim.addParticle(b, rb + 0.5 * gap, 0.0, -0.5 * v0);
    }
    auto overlap = [&]() {
        return b < 0 ? ra - (sim.y()[0] - s.box.yMin) : ra + rb - (sim.x()[1] - sim.x()[0]);
    };
    bool touched = false;
    for (int k = 0; k < 100000; ++k) {
        sim.advance(dt);
        touched = touched || overlap() > 0.0;
        if (touched && overlap() <= 0.0) break;
    }
    return (b < 0 ? sim.vy()[0] : sim.vx()[1] - sim.vx()[0]) / v0;
}

} // namespace

TEST(RestitutionStepOrder, PaperStepSpreadsEOverTheContactPhase)
{
    // The paper's e = 0.97, kn = 800 N/m, dt = 1e-5 s, every kind of contact, the contact
    // starting at 20 phases spread over a step (a bed's contacts start at any). Each within
    // 1 % of e (the safe bound t_c/10 that every kind is under: docs/theory/numerics.md, "The DEM step's
    // bound"); their mean within A/(10 N) of e + L/N: the onset's first-order part averages
    // out over the phase, the lag's stays.
    const double e = 0.97, kn = 800.0, dt = 1e-5;
    const Settings paper = test::paperSettings({-0.05, 0.05, -0.05, 0.05}, dt);
    const double mass[2] = {sphereMass(paper.classes[0].diameter, paper.classes[0].density),
                            sphereMass(paper.classes[1].diameter, paper.classes[1].density)};
    struct Kind {
        const char* name;
        int a, b;
    };
    for (const Kind& kind : {Kind{"small-small", 0, 0}, Kind{"small-large", 0, 1},
                             Kind{"large-large", 1, 1}, Kind{"small-wall", 0, -1},
                             Kind{"large-wall", 1, -1}}) {
        const double ma = mass[kind.a];
        const double mEff = kind.b < 0 ? ma : ma * mass[kind.b] / (ma + mass[kind.b]);
        const double steps = contactTime(mEff, kn, e) / dt;
        const FirstOrder derived = linearFirstOrder(mEff, kn, e);
        constexpr int phases = 20;
        double sum = 0.0, low = INFINITY, high = -INFINITY;
        for (int k = 0; k < phases; ++k) {
            const double got = paperImpact(kind.a, kind.b, (k + 0.5) / phases);
            EXPECT_NEAR(got, e, 0.01 * e) << kind.name << " phase " << (k + 0.5) / phases;
            sum += got;
            low = std::min(low, got);
            high = std::max(high, got);
        }
        const double mean = sum / phases;
        std::printf("  paper's step, %-11s t_c/dt %5.2f: e %.4f-%.4f over the phase, mean %.5f "
                    "(first order: %.4f-%.4f, mean %.5f)\n", kind.name, steps, low, high, mean,
                    e + (derived.lag - derived.onset) / steps, e + (derived.lag + derived.onset) / steps,
                    e + derived.lag / steps);
        EXPECT_NEAR(mean, e + derived.lag / steps, 0.1 * derived.onset / steps) << kind.name;
    }
}
