// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The contact laws: the list of their policies (LawPolicy.hpp), the one place where the run's
// choice (ContactSettings::law) becomes a law's type, and the coefficients of one kind of
// contact (a pair of size classes, or a size class against a wall) as the engines hold them.

#include "dem/HertzMindlin.hpp"
#include "dem/LinearSpringDashpot.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <type_traits>

namespace dem {

template <class... Laws> struct LawList {
    static constexpr std::size_t size = sizeof...(Laws);
    /// Law's place in the list.
    template <class Law> static constexpr std::size_t indexOf()
    {
        constexpr bool same[] = {std::is_same_v<Law, Laws>...};
        for (std::size_t k = 0; k < size; ++k) {
            if (same[k]) return k;
        }
        return size;
    }
};

/// Every contact law. A law is its policy, its ContactLawType and its place here; the first
/// is ContactSettings' default.
using ContactLaws = LawList<LinearSpringDashpot, HertzMindlin>;

namespace lawDispatch {
template <class Body, class Law, class... Rest>
decltype(auto) visit(std::size_t index, const Body& body, LawList<Law, Rest...>)
{
    if constexpr (sizeof...(Rest) > 0) {
        if (index > 0) return visit(index - 1, body, LawList<Rest...>{});
    }
    return body(Law{});
}
template <class... Laws> std::size_t indexOfType(ContactLawType type, LawList<Laws...>)
{
    const ContactLawType types[] = {Laws::type...};
    for (std::size_t k = 0; k < sizeof...(Laws); ++k) {
        if (types[k] == type) return k;
    }
    return 0;   // a value of no law: the default
}
template <class Body, class... Laws> void forEach(const Body& body, LawList<Laws...>)
{
    (body(Laws{}), ...);
}
} // namespace lawDispatch

/// body(Law{}) with the law of `type` (the first law for a value that names none); returns
/// what body returns. The engines' contact loops are compiled once per law and chosen here
/// once per loop, not per contact.
template <class Body> decltype(auto) withLaw(ContactLawType type, const Body& body)
{
    return lawDispatch::visit(lawDispatch::indexOfType(type, ContactLaws{}), body, ContactLaws{});
}

/// body(Law{}) for every law, in the list's order.
template <class Body> void forEachLaw(const Body& body)
{
    lawDispatch::forEach(body, ContactLaws{});
}

/// A law's code in the state file's settings key, and the law of a code (none if unknown).
double contactLawCode(ContactLawType law);
std::optional<ContactLawType> contactLawOfCode(double code);

/// Sliding friction and rolling resistance, the coefficients of a contact whatever its law,
/// with the coefficients of Laws (the laws after the first, ContactRecord).
template <class... Laws> struct ContactFriction : Laws::Coefficients... {
    ContactFriction() = default;
    /// Implicit: the mu of ContactLaw{kn, kt, etaN, etaT, mu}, a contact of the first law
    /// (this part no aggregate, so that the other laws' coefficients are 0 without a
    /// missing-initializer warning).
    ContactFriction(double friction) : mu(friction) {}

    double mu = 0.0;   ///< sliding friction coefficient
    /// Rolling resistance (docs/theory/dem.md, "Rolling resistance"): mu_r R_r, the largest rolling
    /// torque per newton of normal force, m; 0 without rolling resistance.
    double rollingTorquePerForce = 0.0;
    /// I_eff/(n dt): the rolling torque per unit relative rolling speed below which it is
    /// clamped, so that it stops the relative rolling in n steps at the fastest, N m s.
    double rollingTorquePerSpin = 0.0;
};

/// Coefficients of one kind of contact, computed once at set-up: every law's (the run's law's
/// set, the others 0), each law's loops reading its own, and the friction. The first law's
/// come first: ContactLaw{kn, kt, etaN, etaT, mu} is a linear contact.
template <class List> struct ContactRecord;
template <class First, class... Rest>
struct ContactRecord<LawList<First, Rest...>> : First::Coefficients, ContactFriction<Rest...> {};
using ContactLaw = ContactRecord<ContactLaws>;

/// Law's coefficients in a record.
template <class Law> typename Law::Coefficients& coefficientsOf(ContactLaw& law) { return law; }

/// The record of the law `contact.law` for a kind of contact of sliding friction mu.
ContactLaw makeContactLaw(const ContactSettings& contact, const ContactPartners& partners,
                          double mu);

/// A linear spring-dashpot contact of effective mass mEff (m_i m_j/(m_i + m_j), or m_i for a
/// wall); kt < 0 means 2/7 kn, and etaT = tangentialDampingRatio etaN.
ContactLaw makeContactLaw(double mEff, double kn, double kt, double e, double mu,
                          double tangentialDampingRatio = 1.0);

/// A Hertz-Mindlin contact of effective mass mEff, radius rEff (r_i r_j/(r_i + r_j), or r_i
/// for a wall, m) and effective moduli eStar, gStar (Pa), restitution e, friction mu.
ContactLaw makeHertzMindlinLaw(double mEff, double rEff, double eStar, double gStar, double e,
                               double mu, double tangentialDampingRatio = 1.0);

/// Adds the constant-torque rolling resistance of coefficient muR to `law`, for a contact of
/// rolling radius rRolling (r_i r_j/(r_i + r_j), or r_i for a wall, m) and effective moment
/// of inertia iEff (I_i I_j/(I_i + I_j), or I_i for a wall, kg m^2) at the DEM step dt.
void addRollingResistance(ContactLaw& law, double muR, double rRolling, double iEff, double dt);

/// Steps over which the clamped rolling torque stops the relative rolling at the fastest:
/// with n = 4 a particle's rolling torques stay stable with up to eight contacts.
constexpr double rollingStopSteps = 4.0;

} // namespace dem
