// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Coefficients of the contact laws for one kind of contact (a pair of size classes, or a
// size class against a wall): the linear spring-dashpot and Hertz-Mindlin.

namespace dem {

/// Coefficients of one kind of contact, computed once at set-up.
struct ContactLaw {
    double kn;     ///< normal stiffness, N/m
    double kt;     ///< tangential stiffness, N/m
    double etaN;   ///< normal damping, N s/m
    double etaT;   ///< tangential damping, N s/m (by default = etaN: the paper's Table 1 has one eta)
    double mu;     ///< sliding friction coefficient
    /// Rolling resistance (docs/theory/dem.md, "Rolling resistance"): mu_r R_r, the largest rolling
    /// torque per newton of normal force, m; 0 without rolling resistance.
    double rollingTorquePerForce = 0.0;
    /// I_eff/(n dt): the rolling torque per unit relative rolling speed below which it is
    /// clamped, so that it stops the relative rolling in n steps at the fastest, N m s.
    double rollingTorquePerSpin = 0.0;
    /// Hertz-Mindlin (docs/theory/dem.md, "The Hertz-Mindlin law"; 0 under the linear law):
    /// F_n = max(hertzKn delta^3/2 + hertzEtaN delta^1/4 v_n, 0), kt = mindlinKt delta^1/2,
    /// eta_t = mindlinEtaT delta^1/4.
    double hertzKn = 0.0;       ///< 4/3 E* sqrt(R*), N/m^1.5
    double hertzEtaN = 0.0;     ///< alpha(e) sqrt(mEff hertzKn), N s/m^1.25
    double mindlinKt = 0.0;     ///< 8 G* sqrt(R*), N/m^1.5
    double mindlinEtaT = 0.0;   ///< tangentialDampingRatio alpha(e) sqrt(2/3 mEff mindlinKt), N s/m^1.25
};

/// Restitution of a head-on collision of the linear spring-dashpot whose normal force is
/// clamped at zero, at damping ratio zeta = etaN/(2 sqrt(mEff kn)): the particles part when
/// the force vanishes (Schwager and Poeschel 2007; docs/theory/dem.md, "Particles").
double restitutionOfDampingRatio(double zeta);

/// Normal damping that gives restitution e in (0, 1] for a head-on collision of effective
/// mass mEff under the clamped law: etaN = 2 zeta sqrt(mEff kn), zeta the root of
/// restitutionOfDampingRatio(zeta) = e.
double dampingFromRestitution(double mEff, double kn, double e);

/// Law for a contact of effective mass mEff (m_i m_j/(m_i + m_j), or m_i for a wall); kt < 0
/// means 2/7 kn, and etaT = tangentialDampingRatio etaN.
ContactLaw makeContactLaw(double mEff, double kn, double kt, double e, double mu,
                          double tangentialDampingRatio = 1.0);

/// Duration of a head-on contact of the clamped linear spring-dashpot, until the force
/// vanishes, s.
double linearContactDuration(double mEff, double kn, double etaN);

/// Restitution of a head-on impact under the clamped Hertz law with Tsuji et al.'s (1992)
/// damping, F = max(Kn delta^3/2 + alpha sqrt(mEff Kn) delta^1/4 v, 0): in the units
/// delta* = (mEff v0^2/Kn)^2/5, delta*/v0 the impact is x'' = -x^3/2 - alpha x^1/4 x' from
/// x = 0, x' = 1 whatever v0, integrated numerically until the force vanishes.
double hertzRestitutionOfDamping(double alpha);

/// The alpha of hertzRestitutionOfDamping that gives restitution e in (0, 1].
double hertzDampingFromRestitution(double e);

/// Effective moduli of two materials (Young's modulus E, Pa; Poisson's ratio nu):
/// 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 and 1/G* = (2 - nu1)/G1 + (2 - nu2)/G2,
/// G = E/(2 (1 + nu)) (Mindlin and Deresiewicz 1953), Pa.
double effectiveYoungsModulus(double e1, double nu1, double e2, double nu2);
double effectiveShearModulus(double e1, double nu1, double e2, double nu2);

/// Hertz-Mindlin law of a contact of effective mass mEff, radius rEff (r_i r_j/(r_i + r_j),
/// or r_i for a wall, m) and effective moduli eStar, gStar (Pa), restitution e, friction mu.
ContactLaw makeHertzMindlinLaw(double mEff, double rEff, double eStar, double gStar, double e,
                               double mu, double tangentialDampingRatio = 1.0);

/// Hertz's elastic contact time of a head-on impact at normal speed v (m/s):
/// 2.9432 delta_max/v, delta_max = (15 mEff v^2/(16 E* sqrt(R*)))^2/5 (Johnson 1985,
/// section 11.4), s.
double hertzContactTime(double mEff, double rEff, double eStar, double v);

/// Adds the constant-torque rolling resistance of coefficient muR to `law`, for a contact of
/// rolling radius rRolling (r_i r_j/(r_i + r_j), or r_i for a wall, m) and effective moment
/// of inertia iEff (I_i I_j/(I_i + I_j), or I_i for a wall, kg m^2) at the DEM step dt.
void addRollingResistance(ContactLaw& law, double muR, double rRolling, double iEff, double dt);

/// Steps over which the clamped rolling torque stops the relative rolling at the fastest:
/// with n = 4 a particle's rolling torques stay stable with up to eight contacts.
constexpr double rollingStopSteps = 4.0;

} // namespace dem
