// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The shared pair-force kernel, checked by hand-computed values, and the tangential spring
// of a sliding contact: after the Coulomb cap the stored displacement is the one whose spring
// and dashpot together give the capped force (the convention of LAMMPS' granular pair
// styles), so that the spring holds no energy that the tangential force did not supply.

#include "dem/ContactKernel.hpp"

#include <gtest/gtest.h>

#include <cmath>

using dem::ContactLaw;
using dem::PairGeometry;

namespace {

ContactLaw law() { return ContactLaw{800.0, 800.0 * 2.0 / 7.0, 0.01, 0.01, 0.2}; }

PairGeometry geometry(double overlap, double vn, double vt, double xi)
{
    PairGeometry g;
    g.overlap = overlap;
    g.nHat = Eigen::Vector2d(1.0, 0.0);          // j to the right of i; tHat = (0, 1)
    g.vRel = Eigen::Vector2d(vn, vt);
    g.rI = 1e-3;
    g.rJ = 2e-3;
    g.xiT = xi;
    return g;
}

} // namespace

TEST(ContactKernel, NormalForceIsSpringPlusDashpotAlongMinusNormal)
{
    // F_n on i = -(kn delta + etaN vn) nHat (docs/theory/paper-model.md, "Particles"), by hand: 800*1e-5 + 0.01*0.1.
    const auto f = dem::contactForce(geometry(1e-5, 0.1, 0.0, 0.0), law(), 1e-5);
    EXPECT_DOUBLE_EQ(f.force.x(), -(800.0 * 1e-5 + 0.01 * 0.1));
    EXPECT_DOUBLE_EQ(f.force.y(), 0.0);
    EXPECT_DOUBLE_EQ(f.torqueI, 0.0);
}

TEST(ContactKernel, StickingAccumulatesHistoryAndTorquesBothPartners)
{
    // Trial tangential force -kt (xi + vt dt) - etaT vt, below mu |Fn|: no slip.
    const double kt = 800.0 * 2.0 / 7.0;
    const auto f = dem::contactForce(geometry(1e-4, 0.0, 1e-3, 2e-6), law(), 1e-5);
    const double xi = 2e-6 + 1e-3 * 1e-5;
    const double ft = -kt * xi - 0.01 * 1e-3;
    EXPECT_DOUBLE_EQ(f.xiT, xi);
    EXPECT_DOUBLE_EQ(f.force.y(), ft);
    // T = (r nHat) x Ft = r ft for both partners.
    EXPECT_DOUBLE_EQ(f.torqueI, 1e-3 * ft);
    EXPECT_DOUBLE_EQ(f.torqueJ, 2e-3 * ft);
}

TEST(ContactKernel, SlidingCapsAtCoulombAndResetsHistory)
{
    // |Ft| = mu |Fn|, sign opposing the trial force; stored displacement = -Ft/kt.
    const double kt = 800.0 * 2.0 / 7.0;
    const auto f = dem::contactForce(geometry(1e-5, 0.0, 0.0, 1e-4), law(), 1e-5);
    const double limit = 0.2 * 800.0 * 1e-5;
    EXPECT_DOUBLE_EQ(f.force.y(), -limit);
    EXPECT_DOUBLE_EQ(f.xiT, limit / kt);
}

namespace {

/// A fresh contact at rest in the normal direction that slides from its first step: the
/// dashpot alone carries 0.8 of the Coulomb limit at the tangential speed v, the spring's
/// increment of one step 0.3 of it. A spring set to carry the whole capped force would hold
/// limit^2/(2 kt), 5/3 of the work limit v dt that the force does in that step.
struct SlidingStart {
    static constexpr double overlap = 1e-5;   // m
    static constexpr double v = 0.1;          // m/s
    static constexpr double mu = 0.3;
    static constexpr double kn = 800.0;
    static constexpr double kt = kn * 2.0 / 7.0;
    static constexpr double limit = mu * kn * overlap;       // N
    static constexpr double etaT = 0.8 * limit / v;          // N s/m
    static constexpr double dt = 0.3 * limit / (kt * v);     // s
    static ContactLaw law() { return ContactLaw{kn, kt, 0.01, etaT, mu}; }
};

} // namespace

TEST(ContactKernel, SlidingSpringPlusDashpotGiveTheCappedForce)
{
    // 2D: -kt xi - eta_t v_t = F_t = -mu F_n after the step, and the spring's energy never
    // exceeds the work the tangential force has done, over 50 steps of steady sliding.
    using S = SlidingStart;
    double xi = 0.0, work = 0.0;
    for (int step = 0; step < 50; ++step) {
        const auto f = dem::contactForce(geometry(S::overlap, 0.0, S::v, xi), S::law(), S::dt);
        ASSERT_DOUBLE_EQ(f.ft, -S::limit) << "step " << step;
        EXPECT_NEAR(-S::kt * f.xiT - S::etaT * S::v, f.ft, 1e-12 * S::limit) << "step " << step;
        work += -f.ft * S::v * S::dt;
        EXPECT_LE(0.5 * S::kt * f.xiT * f.xiT, work) << "step " << step;
        xi = f.xiT;
    }
}

TEST(ContactKernel, SlidingSpringPlusDashpotGiveTheCappedForceIn3D)
{
    // The 3D kernel, the tangential velocity at an angle in the plane of an oblique normal
    using S = SlidingStart;
    dem::PairGeometry3 g;
    g.overlap = S::overlap;
    g.nHat = Eigen::Vector3d(1.0, 2.0, -2.0) / 3.0;
    const Eigen::Vector3d t1 = Eigen::Vector3d(2.0, -1.0, 0.0).normalized();
    const Eigen::Vector3d t2 = g.nHat.cross(t1);
    g.vRel = S::v * (0.6 * t1 + 0.8 * t2);
    g.rI = 1e-3;
    g.rJ = 0.0;
    g.xiT = Eigen::Vector3d::Zero();
    g.omegaRel = Eigen::Vector3d::Zero();
    double work = 0.0;
    for (int step = 0; step < 50; ++step) {
        const auto f = dem::contactForce<3>(g, S::law(), S::dt);
        ASSERT_NEAR(f.ft.norm(), S::limit, 1e-12 * S::limit) << "step " << step;
        const Eigen::Vector3d springAndDashpot = -S::kt * f.xiT - S::etaT * g.vRel;
        EXPECT_LT((springAndDashpot - f.ft).norm(), 1e-12 * S::limit) << "step " << step;
        work += -f.ft.dot(g.vRel) * S::dt;
        EXPECT_LE(0.5 * S::kt * f.xiT.squaredNorm(), work) << "step " << step;
        g.xiT = f.xiT;
    }
}

TEST(ContactKernel, HertzMindlinSlidingSpringPlusDashpotGiveTheCappedForce)
{
    // Under Hertz-Mindlin kt and eta_t are those of the current overlap, in both kernels: a
    // fresh contact whose dashpot carries half the limit and whose spring increment 0.8 of it.
    const ContactLaw hm = dem::makeHertzMindlinLaw(2e-6, 5e-4, 5e6, 2e6, 0.5, 0.3);
    const double overlap = 1e-5;
    const double kt = hm.mindlinKt * std::sqrt(overlap);
    const double etaT = hm.mindlinEtaT * std::sqrt(std::sqrt(overlap));
    const double limit = hm.mu * hm.hertzKn * overlap * std::sqrt(overlap);
    const double vt = 0.5 * limit / etaT;
    const double dt = 0.8 * limit / (kt * vt);
    const auto f2 = dem::contactForce<2, dem::HertzMindlin>(geometry(overlap, 0.0, vt, 0.0), hm, dt);
    ASSERT_NEAR(f2.ft, -limit, 1e-12 * limit) << "the contact slides";
    EXPECT_NEAR(-kt * f2.xiT - etaT * vt, f2.ft, 1e-12 * limit);

    dem::PairGeometry3 g;
    g.overlap = overlap;
    g.nHat = Eigen::Vector3d(0.0, 0.0, 1.0);
    g.vRel = Eigen::Vector3d(vt, 0.0, 0.0);
    g.rI = g.rJ = 1e-3;
    g.xiT = Eigen::Vector3d::Zero();
    g.omegaRel = Eigen::Vector3d::Zero();
    const auto f3 = dem::contactForce<3, dem::HertzMindlin>(g, hm, dt);
    ASSERT_NEAR(f3.ft.norm(), limit, 1e-12 * limit) << "the contact slides";
    EXPECT_LT((-kt * f3.xiT - etaT * g.vRel - f3.ft).norm(), 1e-12 * limit);
}

TEST(ContactKernel, SlidingSpringIsRelaxedWhereTheDashpotAloneExceedsTheLimit)
{
    // Spring plus dashpot equal to the cap would need a spring pushing along the sliding:
    // the spring is left relaxed instead, and the force stays capped, in both kernels.
    using S = SlidingStart;
    const double v = 3.0 * S::limit / S::etaT;   // the dashpot alone: 3 times the limit
    const auto f2 = dem::contactForce(geometry(S::overlap, 0.0, v, 2e-7), S::law(), S::dt);
    EXPECT_DOUBLE_EQ(f2.ft, -S::limit);
    EXPECT_EQ(f2.xiT, 0.0);

    dem::PairGeometry3 g;
    g.overlap = S::overlap;
    g.nHat = Eigen::Vector3d(0.0, 1.0, 0.0);
    g.vRel = Eigen::Vector3d(0.0, 0.0, v);
    g.rI = 1e-3;
    g.rJ = 0.0;
    g.xiT = Eigen::Vector3d(0.0, 0.0, 2e-7);
    g.omegaRel = Eigen::Vector3d::Zero();
    const auto f3 = dem::contactForce<3>(g, S::law(), S::dt);
    EXPECT_NEAR(f3.ft.z(), -S::limit, 1e-12 * S::limit);
    EXPECT_EQ(f3.xiT, Eigen::Vector3d::Zero());
}
