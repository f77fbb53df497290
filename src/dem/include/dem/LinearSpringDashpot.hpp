// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The paper's linear spring-dashpot (contactLaw linear; docs/theory/dem.md, "Particles"):
// constant kn, kt, etaN, etaT, its damping solved for the restitution of the clamped force.
// A contact-law policy (LawPolicy.hpp); its closed forms and step bounds:
// LinearSpringDashpot.cpp.

#include "dem/LawPolicy.hpp"

#include <string>
#include <vector>

namespace dem {

/// Restitution of a head-on collision of the linear spring-dashpot whose normal force is
/// clamped at zero, at damping ratio zeta = etaN/(2 sqrt(mEff kn)): the particles part when
/// the force vanishes (Schwager and Poeschel 2007; docs/theory/dem.md, "Particles").
double restitutionOfDampingRatio(double zeta);

/// Normal damping that gives restitution e in (0, 1] for a head-on collision of effective
/// mass mEff under the clamped law: etaN = 2 zeta sqrt(mEff kn), zeta the root of
/// restitutionOfDampingRatio(zeta) = e.
double dampingFromRestitution(double mEff, double kn, double e);

/// Duration of a head-on contact of the clamped linear spring-dashpot, until the force
/// vanishes, s.
double linearContactDuration(double mEff, double kn, double etaN);

struct LinearSpringDashpot {
    static constexpr ContactLawType type = ContactLawType::linear;
    static constexpr const char* name = "linear";
    static constexpr double stateCode = 0.0;
    static constexpr bool readsStiffness = true;
    static constexpr bool readsModuli = false;

    /// Coefficients of one kind of contact.
    struct Coefficients {
        double kn = 0.0;     ///< normal stiffness, N/m
        double kt = 0.0;     ///< tangential stiffness, N/m
        double etaN = 0.0;   ///< normal damping, N s/m
        /// Tangential damping, N s/m (by default = etaN: the paper's Table 1 has one eta)
        double etaT = 0.0;
    };

    /// Those of a contact of effective mass mEff (m_i m_j/(m_i + m_j), or m_i for a wall);
    /// kt < 0 means 2/7 kn, etaN gives restitution e, etaT = tangentialDampingRatio etaN.
    static Coefficients make(double mEff, double kn, double kt, double e,
                             double tangentialDampingRatio);
    static Coefficients coefficients(const ContactSettings& c, const ContactPartners& p)
    {
        return make(p.mEff, c.kn, c.kt, p.restitution, c.tangentialDampingRatio);
    }

    static LawConstants<double> constants(const Coefficients& c)
    {
        return {c.kn, c.etaN, c.kt, c.etaT};
    }
    /// F_n = kn delta + etaN v_n (before the clamp), kt and etaT whatever the overlap.
    template <class Real, class Root>
    [[gnu::always_inline]] static LawResponse<Real>
    response(const Real& overlap, const Real& vn, const LawConstants<Real>& k, Root)
    {
        return {k.normal * overlap + k.normalDamping * vn, k.tangential, k.tangentialDamping};
    }
    template <class History>
    static double elasticEnergy(double overlap, const History& xi, const Coefficients& c)
    {
        return 0.5 * c.kn * overlap * overlap + springEnergy(c.kt, xi);
    }

    /// kn and kt are checked for every law (their defaults are valid).
    static void validate(const Settings&) {}
    /// Eq. 7: (2 pi/5) sqrt(m_min/kn), m_min the lightest particle's mass.
    static double timeStepBound(const Settings& s, int* smallestClass);
    static std::string timeStepBoundText(const Settings& s, double bound);
    /// A pair of the lightest class's lightest particles, until the clamped force vanishes.
    static double contactTime(const Settings& s);
    /// etaN, the same at every overlap.
    static double normalDamping(const Settings& s, const ContactKind& k, double restitution);
    static std::vector<std::string> warnings(const Settings&) { return {}; }
};

} // namespace dem
