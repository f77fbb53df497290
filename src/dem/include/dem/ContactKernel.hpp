#pragma once
// The pair-force arithmetic, shared by particle-particle and particle-wall contacts.
// Stateless: geometry and stored history in, force, torques and new history out.

#include "dem/ContactLaw.hpp"

#include <Eigen/Core>
#include <cmath>

namespace dem {

/// Geometry and kinematics of one contact, seen from particle i.
struct PairGeometry {
    double overlap;          ///< r_i + r_j - |x_j - x_i| (or r_i - distance to the wall), m, > 0
    Eigen::Vector2d nHat;    ///< unit normal from i towards j (or towards the wall)
    Eigen::Vector2d vRel;    ///< velocity of i's contact point relative to j's, m/s
    double rI;               ///< lever arm of i, m
    double rJ;               ///< lever arm of j, m (0 for a wall)
    double xiT;              ///< stored tangential spring displacement along tHat, m (contact history)
};

/// Result of one contact evaluation.
struct PairForce {
    Eigen::Vector2d force;   ///< on i (j receives -force), N
    double torqueI;          ///< about z on i, N m
    double torqueJ;          ///< about z on j, N m
    double ft;               ///< tangential force along tHat on i, N
    double xiT;              ///< updated tangential displacement, m
};

/// Linear spring-dashpot with Coulomb friction (model.md section 3).
///
/// In the plane the tangent "plane" of a contact is the line tHat = ez x nHat. The history
/// is stored as the scalar component along tHat, so it turns with the contact normal, which
/// is what rotating the stored displacement into the current tangent plane does in 3D.
/// When the trial force (spring + dashpot) exceeds mu |Fn| the contact slides: the force is
/// set to the limit and the stored displacement is reset so that the spring alone carries it,
/// xiT = -Ft/kt. Dashpot velocity is the one passed in vRel. dt = 0 evaluates without
/// accumulating history.
inline PairForce contactForce(const PairGeometry& g, const ContactLaw& law, double dt)
{
    const Eigen::Vector2d tHat(-g.nHat.y(), g.nHat.x());
    const double vn = g.vRel.dot(g.nHat);     // > 0 approaching
    const double vt = g.vRel.dot(tHat);

    // Normal: F_n = -(kn delta + etaN vn) nHat on i. No clamp of the tensile part near the
    // end of the contact: the exact restitution of eta_n(e) assumes the unclamped law.
    const double fn = law.kn * g.overlap + law.etaN * vn;

    double xiT = g.xiT + vt * dt;
    double ft = -law.kt * xiT - law.etaT * vt;
    const double limit = law.mu * std::abs(fn);
    if (std::abs(ft) > limit) {
        ft = std::copysign(limit, ft);
        xiT = -ft / law.kt;
    }

    PairForce out;
    out.force = -fn * g.nHat + ft * tHat;
    // T = (r nHat) x (ft tHat) = r ft ez for both partners (nHat x tHat = ez).
    out.torqueI = g.rI * ft;
    out.torqueJ = g.rJ * ft;
    out.ft = ft;
    out.xiT = xiT;
    return out;
}

} // namespace dem
