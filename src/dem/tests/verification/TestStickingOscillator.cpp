// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The tangential spring and dashpot of both laws, alone, at e < 1: a sphere at rest on the
// floor at its static overlap, given a small sliding speed u0, sticks, and its contact point
// oscillates along the floor as a damped oscillator of the contact's tangential stiffness
// and damping and the contact point's mass m_t = m/(1 + m r^2/I) = 2m/7 (a solid sphere),
//   m_t x'' = -kt x - eta_t x',   x(0) = 0, x'(0) = u0,
// whose velocity is u(t) = u0 exp(-gamma t) (cos(w_d t) - gamma/w_d sin(w_d t)),
// gamma = eta_t/(2 m_t), w_d = sqrt(kt/m_t - gamma^2). The coefficients are written here from
// the laws' definitions (docs/theory/dem.md): the linear law's kt = 2/7 kn and eta_t = eta_n of
// the clamped head-on contact at e; Hertz-Mindlin's kt = 8 G* sqrt(R delta0) and
// eta_t = alpha(e) sqrt(2/3 m kt) at the static overlap delta0 = (m g/(4/3 E* sqrt(R)))^2/3,
// alpha(e) the damping of Tsuji et al.'s Hertz impact solved here for e. The normal contact
// stays at rest (the tangential force moves the sphere along the floor only).

#include "verification/VerificationHelpers.hpp"

using namespace dem;
using namespace dem::verification;

namespace {

constexpr double g = 9.81;

/// Restitution of the clamped Hertz impact x'' = -x^3/2 - alpha x^1/4 x' from x = 0,
/// x' = 1 (the units delta*, delta*/v0 in which it does not depend on v0), by RK4 until the
/// force x^1/4 (x^5/4 + alpha x') vanishes.
double tsujiRestitution(double alpha)
{
    const double h = 2e-5;
    auto force = [alpha](double x, double v) {
        const double xp = std::max(x, 0.0);
        return std::max(xp * std::sqrt(xp) + alpha * std::sqrt(std::sqrt(xp)) * v, 0.0);
    };
    double x = 0.0, v = 1.0;
    for (long k = 0; k < 10000000L; ++k) {
        const double k1x = v, k1v = -force(x, v);
        const double k2x = v + 0.5 * h * k1v, k2v = -force(x + 0.5 * h * k1x, v + 0.5 * h * k1v);
        const double k3x = v + 0.5 * h * k2v, k3v = -force(x + 0.5 * h * k2x, v + 0.5 * h * k2v);
        const double k4x = v + h * k3v, k4v = -force(x + h * k3x, v + h * k3v);
        x += h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
        v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
        if (k > 0 && (x <= 0.0 || force(x, v) <= 0.0)) return -v;
    }
    return 0.0;
}

/// alpha with tsujiRestitution(alpha) = e, by bisection (e falls with alpha).
double tsujiAlpha(double e)
{
    double low = 0.0, high = 4.0;
    for (int k = 0; k < 50; ++k) {
        const double mid = 0.5 * (low + high);
        (tsujiRestitution(mid) > e ? low : high) = mid;
    }
    return 0.5 * (low + high);
}

struct Oscillator {
    double kt, etaT, delta0;   // N/m, N s/m, m
};

// Alumina (Chung and Ooi's test 3 material), d = 5 mm, on a rigid floor; kn of the linear law
constexpr double d = 5e-3, rho = 4000.0, youngs = 3.8e11, poisson = 0.23, kn = 1e6, mu = 1.0;

Oscillator expected(bool hertz, double e)
{
    const double m = sphereMass(d, rho), r = 0.5 * d;
    if (!hertz) return {2.0 / 7.0 * kn, ::dem::test::etaFor(m, kn, e), m * g / kn};
    const double eStar = youngs / (1.0 - poisson * poisson);            // rigid floor
    const double gStar = youngs / (2.0 * (1.0 + poisson)) / (2.0 - poisson);
    const double delta0 = std::pow(m * g / (4.0 / 3.0 * eStar * std::sqrt(r)), 2.0 / 3.0);
    const double kt = 8.0 * gStar * std::sqrt(r * delta0);
    return {kt, tsujiAlpha(e) * std::sqrt(2.0 / 3.0 * m * kt), delta0};
}

/// The worst |u - u_exact|/u0 over three periods, and u after them over u0 (DEM, exact).
struct Decay {
    double worst, endDem, endExact;
};

Decay stickingOscillation(int dimension, bool hertz, double e)
{
    const double m = sphereMass(d, rho), r = 0.5 * d, mt = 2.0 / 7.0 * m;
    const Oscillator o = expected(hertz, e);
    const double gamma = o.etaT / (2.0 * mt);
    const double wd = std::sqrt(o.kt / mt - gamma * gamma);
    const double period = 2.0 * pi / wd;
    Settings s = oneClass(d, rho, {0.0, 20.0 * d, 0.0, 20.0 * d}, dimension, 2.0 * d, period / 2000.0);
    s.gravity[1] = -g;
    s.contact.frictionWall = mu;
    s.contact.restitutionWall = e;
    if (hertz) {
        setHertzMindlin(s, youngs, poisson);
    } else {
        s.contact.kn = kn;
    }
    Simulation sim(s);
    // u0 small enough to stick: the spring's peak force ~u0 sqrt(kt m_t) at 10 % of mu m g
    const double u0 = 0.1 * mu * m * g / std::sqrt(o.kt * mt);
    place(sim, 0, {10.0 * d, r - o.delta0, d}, {u0, 0.0, 0.0}, Vec3::Zero());
    auto exact = [&](double t) {
        return u0 * std::exp(-gamma * t) * (std::cos(wd * t) - gamma / wd * std::sin(wd * t));
    };
    Decay out{0.0, 0.0, 0.0};
    while (sim.time() < 3.0 * period) {
        sim.advance(s.dt);
        const double u = sim.vx()[0] + spin(sim, 0).z() * r;   // contact point: v + w ez x (-r ey)
        out.worst = std::max(out.worst, std::abs(u - exact(sim.time())) / u0);
        out.endDem = u / u0;
        out.endExact = exact(sim.time()) / u0;
    }
    return out;
}

} // namespace

TEST(StickingOscillator, TangentialDampingDecaysAtTheLawsRate)
{
    // Tolerance 0.5 % of u0 pointwise over three periods at dt = T/2000: the dashpot fed the
    // half-step velocity errs in gamma by ~gamma dt/2 (1e-4 here); a tangential damping off by
    // a third, or a stiffness off by 1 %, moves u by more. e = 0.5 and 0.8 (at e = 1 the
    // Hertz-Mindlin dashpot vanishes).
    for (bool hertz : {false, true}) {
        for (double e : {0.5, 0.8}) {
            for (int dimension : {2, 3}) {
                const Decay r = stickingOscillation(dimension, hertz, e);
                std::printf("  sticking oscillator %-6s %-4s e %.1f: worst |u - exact|/u0 %.2e, "
                            "u/u0 after 3 periods %.5f (exact %.5f)\n",
                            hertz ? "Hertz" : "linear", engineName(dimension), e, r.worst,
                            r.endDem, r.endExact);
                EXPECT_LT(r.worst, 0.005) << (hertz ? "Hertz " : "linear ")
                                          << engineName(dimension) << " e " << e;
            }
        }
    }
}
