// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Hertz's normal force and Mindlin and Deresiewicz's tangential stiffness (contactLaw
// HertzMindlin; docs/theory/dem.md, "The Hertz-Mindlin law"), from the materials' Young's
// moduli and Poisson's ratios, with Tsuji et al.'s (1992) damping solved for the restitution.
// A contact-law policy (LawPolicy.hpp); its closed forms and step bounds: HertzMindlin.cpp.

#include "dem/LawPolicy.hpp"

#include <string>
#include <vector>

namespace dem {

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

/// Hertz's elastic contact time of a head-on impact at normal speed v (m/s):
/// 2.9432 delta_max/v, delta_max = (15 mEff v^2/(16 E* sqrt(R*)))^2/5 (Johnson 1985,
/// section 11.4), s.
double hertzContactTime(double mEff, double rEff, double eStar, double v);

struct HertzMindlin {
    static constexpr ContactLawType type = ContactLawType::hertzMindlin;
    static constexpr const char* name = "HertzMindlin";
    static constexpr double stateCode = 1.0;
    static constexpr bool readsStiffness = false;   // kt stays the default: validate
    static constexpr bool readsModuli = true;

    /// Coefficients of one kind of contact: F_n = max(hertzKn delta^3/2 + hertzEtaN
    /// delta^1/4 v_n, 0), kt = mindlinKt delta^1/2, eta_t = mindlinEtaT delta^1/4.
    struct Coefficients {
        double hertzKn = 0.0;       ///< 4/3 E* sqrt(R*), N/m^1.5
        double hertzEtaN = 0.0;     ///< alpha(e) sqrt(mEff hertzKn), N s/m^1.25
        double mindlinKt = 0.0;     ///< 8 G* sqrt(R*), N/m^1.5
        /// tangentialDampingRatio alpha(e) sqrt(2/3 mEff mindlinKt), N s/m^1.25
        double mindlinEtaT = 0.0;
    };

    /// Those of a contact of effective mass mEff, radius rEff (r_i r_j/(r_i + r_j), or r_i
    /// for a wall, m) and effective moduli eStar, gStar (Pa), restitution e.
    static Coefficients make(double mEff, double rEff, double eStar, double gStar, double e,
                             double tangentialDampingRatio);
    static Coefficients coefficients(const ContactSettings& c, const ContactPartners& p);

    static LawConstants<double> constants(const Coefficients& c)
    {
        return {c.hertzKn, c.hertzEtaN, c.mindlinKt, c.mindlinEtaT};
    }
    template <class Real, class Root>
    [[gnu::always_inline]] static LawResponse<Real>
    response(const Real& overlap, const Real& vn, const LawConstants<Real>& k, Root root)
    {
        const Real sqrtOverlap = root(overlap);      // delta^1/2
        const Real quarter = root(sqrtOverlap);      // delta^1/4
        return {k.normal * overlap * sqrtOverlap + k.normalDamping * quarter * vn,
                k.tangential * sqrtOverlap, k.tangentialDamping * quarter};
    }
    template <class History>
    static double elasticEnergy(double overlap, const History& xi, const Coefficients& c)
    {
        const double root = std::sqrt(overlap);
        return 0.4 * c.hertzKn * overlap * overlap * root + springEnergy(c.mindlinKt * root, xi);
    }

    /// The moduli of every material and impactSpeed; kt must be left at its default.
    static void validate(const Settings& s);
    /// The least (2 pi/5) sqrt(m/S) over the kinds of contact, S Hertz's stiffness at the
    /// peak overlap of an impact at hertzSpeed.
    static double timeStepBound(const Settings& s, int* smallestClass);
    static std::string timeStepBoundText(const Settings& s, double bound);
    /// The shortest of Hertz's elastic contact times at hertzSpeed.
    static double contactTime(const Settings& s);
    /// Its largest: the law's (made for mEffLaw) at the elastic peak overlap of the lightest
    /// particles' impact at hertzSpeed (damping lowers the peak).
    static double normalDamping(const Settings& s, const ContactKind& k, double restitution);
    /// impactSpeed below the bed's own speed scale.
    static std::vector<std::string> warnings(const Settings& s);
};

} // namespace dem
