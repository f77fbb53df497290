// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Chung & Ooi (2011, Granular Matter 13:643) with the HertzMindlin law, in both engines.
// Tests 1 and 2: elastic normal impacts of two equal glass spheres (R = 10 mm, E = 4.8e10 Pa,
// nu = 0.2, rho = 2800 kg/m^3, 10 m/s each) and of an aluminium sphere on a rigid plane
// (R = 0.1 m, E = 7e10 Pa, nu = 0.3, rho = 2699 kg/m^3, 0.2 m/s; Kratos
// DEM3D_chung_ooi_tests/test1_data, test2_data): the peak overlap, the peak force and the
// contact time against Hertz's (Johnson 1985, section 11.4), within the step's error.
// Test 3: the restitution at e = 0.2 ... 1 on a wall and between two spheres (Al oxide,
// R = 2.5 mm, E = 3.8e11 Pa, nu = 0.23, 3.9 m/s), Kratos's 1e-3. Test 4: the oblique impacts
// against the paper's Al-oxide curves (its own Hertz-Mindlin results), the suite's 10 %
// at every angle. Tests 5 and 6: the Al alloy (E = 7e10 Pa, nu = 0.33; Kratos
// benchmark6DEM.mdpa): sliding impacts against the rigid-body impulse result, and the
// spinning impacts against the paper's curves where the contact slides.

#include "verification/ObliqueImpact.hpp"

#include <algorithm>

using namespace dem;
using namespace dem::verification;

namespace {

struct Peak {
    double overlap;       // m
    double force;         // N, from the velocity change per step
    double contactTime;   // s
    double restitution;
};

/// A head-on impact of two equal spheres approaching at `speed` (wall = false) or of one on
/// the floor, HertzMindlin with (youngs, poisson), at dt = t_c/steps of Hertz's t_c.
Peak normalImpact(int dimension, bool wall, double d, double rho, double youngs, double poisson,
                  double speed, double e, double steps)
{
    const double m = sphereMass(d, rho), r = 0.5 * d;
    const double eStar = wall ? youngs / (1.0 - poisson * poisson)
                              : youngs / (2.0 * (1.0 - poisson * poisson));
    const double mEff = wall ? m : 0.5 * m, rEff = wall ? r : 0.5 * r;
    const double size = 20.0 * d;
    Settings s = oneClass(d, rho, {-size, size, -size, size}, dimension, 3.0 * d, 1.0);
    s.dt = hertzImpactDuration(mEff, rEff, eStar, speed) / steps;
    setHertzMindlin(s, youngs, poisson);
    s.contact.restitution = e;
    s.contact.restitutionWall = e;
    s.contact.impactSpeed = speed;
    Simulation sim(s);
    const double gap = 10.0 * speed * s.dt + 1e-9 * r, z = 1.5 * d;
    if (wall) {
        place(sim, 0, {0.0, s.box.yMin + r + gap, z}, {0.0, -speed, 0.0}, Vec3::Zero());
    } else {
        place(sim, 0, {-r - 0.5 * gap, 0.0, z}, {0.5 * speed, 0.0, 0.0}, Vec3::Zero());
        place(sim, 0, {r + 0.5 * gap, 0.0, z}, {-0.5 * speed, 0.0, 0.0}, Vec3::Zero());
    }
    auto overlap = [&]() { return wall ? r - (sim.y()[0] - s.box.yMin) : d - (sim.x()[1] - sim.x()[0]); };
    auto speedOf = [&]() { return wall ? sim.vy()[0] : sim.vx()[1]; };
    Peak p{0.0, 0.0, 0.0, 0.0};
    double last = overlap(), v = speedOf();
    for (long k = 0; k < 100L * static_cast<long>(steps); ++k) {
        sim.advance(s.dt);
        const double o = overlap(), vNew = speedOf();
        p.overlap = std::max(p.overlap, o);
        p.force = std::max(p.force, m * std::abs(vNew - v) / s.dt);
        if (o > 0.0) p.contactTime += last <= 0.0 ? s.dt * o / (o - last) : s.dt;
        if (o <= 0.0 && last > 0.0) {
            p.contactTime += s.dt * last / (last - o);
            break;
        }
        last = o;
        v = vNew;
    }
    p.restitution = wall ? sim.vy()[0] / speed : (sim.vx()[1] - sim.vx()[0]) / speed;
    return p;
}

void checkAgainstHertz(int dimension, bool wall, double d, double rho, double youngs,
                       double poisson, double speed, const char* test)
{
    const double m = sphereMass(d, rho), r = 0.5 * d;
    const double eStar = wall ? youngs / (1.0 - poisson * poisson)
                              : youngs / (2.0 * (1.0 - poisson * poisson));
    const double mEff = wall ? m : 0.5 * m, rEff = wall ? r : 0.5 * r;
    const double deltaMax = hertzPeakOverlap(mEff, rEff, eStar, speed);
    const double forceMax = 4.0 / 3.0 * eStar * std::sqrt(rEff) * std::pow(deltaMax, 1.5);
    const double tc = hertzImpactDuration(mEff, rEff, eStar, speed);
    const Peak p = normalImpact(dimension, wall, d, rho, youngs, poisson, speed, 1.0, 1000.0);
    std::printf("  %s %-4s: peak overlap %.4g/%.4g m, force %.4g/%.4g N, t_c %.4g/%.4g s "
                "(DEM/Hertz); relative errors %.2e %.2e %.2e, e - 1 %.2e\n", test,
                engineName(dimension), p.overlap, deltaMax, p.force, forceMax, p.contactTime, tc,
                p.overlap / deltaMax - 1.0, p.force / forceMax - 1.0, p.contactTime / tc - 1.0,
                p.restitution - 1.0);
    // Tolerances from the step, dt = t_c/1000: the peaks are sampled once a step, within
    // (pi dt/t_c)^2/8 ~ 1e-6 of the continuous peak, and velocity Verlet's own error is of
    // order (dt/t_c)^2 (overlap 1e-5; the force, a step's mean from the velocity change,
    // 1e-4); the contact time's ends are interpolated within a step, dt/t_c = 1e-3; the
    // elastic (e = 1) step conserves energy to (dt/t_c)^2, 1e-6 in e
    const std::string what = std::string(test) + " " + engineName(dimension);
    EXPECT_NEAR(p.overlap / deltaMax, 1.0, 1e-5) << what;
    EXPECT_NEAR(p.force / forceMax, 1.0, 1e-4) << what;
    EXPECT_NEAR(p.contactTime / tc, 1.0, 1e-3) << what;
    EXPECT_NEAR(p.restitution, 1.0, 1e-6) << what;
}

} // namespace

TEST(ChungOoiHertz, Test1ElasticImpactOfTwoSpheres)
{
    for (int dimension : {2, 3}) {
        checkAgainstHertz(dimension, false, 0.02, 2800.0, 4.8e10, 0.2, 20.0, "test 1");
    }
}

TEST(ChungOoiHertz, Test2ElasticImpactOnARigidPlane)
{
    for (int dimension : {2, 3}) {
        checkAgainstHertz(dimension, true, 0.2, 2699.0, 7e10, 0.3, 0.2, "test 2");
    }
}

TEST(ChungOoiHertz, Test3RestitutionMatchesTheInputAtEveryE)
{
    // Tolerance Kratos's 1e-3 on e at dt = t_c/1000
    for (int dimension : {2, 3}) {
        for (bool wall : {true, false}) {
            for (double e : {0.2, 0.4, 0.6, 0.8, 1.0}) {
                const Peak p = normalImpact(dimension, wall, 5e-3, 4000.0, 3.8e11, 0.23, 3.9, e, 1000.0);
                EXPECT_NEAR(p.restitution, e, 1e-3)
                    << engineName(dimension) << (wall ? " wall" : " pair") << " e " << e;
            }
        }
    }
}

TEST(ChungOoiHertz, Test3SmallRestitutionsMatchTheInput)
{
    // The overdamped end (e = 0 is refused, README.md): Kratos's 1e-3 at dt = t_c/1000
    for (int dimension : {2, 3}) {
        for (bool wall : {true, false}) {
            for (double e : {0.01, 0.05, 0.1, 0.13, 0.14}) {
                const Peak p = normalImpact(dimension, wall, 5e-3, 4000.0, 3.8e11, 0.23, 3.9, e, 1000.0);
                std::printf("  test 3 %-4s %s e %.2f: DEM %.5f at t_c/1000\n", engineName(dimension),
                            wall ? "wall" : "pair", e, p.restitution);
                EXPECT_NEAR(p.restitution, e, 1e-3)
                    << engineName(dimension) << (wall ? " wall" : " pair") << " e " << e;
            }
        }
    }
}

namespace {

// Test 4: Al oxide; tests 5 and 6: Al alloy (kn, kt unused under HertzMindlin)
const Material oxideHertz{5e-3, 4000.0, 0.0, -1.0, 0.98, 0.092, 3.8e11, 0.23};
const Material alloyHertz{0.2, 2700.0, 0.0, -1.0, 0.5, 0.4, 7e10, 0.33};
constexpr double speed4 = 3.9, vnAlloy = 5.0;

double test4Quantity(int dimension, const std::string& quantity, double theta)
{
    const Rebound r = angledImpact(dimension, oxideHertz, speed4, theta, 200.0);
    const double vt = speed4 * std::sin(theta * pi / 180.0);
    if (quantity == "et") return r.vt / vt;
    if (quantity == "omega") return -r.wa;
    return std::atan((r.vt - 0.5 * oxideHertz.d * r.wa) / r.vn) * 180.0 / pi;
}

} // namespace

TEST(ChungOoiHertz, Test4ObliqueImpactsWithinTenPercentAtEveryAngle)
{
    // The suite's error sum|DEM - ref|/sum|ref| < 10 % against the Al-oxide curves (Kratos
    // Chung_Ooi_class.py), each quantity over all angles; Kharaz et al.'s (2001) points
    // printed beside (dt = t_c/200)
    DEM_REFERENCE_OR_SKIP(table, "kratos_co_test4.csv");
    for (int dimension : {2, 3}) {
        for (const std::string q : {"et", "omega", "rebound"}) {
            for (const std::string source : {"oxide", "experiment"}) {
                std::vector<double> dem, ref;
                std::printf("  test 4 %-4s Hertz %-7s against %-10s (angle:DEM/ref):",
                            engineName(dimension), q.c_str(), source.c_str());
                for (const auto& row : table.where("quantity", q)) {
                    if (row.at("source") != source) continue;
                    const double angle = number(row, "angle");
                    dem.push_back(test4Quantity(dimension, q, angle));
                    ref.push_back(number(row, "value"));
                    std::printf(" %.0f:%.3g/%.3g", angle, dem.back(), ref.back());
                }
                const double error = summedRelativeError(dem, ref);
                std::printf("  error %.2f %%\n", 100.0 * error);
                if (source == "oxide") {
                    EXPECT_LT(error, 0.10) << engineName(dimension) << " " << q;
                }
            }
        }
    }
}

TEST(ChungOoiHertz, Test5SlidingImpactsMatchTheCoulombImpulse)
{
    // vt/vn 3 to 20 (above the sliding limit 3.5 mu (1 + e) = 2.1): vn' = e vn within 0.5 %,
    // J_t = mu J_n within 1 %, omega' R = 2.5 (vt - vt') within 1e-9 (dt = t_c/500)
    const double R = 0.5 * alloyHertz.d;
    for (int dimension : {2, 3}) {
        for (double ratio : {3.0, 5.0, 10.0, 20.0}) {
            const double vt = ratio * vnAlloy;
            const Rebound r = wallImpact(dimension, alloyHertz, vt, vnAlloy, 0.0, 500.0);
            const std::string what = std::string(engineName(dimension)) + " vt/vn " + std::to_string(ratio);
            EXPECT_NEAR(r.vn, alloyHertz.e * vnAlloy, 0.005 * alloyHertz.e * vnAlloy) << what;
            EXPECT_NEAR(r.wa * R, 2.5 * (vt - r.vt), 1e-9 * vt) << what;
            const double impulseRatio = (vt - r.vt) / (alloyHertz.mu * (r.vn + vnAlloy));
            EXPECT_NEAR(impulseRatio, 1.0, 0.01) << what;
        }
    }
}

TEST(ChungOoiHertz, Test6SpinningImpactsAgainstTheReferenceWhereTheContactSlides)
{
    // Graph 1: beta = -vtc'/vtc against chi = 3.5 mu (1 + e) vn/vtc; graph 2: vtc'/vn'
    // against vtc/vn; the suite's 10 % where the contact slides throughout (chi <= 1),
    // printed everywhere: where it sticks the rebound depends on the tangential history
    // model, which the paper's curves do not state (this law departs there by up to 0.30
    // in beta, at chi = 24: -0.04 against -0.34; the verification README's findings)
    DEM_REFERENCE_OR_SKIP(table, "kratos_co_test6.csv");
    const double slide = 3.5 * alloyHertz.mu * (1.0 + alloyHertz.e);
    const double R = 0.5 * alloyHertz.d;
    for (int dimension : {2, 3}) {
        for (const std::string graph : {"1", "2"}) {
            std::vector<double> dem, ref;
            std::printf("  test 6 %-4s Hertz graph %s (x: DEM/ref):", engineName(dimension), graph.c_str());
            for (const auto& row : table.where("graph", graph)) {
                const double x = number(row, "x");
                const double vtc = graph == "1" ? slide * vnAlloy / x : x * vnAlloy;
                const Rebound r = wallImpact(dimension, alloyHertz, 0.0, vnAlloy, -vtc / R, 500.0);
                const double vtcAfter = r.vt - R * r.wa;
                const double y = graph == "1" ? -vtcAfter / vtc : vtcAfter / r.vn;
                std::printf(" %.3g:%.3g/%.3g", x, y, number(row, "y"));
                if (vtc >= slide * vnAlloy) {
                    dem.push_back(y);
                    ref.push_back(number(row, "y"));
                }
            }
            const double error = summedRelativeError(dem, ref);
            std::printf("  sliding points %zu, error %.2f %%\n", dem.size(), 100.0 * error);
            ASSERT_GE(dem.size(), 4u);
            EXPECT_LT(error, 0.10) << engineName(dimension) << " graph " << graph;
        }
    }
}
