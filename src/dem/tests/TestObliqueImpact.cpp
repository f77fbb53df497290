// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Oblique impact of a sphere on a wall with friction. Sliding throughout the
// contact: the tangential impulse is mu times the normal one, m (1 + e) v_n, so
//   v_t' = v_t - mu (1 + e) v_n,   |omega'| = 2.5 mu (1 + e) v_n / R   (I = 0.4 m R^2),
// which holds while v_t / v_n > 3.5 mu (1 + e) (Maw, Barber & Fawcett 1976; Walton 1993).
// Below it the contact sticks: the contact point's tangential motion is a damped spring
// of mass m_t = m/(1 + m R^2/I) = 2/7 m, and with kt = 2/7 kn its period equals the normal
// one, so over the contact time the contact-point velocity is reversed (Schaefer, Dippel &
// Wolf 1996, J. Phys. I France 6, 5).

#include "TestHelpers.hpp"

#include <gtest/gtest.h>

using namespace dem;
using namespace dem::test;

namespace {

struct Rebound {
    double vt, vn, omega;
};

Rebound impact(double vt, double vn, double mu, double dt)
{
    Settings s = paperSettings({-0.05, 0.05, 0.0, 0.05}, dt);
    s.contact.frictionWall = mu;
    Simulation sim(s);
    const double r = 0.5 * dSmall;
    sim.addParticle(0, 0.0, r + 10.0 * vn * dt + 1e-7, vt, -vn, 0.0);
    bool touched = false;
    for (int k = 0; k < 100000; ++k) {
        sim.advance(dt);
        const bool inContact = sim.y()[0] < r;
        if (inContact) touched = true;
        if (touched && !inContact) break;
    }
    return {sim.vx()[0], sim.vy()[0], sim.omega()[0]};
}

} // namespace

TEST(ObliqueImpact, SlidingMatchesCoulombImpulse)
{
    const double mu = 0.10, e = 0.97, vn = 0.5, vt = 1.0;   // vt/vn = 2 > 3.5 mu (1+e) = 0.69
    const double R = 0.5 * dSmall;
    const double tc = contactTime(sphereMass(dSmall), 800.0, e);
    const Rebound got = impact(vt, vn, mu, tc / 50.0);
    const double vtExpected = vt - mu * (1.0 + e) * vn;
    const double omegaExpected = -2.5 * mu * (1.0 + e) * vn / R;   // clockwise: rolls toward +x
    EXPECT_NEAR(got.vt, vtExpected, 0.02 * vtExpected);
    EXPECT_NEAR(got.omega, omegaExpected, 0.02 * std::abs(omegaExpected));
    EXPECT_NEAR(got.vn, e * vn, 0.002 * e * vn);
}

TEST(ObliqueImpact, StickingReversesContactPointVelocity)
{
    const double mu = 0.5, e = 0.97, vn = 0.5, vt = 0.05;   // vt/vn = 0.1 << 3.5 mu (1+e)
    const double R = 0.5 * dSmall;
    const double m = sphereMass(dSmall);
    const double kn = 800.0;
    const double tc = contactTime(m, kn, e);
    const Rebound got = impact(vt, vn, mu, tc / 50.0);

    // Angular momentum about the contact point: omega' R = 2.5 (vt' - vt), any regime.
    EXPECT_NEAR(got.omega * R, 2.5 * (got.vt - vt), 1e-9);
    // Impulse below the sliding value: the contact did not slide through.
    EXPECT_LT(std::abs(got.vt - vt), 0.5 * mu * (1.0 + e) * vn);

    // Damped tangential oscillator over the contact time: x'' + 2 zeta w0 x' + w0^2 x = 0.
    const double mt = 2.0 / 7.0 * m;
    const double kt = 2.0 / 7.0 * kn;
    const double eta = etaFor(m, kn, e);      // etaT = etaN
    const double w0 = std::sqrt(kt / mt);
    const double zeta = eta / (2.0 * std::sqrt(kt * mt));
    const double wd = w0 * std::sqrt(1.0 - zeta * zeta);
    const double ratio = std::exp(-zeta * w0 * tc) * (std::cos(wd * tc) - zeta * w0 / wd * std::sin(wd * tc));
    const double vcExpected = ratio * vt;
    const double vc = got.vt + got.omega * R;   // contact-point tangential velocity after
    std::printf("  sticking: contact-point velocity %.5g -> %.5g m/s (oscillator %.5g)\n", vt, vc, vcExpected);
    EXPECT_LT(vc, 0.0);
    EXPECT_NEAR(vc, vcExpected, 0.05 * std::abs(vcExpected));
}
