// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// MFIX's DEM verification case DEM05: oblique impacts of a sphere on a wall at 3.9 m/s and
// incidence angles 0-65 degrees from the normal, with MFIX's linear spring-dashpot set-up
// (tests/dem/DEM05/mfix.dat: d = 5 mm, rho = 4000 kg/m^3, kn = 1.72e7 N/m, kt = 1.48/1.72 kn,
// e = 1, mu = 0.092), read as MFIX does (usr3_des.f): rebound angle atan(vt'/vn') of the
// centre, |omega'| and the tangential restitution vt'/vt. References: mfix_dem05.csv of the
// reference folder, MFIX's LSD column (particle-wall) and the experiment of Kharaz, Gorham &
// Salman (2001, Powder Technol. 120:281) as digitised by Di Renzo & Di Maio (2004).

#include "verification/ObliqueImpact.hpp"

#include <algorithm>

using namespace dem;
using namespace dem::verification;

namespace {

const Material mfixLsd{5e-3, 4000.0, 1.72e7, 1.48e7, 1.0, 0.092};
constexpr double speed = 3.9;   // m/s, Kharaz et al.'s

struct Measures {
    double alpha, omega, coeff;   // degrees, rad/s, 1
};

Measures measure(int dimension, double thetaDeg)
{
    const double th = thetaDeg * pi / 180.0;
    const Rebound r = angledImpact(dimension, mfixLsd, speed, thetaDeg, 100.0);
    const double vt0 = speed * std::sin(th);
    return {std::atan2(std::abs(r.vt), r.vn) * 180.0 / pi, std::abs(r.wa),
            vt0 > 0.0 ? r.vt / vt0 : 0.0};
}

double pick(const Measures& m, const std::string& quantity)
{
    return quantity == "ALPHA" ? m.alpha : quantity == "OMEGA" ? m.omega : m.coeff;
}

} // namespace

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
