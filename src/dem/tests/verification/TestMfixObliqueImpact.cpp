// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// MFIX's DEM verification case DEM05: oblique impacts of a sphere on a wall at 3.9 m/s and
// incidence angles 0-65 degrees from the normal, with MFIX's linear spring-dashpot set-up
// (tests/dem/DEM05/mfix.dat: d = 5 mm, rho = 4000 kg/m^3, kn = 1.72e7 N/m, kt = 1.48/1.72 kn,
// e = 1, mu = 0.092), read as MFIX does (usr3_des.f): rebound angle atan(vt'/vn') of the
// centre, |omega'| and the tangential restitution vt'/vt. References: mfix_dem05.csv of the
// reference folder, MFIX's LSD column (particle-wall) and the experiment of Kharaz, Gorham &
// Salman (2001, Powder Technol. 120:281) as digitised by Di Renzo & Di Maio (2004). And the
// same impacts with the HertzMindlin law and MFIX's Hertzian inputs (tests/dem/DEM05/
// runtests.sh: alumina E = 380 GPa, nu = 0.23 on an aluminium wall E = 70 GPa, nu = 0.25,
// e = 1, no tangential damping) against MFIX's Hertz column and the law's grazing limit.

#include "verification/ObliqueImpact.hpp"

#include <algorithm>
#include <array>
#include <cmath>

using namespace dem;
using namespace dem::verification;

namespace {

const Material mfixLsd{5e-3, 4000.0, 1.72e7, 1.48e7, 1.0, 0.092};
const Material mfixHertz{5e-3, 4000.0, 0.0, -1.0, 1.0, 0.092, 380e9, 0.23, 70e9, 0.25};
constexpr double speed = 3.9;   // m/s, Kharaz et al.'s

struct Measures {
    double alpha, omega, coeff;   // degrees, rad/s, 1
};

Measures measure(int dimension, double thetaDeg, const Material& mat = mfixLsd)
{
    const double th = thetaDeg * pi / 180.0;
    const Rebound r = angledImpact(dimension, mat, speed, thetaDeg, 100.0);
    const double vt0 = speed * std::sin(th);
    return {std::atan2(std::abs(r.vt), r.vn) * 180.0 / pi, std::abs(r.wa),
            vt0 > 0.0 ? r.vt / vt0 : 0.0};
}

double pick(const Measures& m, const std::string& quantity)
{
    return quantity == "ALPHA" ? m.alpha : quantity == "OMEGA" ? m.omega : m.coeff;
}

/// The Hertz law's grazing limit theta -> 0: the contact point sticks through the contact,
/// its tangential displacement xi an oscillator of mass m_t = 2/7 m whose stiffness
/// Kt sqrt(delta) follows Hertz's normal impact m delta'' = -Kn delta^3/2. In the units
/// delta* = (m vn^2/Kn)^2/5, delta*/vn: x'' = -x^3/2 from x = 0, x' = 1, and xi'' =
/// -lambda sqrt(x) xi from xi = 0, xi' = 1 with lambda = 3.5 Kt/Kn = 21 G*/E* whatever vn.
/// Returns xi' when x is back at 0: the contact point's velocity turned by this factor,
/// c (vt'/vt = 1 - 2/7 (1 - c), omega' R/vt = 5/7 (1 - c)). Integrated here by RK4 at
/// 1e-5 of the contact (its error below 1e-9).
double hertzStickingTurn(double lambda)
{
    auto rates = [&](const std::array<double, 4>& y) {   // x, x', xi, xi'
        const double x = std::max(y[0], 0.0);
        return std::array<double, 4>{y[1], -x * std::sqrt(x), y[3], -lambda * std::sqrt(x) * y[2]};
    };
    std::array<double, 4> y{0.0, 1.0, 0.0, 1.0};
    const double h = 3.2e-5;   // the contact lasts 3.218 in these units
    for (int step = 0; step < 10000000; ++step) {
        auto shifted = [&](const std::array<double, 4>& k, double f) {
            std::array<double, 4> z;
            for (int i = 0; i < 4; ++i) z[i] = y[i] + f * h * k[i];
            return z;
        };
        const auto k1 = rates(y);
        const auto k2 = rates(shifted(k1, 0.5));
        const auto k3 = rates(shifted(k2, 0.5));
        const auto k4 = rates(shifted(k3, 1.0));
        std::array<double, 4> next;
        for (int i = 0; i < 4; ++i) next[i] = y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
        if (step > 0 && next[0] <= 0.0) {   // back at zero overlap within this step
            const double f = y[0] / (y[0] - next[0]);
            return y[3] + f * (next[3] - y[3]);
        }
        y = next;
    }
    return NAN;
}

/// Hertz's and Mindlin's effective moduli of mfixHertz on its wall, Pa.
double mfixHertzEStar() { return wallEffectiveModulus(mfixHertz); }
double mfixHertzGStar()
{
    const double g = mfixHertz.youngs / (2.0 * (1.0 + mfixHertz.poisson));
    const double gWall = mfixHertz.wallYoungs / (2.0 * (1.0 + mfixHertz.wallPoisson));
    return 1.0 / ((2.0 - mfixHertz.poisson) / g + (2.0 - mfixHertz.wallPoisson) / gWall);
}

} // namespace

TEST(MfixDem05, HertzGrazingLimitMatchesTheStickingOscillator)
{
    // Reference: the Hertz law's own limit theta -> 0 (hertzStickingTurn, integrated here,
    // not by the library), at theta = 0.05 deg and dt = t_c/1000: the contact point's
    // velocity u' = vt' - omega' R over vt within 1e-4 of c (the step's error is first
    // order: 3e-6 here), vn' within 1e-3 of vn.
    const double lambda = 21.0 * mfixHertzGStar() / mfixHertzEStar();
    const double c = hertzStickingTurn(lambda);
    const double theta = 0.05 * pi / 180.0;
    const double vt = speed * std::sin(theta);
    const double r = 0.5 * mfixHertz.d;
    for (int dimension : {2, 3}) {
        const Rebound b = angledImpact(dimension, mfixHertz, speed, 0.05, 1000.0);
        const double turn = (b.vt - b.wa * r) / vt;
        EXPECT_NEAR(turn, c, 1e-4) << engineName(dimension);
        EXPECT_NEAR(b.vn, speed * std::cos(theta), 1e-3 * speed) << engineName(dimension);
        std::printf("  DEM05 %-4s Hertz grazing limit: u'/vt %.7f (oscillator %.7f, lambda "
                    "%.4f), vt'/vt %.5f, omega R/vt %.5f\n", engineName(dimension), turn, c,
                    lambda, b.vt / vt, b.wa * r / vt);
    }
}

TEST(MfixDem05, GrazingLimitMatchesTheStickingOscillator)
{
    // Reference: the law's own analytic limit theta -> 0, where the contact point sticks
    // through the contact (the Coulomb limit is reached only in a vanishing interval at its
    // end): the contact point's tangential motion is an undamped oscillator of mass
    // m_t = 2/7 m and stiffness kt, so over tc = pi sqrt(m/kn) its velocity turns by
    // cos(w_t tc), w_t tc = pi sqrt(3.5 kt/kn), and vt'/vt = 1 - 2/7 (1 - cos(w_t tc)),
    // omega' R/vt = 5/7 (1 - cos(w_t tc)) (Schaefer, Dippel & Wolf 1996, J. Phys. I France
    // 6:5). At theta = 0.05 deg and dt = tc/1000, within 0.5 % and 1 % (the step's error is
    // first order: 0.6 % and 4 % at tc/100).
    const double c = std::cos(pi * std::sqrt(3.5 * mfixLsd.kt / mfixLsd.kn));
    const double theta = 0.05 * pi / 180.0;
    const double vt = speed * std::sin(theta);
    for (int dimension : {2, 3}) {
        const Rebound r = angledImpact(dimension, mfixLsd, speed, 0.05, 1000.0);
        EXPECT_NEAR(r.vt / vt, 1.0 - 2.0 / 7.0 * (1.0 - c), 0.005 * (1.0 - 2.0 / 7.0 * (1.0 - c)))
            << engineName(dimension);
        EXPECT_NEAR(r.wa * 0.5 * mfixLsd.d / vt, 5.0 / 7.0 * (1.0 - c), 0.01 * 5.0 / 7.0 * (1.0 - c))
            << engineName(dimension);
        EXPECT_NEAR(r.vn, speed * std::cos(theta), 1e-3 * speed) << engineName(dimension);
        std::printf("  DEM05 %-4s grazing limit: vt'/vt %.5f (analytic %.5f), omega R/vt %.5f "
                    "(analytic %.5f)\n", engineName(dimension), r.vt / vt,
                    1.0 - 2.0 / 7.0 * (1.0 - c), r.wa * 0.5 * mfixLsd.d / vt, 5.0 / 7.0 * (1.0 - c));
    }
}

TEST(MfixDem05, ObliqueImpactsMatchMfixLinearSpringDashpot)
{
    // Reference: MFIX's LSD results (the same law and parameters; its step tc/50 with
    // Adams-Bashforth). Tolerance 2 % of each value, at dt = tc/100, at the angles from
    // 7.5 degrees up. Below, MFIX's values leave the law's own limit (its vt'/vt levels at
    // 0.879 below 1 degree where the sticking oscillator gives 0.907, checked above): they
    // are printed, not checked. In 2D on the floor and in the slab on a wall whose normal is
    // along no axis.
    DEM_REFERENCE_OR_SKIP(table, "mfix_dem05.csv");
    const auto rows = table.where("source", "mfix_lsd");
    ASSERT_FALSE(rows.empty());
    for (int dimension : {2, 3}) {
        double worst = 0.0;
        std::string worstAt;
        for (const auto& r : rows) {
            const double angle = number(r, "angle");
            const double ref = number(r, "partwall");
            const std::string q = r.at("quantity");
            const double got = pick(measure(dimension, angle), q);
            const std::string what = std::string(engineName(dimension)) + " " + q + " at "
                                     + std::to_string(angle) + " deg";
            if (angle < 7.5) {
                if (dimension == 2 && angle > 0.0) {
                    std::printf("  DEM05 %-4s %-5s %4.1f deg: DEM %9.4f, MFIX LSD %9.4f "
                                "(below 7.5 deg: printed only)\n", engineName(dimension),
                                q.c_str(), angle, got, ref);
                }
                continue;
            }
            EXPECT_NEAR(got, ref, 0.02 * std::abs(ref)) << what;
            if (std::abs(got / ref - 1.0) > worst) {
                worst = std::abs(got / ref - 1.0);
                worstAt = what;
            }
        }
        std::printf("  DEM05 %-4s against MFIX LSD from 7.5 deg: largest error %.3g %% (%s)\n",
                    engineName(dimension), 100.0 * worst, worstAt.c_str());
    }
}

TEST(MfixDem05, ObliqueImpactsAgainstKharazExperiment)
{
    // Reference: Kharaz et al.'s points. Printed at every angle; checked where the law
    // represents the physics, the sliding impacts (incidence above the limit
    // tan(theta) = 3.5 mu (1 + e), 32.8 degrees here, where the rigid-body impulse result
    // holds): each point within 10 % (the measure Chung & Ooi's suite uses, per point here).
    // Below it the rebound is set by the tangential spring's oscillation, which a linear
    // spring and a sphere's elastic tangential compliance give differently: printed only.
    DEM_REFERENCE_OR_SKIP(table, "mfix_dem05.csv");
    const auto rows = table.where("source", "experiment");
    ASSERT_FALSE(rows.empty());
    const double slidingLimit = std::atan(3.5 * mfixLsd.mu * (1.0 + mfixLsd.e)) * 180.0 / pi;
    for (int dimension : {2, 3}) {
        std::printf("  DEM05 %-4s against Kharaz et al. (2001):\n", engineName(dimension));
        for (const auto& r : rows) {
            const double angle = number(r, "angle");
            const double ref = number(r, "partwall");
            const std::string q = r.at("quantity");
            const double got = pick(measure(dimension, angle), q);
            const double error = std::abs(got - ref) / std::abs(ref);
            std::printf("    %-5s %7.3f deg: DEM %9.4f, experiment %9.4f, error %6.2f %%%s\n",
                        q.c_str(), angle, got, ref, 100.0 * error,
                        angle > slidingLimit ? "" : " (sticking range, printed only)");
            if (angle > slidingLimit) {
                EXPECT_LT(error, 0.10) << engineName(dimension) << " " << q << " at " << angle << " deg";
            }
        }
    }
}

TEST(MfixDem05, ObliqueImpactsMatchMfixHertz)
{
    // Reference: MFIX's Hertzian results (`mfix_hertz`, particle-wall), the law the library's
    // HertzMindlin is: MFIX's Hertz wall contact (CHECK_SOLIDS_DEM_COLL_HERTZ) takes Hertz's
    // 4/3 E* sqrt(R) delta^3/2 and Mindlin's tangential stiffness 8 G* sqrt(R delta) on the
    // accumulated displacement, 1/E* = (1 - nu^2)/E + (1 - nu_w^2)/E_w and 1/G* = (2 - nu)/G
    // + (2 - nu_w)/G_w as the library, Coulomb's limit, no damping at e = e_t = 1. Tolerance
    // 2 % of each value, as the LSD columns', at dt = t_c/100 (MFIX: t_c/50,
    // Adams-Bashforth), from 10 degrees up. Below, MFIX's values leave the law's own limit:
    // at 0.5-2.5 degrees its vt'/vt of 0.997 means u'/vt = 0.990 where the sticking
    // oscillator gives 1.0022 (checked above), its spin 4 times the law's; the same departure
    // is 14 % and 2.9 % of the spin at 5 and 7.5 degrees. Printed, not checked.
    DEM_REFERENCE_OR_SKIP(table, "mfix_dem05.csv");
    const auto rows = table.where("source", "mfix_hertz");
    ASSERT_FALSE(rows.empty());
    for (int dimension : {2, 3}) {
        double worst = 0.0;
        std::string worstAt;
        int checked = 0;
        for (const auto& r : rows) {
            const double angle = number(r, "angle");
            const double ref = number(r, "partwall");
            const std::string q = r.at("quantity");
            if (angle <= 0.0) continue;
            const double got = pick(measure(dimension, angle, mfixHertz), q);
            const std::string what = std::string(engineName(dimension)) + " " + q + " at "
                                     + std::to_string(angle) + " deg";
            if (angle < 10.0) {
                if (dimension == 2) {
                    std::printf("  DEM05 %-4s %-5s %4.1f deg: DEM %9.4f, MFIX Hertz %9.4f "
                                "(below 10 deg: printed only)\n", engineName(dimension),
                                q.c_str(), angle, got, ref);
                }
                continue;
            }
            EXPECT_NEAR(got, ref, 0.02 * std::abs(ref)) << what;
            ++checked;
            if (std::abs(got / ref - 1.0) > worst) {
                worst = std::abs(got / ref - 1.0);
                worstAt = what;
            }
        }
        EXPECT_EQ(checked, 69) << engineName(dimension);   // 23 angles from 10 deg, 3 quantities
        std::printf("  DEM05 %-4s against MFIX Hertz from 10 deg: largest error %.3g %% (%s)\n",
                    engineName(dimension), 100.0 * worst, worstAt.c_str());
    }
}
