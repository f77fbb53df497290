// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Coefficients of the linear spring-dashpot law for one kind of contact
// (a pair of size classes, or a size class against a wall).

namespace dem {

/// Coefficients of one kind of contact, computed once at set-up.
struct ContactLaw {
    double kn;     ///< normal stiffness, N/m
    double kt;     ///< tangential stiffness, N/m
    double etaN;   ///< normal damping, N s/m
    double etaT;   ///< tangential damping, N s/m (by default = etaN: the paper's Table 1 has one eta)
    double mu;     ///< sliding friction coefficient
    /// Rolling resistance (model.md, "Rolling resistance"): mu_r R_r, the largest rolling
    /// torque per newton of normal force, m; 0 without rolling resistance.
    double rollingTorquePerForce = 0.0;
    /// I_eff/(n dt): the rolling torque per unit relative rolling speed below which it is
    /// clamped, so that it stops the relative rolling in n steps at the fastest, N m s.
    double rollingTorquePerSpin = 0.0;
};

/// Restitution of a head-on collision of the linear spring-dashpot whose normal force is
/// clamped at zero, at damping ratio zeta = etaN/(2 sqrt(mEff kn)): the particles part when
/// the force vanishes (Schwager and Poeschel 2007; model.md section 3).
double restitutionOfDampingRatio(double zeta);

/// Normal damping that gives restitution e in (0, 1] for a head-on collision of effective
/// mass mEff under the clamped law: etaN = 2 zeta sqrt(mEff kn), zeta the root of
/// restitutionOfDampingRatio(zeta) = e.
double dampingFromRestitution(double mEff, double kn, double e);

/// Law for a contact of effective mass mEff (m_i m_j/(m_i + m_j), or m_i for a wall); kt < 0
/// means 2/7 kn, and etaT = tangentialDampingRatio etaN.
ContactLaw makeContactLaw(double mEff, double kn, double kt, double e, double mu,
                          double tangentialDampingRatio = 1.0);

/// Adds the constant-torque rolling resistance of coefficient muR to `law`, for a contact of
/// rolling radius rRolling (r_i r_j/(r_i + r_j), or r_i for a wall, m) and effective moment
/// of inertia iEff (I_i I_j/(I_i + I_j), or I_i for a wall, kg m^2) at the DEM step dt.
void addRollingResistance(ContactLaw& law, double muR, double rRolling, double iEff, double dt);

/// Steps over which the clamped rolling torque stops the relative rolling at the fastest:
/// with n = 4 a particle's rolling torques stay stable with up to eight contacts.
constexpr double rollingStopSteps = 4.0;

} // namespace dem
