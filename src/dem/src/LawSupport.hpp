// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the contact laws' sources (LinearSpringDashpot.cpp, HertzMindlin.cpp) share with the
// settings' checks (Settings.cpp) and the step bounds (StepBounds.cpp); internal to the library.

#include "dem/LawPolicy.hpp"

#include <algorithm>
#include <string>

namespace dem {

/// dem::Error "<name> = <value> is outside (0, inf)" unless value is positive and finite.
void requirePositive(double value, const std::string& name);

/// "classes[k] ('name')", class k in messages.
std::string className(const Settings& s, int k);

/// The lightest particle of the class: of its smallest diameter, kg.
double classMass(const ParticleClass& c);

/// The particle the class's contact laws are made for: of its mean diameter (the engines'
/// laws, EngineBase.cpp), kg.
double lawMass(const ParticleClass& c);

/// body(kind) for every pair of classes a <= b, then each class on a wall.
template <class Body> void forEachContactKind(const Settings& s, const Body& body)
{
    const ContactSettings& c = s.contact;
    const ElasticMaterial wall{c.wallYoungsModulus, c.wallPoissonRatio};
    const std::size_t n = s.classes.size();
    for (std::size_t a = 0; a < n; ++a) {
        const ParticleClass& ca = s.classes[a];
        const ElasticMaterial first{ca.youngsModulus, ca.poissonRatio};
        const double ma = classMass(ca);
        const double la = lawMass(ca);
        const double ra = 0.5 * meanDiameter(ca);
        for (std::size_t b = a; b < n; ++b) {
            const ParticleClass& cb = s.classes[b];
            const double mb = classMass(cb);
            const double lb = lawMass(cb);
            const double rb = 0.5 * meanDiameter(cb);
            body(ContactKind{static_cast<int>(a), static_cast<int>(b),
                             static_cast<int>(ma <= mb ? a : b), std::min(ma, mb),
                             ma * mb / (ma + mb), la * lb / (la + lb), ra * rb / (ra + rb), first,
                             ElasticMaterial{cb.youngsModulus, cb.poissonRatio}, false});
        }
        body(ContactKind{static_cast<int>(a), static_cast<int>(a), static_cast<int>(a), ma, ma,
                         la, ra, first, wall, true});
    }
}

} // namespace dem
