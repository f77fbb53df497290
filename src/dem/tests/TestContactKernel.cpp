// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The shared pair-force kernel, checked by hand-computed values.

#include "dem/ContactKernel.hpp"

#include <gtest/gtest.h>

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
