// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The contact laws' names and state-file codes through their list (ContactLaw.hpp), and the
// records of one kind of contact.

#include "dem/ContactLaw.hpp"

namespace dem {

std::string contactLawName(ContactLawType law)
{
    return withLaw(law, [](auto policy) { return std::string(decltype(policy)::name); });
}

ContactLawType contactLawFromName(const std::string& name)
{
    std::optional<ContactLawType> found;
    std::string names;
    forEachLaw([&](auto policy) {
        using Law = decltype(policy);
        if (!found && name == Law::name) found = Law::type;
        names += (names.empty() ? "" : ", ") + std::string(Law::name);
    });
    if (!found) throw Error("contactLaw '" + name + "' is not one of: " + names);
    return *found;
}

double contactLawCode(ContactLawType law)
{
    return withLaw(law, [](auto policy) { return decltype(policy)::stateCode; });
}

std::optional<ContactLawType> contactLawOfCode(double code)
{
    std::optional<ContactLawType> found;
    forEachLaw([&](auto policy) {
        using Law = decltype(policy);
        if (!found && code == Law::stateCode) found = Law::type;
    });
    return found;
}

ContactLaw makeContactLaw(const ContactSettings& contact, const ContactPartners& partners,
                          double mu)
{
    ContactLaw law{};
    withLaw(contact.law, [&](auto policy) {
        using Law = decltype(policy);
        coefficientsOf<Law>(law) = Law::coefficients(contact, partners);
    });
    law.mu = mu;
    return law;
}

ContactLaw makeContactLaw(double mEff, double kn, double kt, double e, double mu,
                          double tangentialDampingRatio)
{
    ContactLaw law{};
    coefficientsOf<LinearSpringDashpot>(law) =
        LinearSpringDashpot::make(mEff, kn, kt, e, tangentialDampingRatio);
    law.mu = mu;
    return law;
}

ContactLaw makeHertzMindlinLaw(double mEff, double rEff, double eStar, double gStar, double e,
                               double mu, double tangentialDampingRatio)
{
    ContactLaw law{};
    coefficientsOf<HertzMindlin>(law) =
        HertzMindlin::make(mEff, rEff, eStar, gStar, e, tangentialDampingRatio);
    law.mu = mu;
    return law;
}

void addRollingResistance(ContactLaw& law, double muR, double rRolling, double iEff, double dt)
{
    law.rollingTorquePerForce = muR * rRolling;
    law.rollingTorquePerSpin = iEff / (rollingStopSteps * dt);
}

} // namespace dem
