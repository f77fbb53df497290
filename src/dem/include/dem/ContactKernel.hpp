// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The pair-force arithmetic, shared by particle-particle and particle-wall contacts and by
// the 2D mode (discs in the x-y plane) and the slab mode (3D spheres), templated on the
// dimension and on the contact law's policy (ContactLaw.hpp), which the engines choose once
// at set-up. Stateless: geometry and stored history in, force, torques and new history out.

#include "dem/ContactLaw.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>   // cross products of the 3D kernel
#include <algorithm>
#include <cmath>
#include <type_traits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace dem {

/// Types of one dimension: in 2D spin, torque and the tangential history are scalars (about
/// z, along tHat = ez x nHat); in 3D they are 3-vectors.
template <int Dim> struct ContactTypes {
    static_assert(Dim == 2 || Dim == 3, "the DEM runs in 2D or 3D");
    using Vector = Eigen::Matrix<double, Dim, 1>;
    using Rotational = std::conditional_t<Dim == 2, double, Eigen::Vector3d>;
};

/// Geometry and kinematics of one contact, seen from particle i.
template <int Dim> struct PairGeometryT {
    using Vector = typename ContactTypes<Dim>::Vector;
    using Rotational = typename ContactTypes<Dim>::Rotational;
    double overlap;          ///< r_i + r_j - |x_j - x_i| (or r_i - distance to the wall), m, > 0
    Vector nHat;             ///< unit normal from i towards j (or towards the wall)
    Vector vRel;             ///< velocity of i's contact point relative to j's, m/s
    double rI;               ///< lever arm of i, m
    double rJ;               ///< lever arm of j, m (0 for a wall)
    Rotational xiT;          ///< stored tangential spring displacement (2D: along tHat), m
    Rotational omegaRel;     ///< w_i - w_j (w_i for a wall), rad/s; read with rolling resistance
};

/// Result of one contact evaluation.
template <int Dim> struct PairForceT {
    using Vector = typename ContactTypes<Dim>::Vector;
    using Rotational = typename ContactTypes<Dim>::Rotational;
    Vector force;            ///< on i (j receives -force), N
    Rotational torqueI;      ///< on i, N m (2D: about z)
    Rotational torqueJ;      ///< on j, N m
    Rotational ft;           ///< tangential force on i (2D: along tHat), N
    Rotational xiT;          ///< updated tangential displacement, m
    Rotational rollingTorque;   ///< rolling resistance on i (j receives minus it), N m; with it only
    double rollingCoefficient;  ///< its |M|/|w_r| (RollingResistanceT), N m s; with it only
};

using PairGeometry = PairGeometryT<2>;
using PairForce = PairForceT<2>;
using PairGeometry3 = PairGeometryT<3>;
using PairForce3 = PairForceT<3>;

/// c ? a : b with a mask instead of the jump GCC makes of the conditional.
inline double selectWithoutBranch(bool c, double a, double b)
{
#if defined(__SSE2__)
    const __m128d mask = _mm_castsi128_pd(_mm_set1_epi64x(-static_cast<long long>(c)));
    return _mm_cvtsd_f64(_mm_or_pd(_mm_and_pd(mask, _mm_set_sd(a)),
                                   _mm_andnot_pd(mask, _mm_set_sd(b))));
#else
    return c ? a : b;
#endif
}

/// The same for each component of a 3-vector.
inline Eigen::Vector3d selectWithoutBranch(bool c, const Eigen::Vector3d& a,
                                           const Eigen::Vector3d& b)
{
    return {selectWithoutBranch(c, a.x(), b.x()), selectWithoutBranch(c, a.y(), b.y()),
            selectWithoutBranch(c, a.z(), b.z())};
}

/// A rolling torque and its coefficient c = |M|/|w_r|, the torque per unit relative rolling
/// speed (at rest the clamp's slope, which a torque of any speed is at most): the share of the
/// rolling it takes in a step, which the engines' limit sums per particle (RollingLimit.hpp).
template <int Dim> struct RollingResistanceT {
    typename ContactTypes<Dim>::Rotational torque;   ///< on i (j receives minus it), N m
    double coefficient;                               ///< N m s
};

/// Constant-torque rolling resistance (Ai et al. 2011, type A; docs/theory/dem.md, "Rolling
/// resistance"): a torque of magnitude mu_r R_r Fn against the relative rolling w_r, clamped
/// to |w_r| I_eff/(n dt) so that it stops the rolling without reversing it. In 3D w_r is the
/// part of w_i - w_j in the tangent plane (the twist about nHat is not rolling).
template <int Dim>
[[gnu::always_inline]] inline RollingResistanceT<Dim>
rollingResistance(const PairGeometryT<Dim>& g, double fn, const ContactLaw& law)
{
    const double limit = law.rollingTorquePerForce * fn;
    auto coefficient = [&](double m, double w) {
        return w > 0.0 ? m / w : law.rollingTorquePerSpin;
    };
    if constexpr (Dim == 2) {
        const double w = std::abs(g.omegaRel);
        const double m = std::min(limit, law.rollingTorquePerSpin * w);
        return {-std::copysign(m, g.omegaRel), coefficient(m, w)};
    } else {
        const Eigen::Vector3d rolling = g.omegaRel - g.omegaRel.dot(g.nHat) * g.nHat;
        const double w = rolling.norm();
        const double m = std::min(limit, law.rollingTorquePerSpin * w);
        return {w > 0.0 ? Eigen::Vector3d(-(m / w) * rolling) : Eigen::Vector3d::Zero(),
                coefficient(m, w)};
    }
}

/// A contact under Law (a policy of ContactLaws) with Coulomb friction.
///
/// The tangential spring lives in the tangent plane of the contact. In 3D the stored
/// displacement is first turned into the current tangent plane (its component along nHat
/// removed, its length kept), then the tangential relative displacement of the step is
/// added. In 2D the tangent "plane" is the line tHat = ez x nHat and the history is the
/// scalar component along tHat, so it turns with the normal by construction.
/// When the trial force (spring + dashpot) exceeds mu Fn the contact slides: the force is
/// set to the limit Ft and the stored displacement is reset so that spring and dashpot
/// together give it, -kt xi = Ft + eta_t v_t (kt and eta_t those of the law at the current
/// overlap), as LAMMPS' granular pair styles do: a spring made to carry the dashpot's share
/// too would hold energy that no work supplied. Where the dashpot alone exceeds the limit,
/// that spring force would point against Ft; the spring is then left relaxed (xi = 0), since
/// a reversed spring, scaled up with the overlap by Hertz-Mindlin's kt, would push the
/// contact along its sliding. The dashpot's velocity is the one in vRel. dt = 0 evaluates without
/// accumulating history. Torques: (r_i nHat) x Ft on i and (r_j nHat) x Ft on j (its lever
/// arm -r_j nHat times its force -Ft). With Rolling, the rolling torque is added to both
/// (rollingTorque on i, its opposite on j) and returned apart in rollingTorque.
/// Always inlined: GCC's size heuristics kept the 3D kernel out of line, called through
/// the shared library's PLT from every pair loop (40 % of a slab run's samples in the call).
template <int Dim, class Law = LinearSpringDashpot, bool Rolling = false>
[[gnu::always_inline]] inline PairForceT<Dim> contactForce(const PairGeometryT<Dim>& g, const ContactLaw& law, double dt)
{
    PairForceT<Dim> out;
    if constexpr (Dim == 2) {
        // The operations and their order of the 2D code before the 3D mode: the same bits.
        const Eigen::Vector2d tHat(-g.nHat.y(), g.nHat.x());
        const double vn = g.vRel.dot(g.nHat);     // > 0 approaching
        const double vt = g.vRel.dot(tHat);
        const ContactStiffness c = stiffnessOf<Law>(g.overlap, vn, law);
        const double fn = c.fn;
        const double xiTrial = g.xiT + vt * dt;
        const double trial = -c.kt * xiTrial - c.etaT * vt;
        const double limit = law.mu * fn;
        // Sliding picked without a branch, both outcomes computed: contacts start and end
        // sliding unpredictably in a bubbling bed
        const double capped = std::copysign(limit, trial);
        const bool slides = std::abs(trial) > limit;
        // Divided by 1 where the result is not taken: at zero overlap Hertz-Mindlin's kt and
        // the limit are both 0, and 0/0 would raise FE_INVALID (which the solver traps)
        const double spring = capped + c.etaT * vt;   // the spring's share of the capped force
        const double xiCapped = selectWithoutBranch(spring * capped > 0.0, -spring, 0.0)
                                / selectWithoutBranch(slides, c.kt, 1.0);
        const double ft = selectWithoutBranch(slides, capped, trial);
        const double xiT = selectWithoutBranch(slides, xiCapped, xiTrial);
        out.force = -fn * g.nHat + ft * tHat;
        // T = (r nHat) x (ft tHat) = r ft ez for both partners (nHat x tHat = ez).
        out.torqueI = g.rI * ft;
        out.torqueJ = g.rJ * ft;
        out.ft = ft;
        out.xiT = xiT;
        if constexpr (Rolling) {
            const RollingResistanceT<Dim> rolling = rollingResistance(g, fn, law);
            out.rollingTorque = rolling.torque;
            out.rollingCoefficient = rolling.coefficient;
            out.torqueI += out.rollingTorque;
            out.torqueJ -= out.rollingTorque;
        }
    } else {
        const double vn = g.vRel.dot(g.nHat);
        const ContactStiffness c = stiffnessOf<Law>(g.overlap, vn, law);
        const double fn = c.fn;
        const double limit = law.mu * fn;
        const Eigen::Vector3d vt = g.vRel - vn * g.nHat;
        // Turn the stored displacement into the current tangent plane, keeping its length.
        Eigen::Vector3d xi = g.xiT - g.xiT.dot(g.nHat) * g.nHat;
        const double before2 = g.xiT.squaredNorm();
        const double after2 = xi.squaredNorm();
        if (after2 > 0.0 && after2 != before2) xi *= std::sqrt(before2 / after2);
        xi += vt * dt;
        Eigen::Vector3d ft = -c.kt * xi - c.etaT * vt;
        const double ft2 = ft.squaredNorm();
        if (ft2 > limit * limit) {
            ft *= limit / std::sqrt(ft2);
            const Eigen::Vector3d spring = ft + c.etaT * vt;   // its share of the capped force
            const double along = spring.x() * ft.x() + spring.y() * ft.y() + spring.z() * ft.z();
            xi = along > 0.0 ? Eigen::Vector3d(-spring / c.kt) : Eigen::Vector3d::Zero();
        }
        out.force = -fn * g.nHat + ft;
        const Eigen::Vector3d nxF = g.nHat.cross(ft);
        out.torqueI = g.rI * nxF;
        out.torqueJ = g.rJ * nxF;
        out.ft = ft;
        out.xiT = xi;
        if constexpr (Rolling) {
            const RollingResistanceT<Dim> rolling = rollingResistance(g, fn, law);
            out.rollingTorque = rolling.torque;
            out.rollingCoefficient = rolling.coefficient;
            out.torqueI += out.rollingTorque;
            out.torqueJ -= out.rollingTorque;
        }
    }
    return out;
}

} // namespace dem
