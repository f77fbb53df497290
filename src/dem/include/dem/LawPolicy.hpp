// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a contact law is: a policy, one struct of static members per law (LinearSpringDashpot.hpp,
// HertzMindlin.hpp), listed in ContactLaw.hpp, where the run's choice becomes its type. The
// engines' loops, the batched slab kernel, the step bounds, the settings' checks and the state
// file's key ask the policy, never the law's name. A law provides:
//
//   static constexpr ContactLawType type;   the choice it answers (ContactSettings::law)
//   static constexpr const char* name;      its contactLaw entry
//   static constexpr double stateCode;      its code in the state file's settings key (kept
//                                           for good: old files carry it)
//   static constexpr bool readsStiffness;   whether it reads ContactSettings::kn and kt
//   static constexpr bool readsModuli;      whether it reads the Young's moduli and Poisson's
//                                           ratios (a restart compares only what it reads)
//   struct Coefficients;                    its coefficients of one kind of contact
//   static Coefficients coefficients(const ContactSettings&, const ContactPartners&)
//   static LawConstants<double> constants(const Coefficients&)
//   template <class Real, class Root>
//   static LawResponse<Real> response(overlap, vn, const LawConstants<Real>&, Root)
//                                           its force, for one contact (Real = double) and
//                                           for the batched kernel's packs of contacts
//   template <class History>
//   static double elasticEnergy(overlap, const History& xi, const Coefficients&)
//   static void validate(const Settings&)   its own entries, dem::Error naming the first bad one
//   static double timeStepBound(const Settings&, int* smallestClass)
//   static std::string timeStepBoundText(const Settings&, double bound)
//   static double contactTime(const Settings&)
//   static double normalDamping(const Settings&, const ContactKind&, double restitution)
//   static std::vector<std::string> warnings(const Settings&)
//
// (the step bounds' meanings: StepBounds.hpp).

#include "dem/Facade.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

namespace dem {

/// The four constants a law's force takes for one contact: of a double, or of a pack of the
/// batched kernel's lanes (SlabPairBatch holds one array of each).
template <class Real> struct LawConstants {
    Real normal;              ///< the normal spring's
    Real normalDamping;       ///< the normal dashpot's
    Real tangential;          ///< the tangential spring's
    Real tangentialDamping;   ///< the tangential dashpot's
};

/// What a law's force gives one contact at its overlap and normal speed.
template <class Real> struct LawResponse {
    Real normal;   ///< the normal force magnitude before its clamp at zero, N
    Real kt;       ///< the tangential spring at this overlap, N/m
    Real etaT;     ///< the tangential dashpot at this overlap, N s/m
};

/// A square root of one contact's values (the batched kernel has its own for packs).
struct ScalarRoot {
    double operator()(double x) const { return std::sqrt(x); }
};

/// What a law gives one contact: the normal force magnitude (F_n = -fn nHat on i, >= 0) and
/// the tangential spring and dashpot at its overlap.
struct ContactStiffness {
    double fn;     ///< N
    double kt;     ///< N/m
    double etaT;   ///< N s/m
};

/// Law's force on one contact (vn > 0 approaching), its normal force clamped at zero: the
/// dashpot does not pull the particles together before they part, so friction and rolling
/// resistance, limited by fn, act only while they are pressed (each law's damping is the one
/// that gives the restitution with the clamp).
template <class Law>
[[gnu::always_inline]] inline ContactStiffness
stiffnessOf(double overlap, double vn, const typename Law::Coefficients& c)
{
    const LawResponse<double> r = Law::response(overlap, vn, Law::constants(c), ScalarRoot{});
    return {std::max(r.normal, 0.0), r.kt, r.etaT};
}

/// Half the spring energy kt xi^2 of a tangential history (2D: a scalar; 3D: a vector), J.
inline double springEnergy(double kt, double xi) { return 0.5 * kt * xi * xi; }
inline double springEnergy(double kt, const Eigen::Vector3d& xi) { return 0.5 * kt * xi.squaredNorm(); }

/// Young's modulus (Pa) and Poisson's ratio of a class's particles or of the walls.
struct ElasticMaterial {
    double youngsModulus = 0.0;
    double poissonRatio = 0.0;
};

/// What a law's coefficients of one kind of contact (a pair of classes, or a class on the
/// walls) are made from: the particles of the class's mean diameter.
struct ContactPartners {
    double mEff;                ///< effective mass m_i m_j/(m_i + m_j), or m_i on a wall, kg
    double rEff;                ///< effective radius r_i r_j/(r_i + r_j), or r_i on a wall, m
    ElasticMaterial first;      ///< class i's
    ElasticMaterial second;     ///< class j's, or the walls'
    double restitution;         ///< of a head-on impact, (0, 1]
};

/// One kind of contact as the step bounds see it: a pair of classes or a class on a wall. A
/// class with a diameter distribution runs its laws made for its mean diameter (mEffLaw,
/// rEff) with particles as light as its smallest (m, mEff): the bounds are those of the
/// smallest particles.
struct ContactKind {
    int a = 0, b = 0;            ///< the classes (b = a on a wall)
    int lighter = 0;             ///< the lighter class
    double m = 0.0;              ///< its lightest particle's mass, kg
    double mEff = 0.0;           ///< effective mass of the lightest particles, kg
    double mEffLaw = 0.0;        ///< effective mass the law's damping is made for, kg
    double rEff = 0.0;           ///< effective radius of the law, m
    ElasticMaterial first;       ///< class a's
    ElasticMaterial second;      ///< class b's, or the walls'
    bool wall = false;
};

} // namespace dem
