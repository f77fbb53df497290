// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Chung & Ooi (2011, Granular Matter 13:643) tests 4-8: oblique impacts on a wall and of pairs.
// Test 4: constant speed 3.9 m/s at incidence angles 5-85 degrees from the normal (Al oxide,
// R = 2.5 mm, rho = 4000 kg/m^3, e = 0.98, mu = 0.092; Kratos DEM3D_chung_ooi_tests/test4_data):
// tangential restitution vt'/vt of the centre, final spin, and the contact point's rebound
// angle atan((vt' - R omega')/vn'), against the paper's Al-oxide curves (the reference Kratos
// checks with the error sum|DEM - ref|/sum|ref| < 10 %, Chung_Ooi_class.py) and Kharaz et
// al.'s (2001) experiment (printed). Test 5: constant normal speed, tangential speeds
// varying; test 6: constant normal speed, spins varying (Al alloy, R = 0.1 m, rho = 2700,
// e = 0.5, mu = 0.4; Kratos basic_benchmarks/benchmark6DEM.mdpa); tests 7 and 8: pairs of
// equal and unequal spheres with spin (the same alloy). Where the contact slides
// throughout, the rigid-body impulse result is analytic (Maw, Barber & Fawcett 1976): the
// contact point's tangential velocity changes by 3.5 mu (1 + e) vn. Reference tables
// kratos_co_test4.csv, kratos_co_test6.csv of the reference folder.
// The linear law's tangential stiffness is the library's default kt = 2/7 kn, or Mindlin's
// ratio kt/kn = 2 (1 - nu)/(2 - nu) of the material (nu = 0.23: 0.870), settable as kt.

#include "verification/ObliqueImpact.hpp"

#include <algorithm>

using namespace dem;
using namespace dem::verification;

namespace {

constexpr double nuOxide = 0.23;
const Material oxide{5e-3, 4000.0, 1e6, -1.0, 0.98, 0.092};
constexpr double speed4 = 3.9;

Material withMindlinRatio(Material m, double nu)
{
    m.kt = 2.0 * (1.0 - nu) / (2.0 - nu) * m.kn;
    return m;
}

/// Test 4's three quantities at incidence angle theta (degrees), Kratos's signs: the spin
/// negative in the rolling sense, the rebound angle negative when the contact point's
/// tangential velocity has turned.
double test4Quantity(int dimension, const Material& mat, const std::string& quantity, double theta)
{
    const Rebound r = angledImpact(dimension, mat, speed4, theta, 200.0);
    const double vt = speed4 * std::sin(theta * pi / 180.0);
    if (quantity == "et") return r.vt / vt;
    if (quantity == "omega") return -r.wa;
    return std::atan((r.vt - 0.5 * mat.d * r.wa) / r.vn) * 180.0 / pi;
}

struct Comparison {
    double error;                 // sum |DEM - ref| / sum |ref|
    std::vector<double> angles, dem, ref;
};

Comparison compare(const Table& table, int dimension, const Material& mat,
                   const std::string& quantity, const std::string& source, double minAngle,
                   double maxAngle)
{
    Comparison c;
    for (const auto& r : table.where("quantity", quantity)) {
        const double angle = number(r, "angle");
        if (r.at("source") != source || angle < minAngle || angle > maxAngle) continue;
        c.angles.push_back(angle);
        c.ref.push_back(number(r, "value"));
        c.dem.push_back(test4Quantity(dimension, mat, quantity, angle));
    }
    c.error = summedRelativeError(c.dem, c.ref);
    return c;
}

void print(const char* label, const std::string& quantity, const std::string& source,
           const Comparison& c)
{
    std::printf("  test 4 %s %-7s against %-10s error %6.2f %%:", label, quantity.c_str(),
                source.c_str(), 100.0 * c.error);
    for (std::size_t k = 0; k < c.angles.size(); ++k) {
        std::printf(" %.0f:%.3g/%.3g", c.angles[k], c.dem[k], c.ref[k]);
    }
    std::printf("  (angle:DEM/ref)\n");
}

} // namespace

TEST(ChungOoiTest4, MindlinStiffnessRatioWithinTenPercentAtEveryAngle)
{
    // Tolerance: the suite's error measure below 10 % against the Al-oxide curves, for each
    // quantity over all angles (dt = tc/200). Kharaz et al.'s points printed beside.
    DEM_REFERENCE_OR_SKIP(table, "kratos_co_test4.csv");
    const Material mat = withMindlinRatio(oxide, nuOxide);
    for (int dimension : {2, 3}) {
        const std::string label = std::string(engineName(dimension)) + " kt Mindlin";
        for (const std::string q : {"et", "omega", "rebound"}) {
            const Comparison c = compare(table, dimension, mat, q, "oxide", 0.0, 90.0);
            print(label.c_str(), q, "oxide", c);
            print(label.c_str(), q, "experiment", compare(table, dimension, mat, q, "experiment", 0.0, 90.0));
            EXPECT_LT(c.error, 0.10) << label << " " << q;
        }
    }
}

TEST(ChungOoiTest4, DefaultStiffnessRatioWithinTenPercentWhereTheContactSlides)
{
    // kt = 2/7 kn, at the angles above the sliding limit tan(theta) = 3.5 mu (1 + e)
    // (32.6 degrees), where the rigid-body impulse result holds: the suite's 10 %.
    DEM_REFERENCE_OR_SKIP(table, "kratos_co_test4.csv");
    const double limit = std::atan(3.5 * oxide.mu * (1.0 + oxide.e)) * 180.0 / pi;
    for (int dimension : {2, 3}) {
        const std::string label = std::string(engineName(dimension)) + " kt 2/7 kn";
        for (const std::string q : {"et", "omega", "rebound"}) {
            const Comparison c = compare(table, dimension, oxide, q, "oxide", limit, 90.0);
            print(label.c_str(), q, "oxide", c);
            EXPECT_LT(c.error, 0.10) << label << " " << q;
        }
    }
}

TEST(ChungOoiTest4, DefaultStiffnessRatioDepartsFromTheCurvesAtSmallAngles)
{
    // A finding, pinned as the expected outcome: with kt = 2/7 kn the tangential oscillation
    // (stiffness 2/7 kn, the contact point's mass 2/7 m) lasts as long as the normal one, so
    // at small incidence the contact point's velocity turns fully, towards the sticking
    // oscillator's vt'/vt = 1 - 2/7 (1 - cos(pi sqrt(3.5 kt/kn))) = 3/7 as theta -> 0
    // (DEM05's grazing limit), where the Al-oxide curve (Hertz-Mindlin's kt/kn) has ~0.95:
    // the suite's measure over all angles exceeds its 10 % for every quantity (the Mindlin
    // ratio above passes it). Checked: vt'/vt at 5 degrees within 10 % of 3/7 (the impact
    // is not yet grazing there) and every measure above 10 %.
    DEM_REFERENCE_OR_SKIP(table, "kratos_co_test4.csv");
    for (int dimension : {2, 3}) {
        const std::string label = std::string(engineName(dimension)) + " kt 2/7 kn";
        for (const std::string q : {"et", "omega", "rebound"}) {
            const Comparison c = compare(table, dimension, oxide, q, "oxide", 0.0, 90.0);
            print(label.c_str(), q, "oxide", c);
            print(label.c_str(), q, "experiment", compare(table, dimension, oxide, q, "experiment", 0.0, 90.0));
            EXPECT_GT(c.error, 0.10) << label << " " << q << ": the finding no longer holds";
        }
        const double grazing = 1.0 - 2.0 / 7.0 * (1.0 - std::cos(pi));
        const double at5 = test4Quantity(dimension, oxide, "et", 5.0);
        EXPECT_NEAR(at5, grazing, 0.1 * grazing) << label;
    }
}

namespace {

// Tests 5 and 6: Al alloy.
const Material alloy{0.2, 2700.0, 1e7, -1.0, 0.5, 0.4};
constexpr double vnAlloy = 5.0;   // m/s; the law's normalised results do not depend on it

} // namespace

TEST(ChungOoiTest5, SlidingImpactsMatchTheCoulombImpulse)
{
    // vt/vn from 3 to 20, all above the sliding limit 3.5 mu (1 + e) = 2.1: vn' = e vn within
    // 0.5 %, and the tangential impulse mu times the normal one within 1 %, so
    // vt' = vt - mu (1 + e) vn and omega' R = 2.5 mu (1 + e) vn, at dt = tc/500. The limit
    // mu F_n takes the compressive force (the normal force is clamped at zero).
    const double R = 0.5 * alloy.d;
    for (int dimension : {2, 3}) {
        for (double ratio : {3.0, 5.0, 10.0, 20.0}) {
            const double vt = ratio * vnAlloy;
            const Rebound r = wallImpact(dimension, alloy, vt, vnAlloy, 0.0, 500.0);
            const std::string what = std::string(engineName(dimension)) + " vt/vn " + std::to_string(ratio);
            EXPECT_NEAR(r.vn, alloy.e * vnAlloy, 0.005 * alloy.e * vnAlloy) << what;
            EXPECT_LT(r.outOfPlane, 1e-9) << what;
            // Angular momentum about the contact point: omega' R = 2.5 (vt - vt'), any regime.
            EXPECT_NEAR(r.wa * R, 2.5 * (vt - r.vt), 1e-9 * vt) << what;
            const double impulseRatio = (vt - r.vt) / (alloy.mu * (r.vn + vnAlloy));
            std::printf("  test 5 %-4s vt/vn %4.1f: vn'/vn %.4f, J_t/(mu J_n) %.4f\n",
                        engineName(dimension), ratio, r.vn / vnAlloy, impulseRatio);
            EXPECT_NEAR(impulseRatio, 1.0, 0.01) << what;
        }
    }
}

namespace {

/// Test 6: no centre velocity along t, the contact point moving at vtc (spin -vtc/R about a).
Rebound spinningImpact(int dimension, double vtc)
{
    return wallImpact(dimension, alloy, 0.0, vnAlloy, -vtc / (0.5 * alloy.d), 500.0);
}

double contactPointVelocity(const Rebound& r) { return r.vt - 0.5 * alloy.d * r.wa; }

} // namespace

TEST(ChungOoiTest6, SpinningImpactsAgainstTheReferenceWhereTheContactSlides)
{
    // Graph 1: beta = -vtc'/vtc against chi = 3.5 mu (1 + e) vn/vtc; graph 2: vtc'/vn'
    // against vtc/vn (the contact point's tangential velocity). Checked with the suite's
    // 10 % where the contact slides throughout (chi <= 1, vtc/vn >= 3.5 mu (1 + e)), printed
    // everywhere: below, the rebound is set by the tangential compliance (Hertz-Mindlin's in
    // the reference; kt = 2/7 kn departs there by up to 0.48 in beta, at chi = 24: the
    // verification README's findings).
    DEM_REFERENCE_OR_SKIP(table, "kratos_co_test6.csv");
    const double slide = 3.5 * alloy.mu * (1.0 + alloy.e);
    for (int dimension : {2, 3}) {
        for (const std::string graph : {"1", "2"}) {
            std::vector<double> dem, ref;
            std::printf("  test 6 %-4s graph %s (x: DEM/ref):", engineName(dimension), graph.c_str());
            for (const auto& row : table.where("graph", graph)) {
                const double x = number(row, "x");
                const double vtc = graph == "1" ? slide * vnAlloy / x : x * vnAlloy;
                const Rebound r = spinningImpact(dimension, vtc);
                const double y = graph == "1" ? -contactPointVelocity(r) / vtc : contactPointVelocity(r) / r.vn;
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

namespace {

struct PairRebound {
    double vn;           // separation speed along the line of centres, m/s
    double vc;           // relative tangential velocity of the contact points, m/s
    double dw1, dw2;     // spin changes of the two spheres about z, rad/s
    double momentum;     // tangential momentum after, over m1 vn (zero before)
};

/// Tests 7 and 8: spheres of diameters d1, d2 (Al alloy) approach along x at relative speed
/// vn, both spinning at w0 about z, so that their contact points slide past each other at
/// vc = w0 (R1 + R2) along y.
/// With `hertz` the HertzMindlin law of the Al alloy (E = 7e10 Pa, nu = 0.33, Chung & Ooi's
/// Table 1), else the linear law.
PairRebound spinningPair(int dimension, double d1, double d2, double vc, bool hertz = false)
{
    const double m1 = sphereMass(d1, alloy.rho), m2 = sphereMass(d2, alloy.rho);
    const double size = 20.0 * std::max(d1, d2);
    Settings s = oneClass(d1, alloy.rho, {-size, size, -size, size}, dimension, 3.0 * std::max(d1, d2), 1.0);
    s.classes.push_back({"partner", d2, alloy.rho});
    // A stiffer spring than the wall's: the line of centres turns during the contact by
    // ~(relative tangential speed x tc)/(R1 + R2), which the impulse result neglects
    // (2.5 % at 1e7 N/m, 0.25 % here; the alloy's Hertz contact is shorter still).
    const double kn = 100.0 * alloy.kn;
    const double mEff = m1 * m2 / (m1 + m2);
    if (hertz) {
        constexpr double youngs = 7e10, poisson = 0.33;
        setHertzMindlin(s, youngs, poisson);
        const double eStar = youngs / (2.0 * (1.0 - poisson * poisson));
        const double rEff = 0.25 * d1 * d2 / (0.5 * d1 + 0.5 * d2);
        s.dt = hertzImpactDuration(mEff, rEff, eStar, vnAlloy) / 500.0;
    } else {
        s.dt = contactTime(mEff, kn, alloy.e) / 500.0;
    }
    s.contact.kn = kn;
    s.contact.restitution = alloy.e;
    s.contact.frictionParticle = alloy.mu;
    Simulation sim(s);
    const double r1 = 0.5 * d1, r2 = 0.5 * d2, gap = 10.0 * vnAlloy * s.dt + 1e-9;
    const double w0 = vc / (r1 + r2), z = 1.5 * std::max(d1, d2);
    const double u1 = m2 / (m1 + m2) * vnAlloy, u2 = -m1 / (m1 + m2) * vnAlloy;   // no net momentum
    place(sim, 0, {-r1 - 0.5 * gap, 0.0, z}, {u1, 0.0, 0.0}, {0.0, 0.0, w0});
    place(sim, 1, {r2 + 0.5 * gap, 0.0, z}, {u2, 0.0, 0.0}, {0.0, 0.0, w0});
    auto overlap = [&]() { return r1 + r2 - (position(sim, 1) - position(sim, 0)).norm(); };
    bool touched = false;
    for (int k = 0; k < 1000000; ++k) {
        sim.advance(s.dt);
        touched = touched || overlap() > 0.0;
        if (touched && overlap() <= 0.0) break;
    }
    // Read along the line of centres at separation and its normal in the x-y plane.
    const Vec3 n = (position(sim, 1) - position(sim, 0)).normalized();
    const Vec3 t = Vec3(0.0, 0.0, 1.0).cross(n);
    const Vec3 v1 = velocity(sim, 0), v2 = velocity(sim, 1);
    const double w1 = spin(sim, 0).z(), w2 = spin(sim, 1).z();
    return {(v2 - v1).dot(n), (v1 - v2).dot(t) + w1 * r1 + w2 * r2, w1 - w0, w2 - w0,
            (m1 * v1 + m2 * v2).dot(t) / (m1 * vnAlloy)};
}

} // namespace

namespace {

void checkSlidingSpinningPairs(bool hertz)
{
    // Equal spheres (test 7, d = 0.2 m) and unequal ones (test 8, d = 0.2 and 0.1 m), Al
    // alloy, relative normal speed 5 m/s, contact points sliding at vc = 3 and 10 vn (above
    // 3.5 mu (1 + e) vn = 2.1 vn: sliding throughout). Rigid-body impulse result for solid
    // spheres: a tangential impulse J = mu J_n, J_n = m_eff (1 + e) vn, changes vc by
    // 3.5 J/m_eff and each spin by 2.5 J/(m_i R_i) (the same sense for both). Checked:
    // e within 0.5 %, the spins' changes in the ratio m2 R2/(m1 R1) within 1e-6, tangential
    // momentum conserved, and J/(mu J_n) = 1 within 1 %.
    for (int dimension : {2, 3}) {
        for (const auto& [d1, d2] : {std::pair{0.2, 0.2}, std::pair{0.2, 0.1}}) {
            const double m1 = sphereMass(d1, alloy.rho), m2 = sphereMass(d2, alloy.rho);
            const double mEff = m1 * m2 / (m1 + m2);
            for (double ratio : {3.0, 10.0}) {
                const PairRebound r = spinningPair(dimension, d1, d2, ratio * vnAlloy, hertz);
                const std::string what = std::string(engineName(dimension)) + " d " + std::to_string(d1)
                                         + "/" + std::to_string(d2) + " vc/vn " + std::to_string(ratio);
                EXPECT_NEAR(r.vn, alloy.e * vnAlloy, 0.005 * alloy.e * vnAlloy) << what;
                EXPECT_NEAR(r.dw1 / r.dw2, (m2 * 0.5 * d2) / (m1 * 0.5 * d1), 1e-6) << what;
                EXPECT_NEAR(r.momentum, 0.0, 1e-9) << what;   // along t, zero before
                const double impulse = (ratio * vnAlloy - r.vc) * mEff / 3.5;
                const double impulseRatio = impulse / (alloy.mu * mEff * (r.vn + vnAlloy));
                std::printf("  tests 7/8 %-6s %-4s d %.1f/%.1f vc/vn %4.1f: e %.4f, J_t/(mu J_n) %.4f\n",
                            hertz ? "Hertz" : "linear", engineName(dimension), d1, d2, ratio,
                            r.vn / vnAlloy, impulseRatio);
                EXPECT_NEAR(impulseRatio, 1.0, 0.01) << what;
            }
        }
    }
}

} // namespace

TEST(ChungOoiTests7And8, SlidingSpinningPairsMatchTheCoulombImpulse)
{
    checkSlidingSpinningPairs(false);
}

// The same with the HertzMindlin law: the rigid-body impulse result holds for any normal law
// that gives the restitution e.
TEST(ChungOoiTests7And8, HertzMindlinSlidingSpinningPairsMatchTheCoulombImpulse)
{
    checkSlidingSpinningPairs(true);
}
