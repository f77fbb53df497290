#pragma once
// Coefficients of the linear spring-dashpot law for one kind of contact
// (a pair of size classes, or a size class against a wall).

namespace dem {

/// Coefficients of one kind of contact, computed once at set-up.
struct ContactLaw {
    double kn;     ///< normal stiffness, N/m
    double kt;     ///< tangential stiffness, N/m
    double etaN;   ///< normal damping, N s/m
    double etaT;   ///< tangential damping, N s/m (= etaN, as the paper's Table 1 has one eta)
    double mu;     ///< sliding friction coefficient
};

/// Normal damping that gives restitution e for a head-on collision of effective mass mEff:
/// etaN = 2 sqrt(mEff kn) |ln e| / sqrt(pi^2 + ln^2 e)  (model.md section 3).
double dampingFromRestitution(double mEff, double kn, double e);

/// Law for a contact of effective mass mEff (m_i m_j/(m_i + m_j), or m_i for a wall).
ContactLaw makeContactLaw(double mEff, double kn, double kt, double e, double mu);

/// Duration of a head-on contact of the linear spring-dashpot, pi / sqrt(kn/mEff - (etaN/(2 mEff))^2), s.
double contactDuration(double mEff, double kn, double etaN);

} // namespace dem
