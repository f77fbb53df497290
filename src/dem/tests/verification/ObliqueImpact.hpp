// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A sphere's impact on a wall at speed V and incidence angle theta from the normal, with spin
// w0 about a = n x t (t: the tangent in the plane of incidence), read in the wall's frame:
// the 2D engine's floor (n = y, t = x, a = -z) or a slab wall whose normal is along no axis.

#include "verification/VerificationHelpers.hpp"

#include "dem/SlabSystem.hpp"

namespace dem::verification {

struct Material {
    double d, rho;       // m, kg/m^3
    double kn, kt;       // N/m (kt < 0: the library's 2/7 kn); the linear law's
    double e, mu;
    double youngs = 0.0;    // Pa; > 0: the HertzMindlin law
    double poisson = 0.0;
    double wallYoungs = 0.0;    // Pa; 0: a rigid wall
    double wallPoisson = 0.0;
};

/// Hertz's effective modulus of mat on its wall, 1/E* = (1 - nu^2)/E + (1 - nu_w^2)/E_w, Pa.
inline double wallEffectiveModulus(const Material& mat)
{
    if (!(mat.wallYoungs > 0.0)) return mat.youngs / (1.0 - mat.poisson * mat.poisson);
    return 1.0 / ((1.0 - mat.poisson * mat.poisson) / mat.youngs
                  + (1.0 - mat.wallPoisson * mat.wallPoisson) / mat.wallYoungs);
}

/// The contact law of `mat` in `s`: HertzMindlin on its wall (rigid unless it has a wall
/// modulus) if it has a Young's modulus, else the linear law with its kn and kt.
inline void setLaw(Settings& s, const Material& mat)
{
    if (mat.youngs > 0.0) {
        setHertzMindlin(s, mat.youngs, mat.poisson);
        if (mat.wallYoungs > 0.0) {
            s.contact.wallYoungsModulus = mat.wallYoungs;
            s.contact.wallPoissonRatio = mat.wallPoisson;
        }
    } else {
        s.contact.kn = mat.kn;
        s.contact.kt = mat.kt;
    }
}

/// Duration of mat's head-on contact on the wall at normal speed vn (the linear law's does
/// not depend on it), s.
inline double wallContactTime(const Material& mat, double vn)
{
    const double m = sphereMass(mat.d, mat.rho);
    if (mat.youngs > 0.0) {
        return hertzImpactDuration(m, 0.5 * mat.d, wallEffectiveModulus(mat), vn);
    }
    return contactTime(m, mat.kn, mat.e);
}

/// The state after the impact, in the wall's frame.
struct Rebound {
    double vt, vn;       // centre velocity along t and along n (> 0 leaving), m/s
    double wa;           // spin about a = n x t, rad/s (> 0: the rolling sense for motion along t)
    double outOfPlane;   // largest velocity or spin component out of the plane of incidence
};

/// Incoming velocity vt t - vn n; dt = tc/stepsPerContact.
inline Rebound wallImpact(int dimension, const Material& mat, double vt, double vn, double w0,
                          double stepsPerContact)
{
    const double r = 0.5 * mat.d;
    const double size = 20.0 * mat.d;   // box half-width: far from the sphere's path
    Settings s = oneClass(mat.d, mat.rho, {-size, size, -size, size}, dimension, 6.0 * mat.d, 1.0);
    s.dt = wallContactTime(mat, vn) / stepsPerContact;
    setLaw(s, mat);
    s.contact.restitutionWall = mat.e;
    s.contact.frictionWall = mat.mu;
    const double gap = 10.0 * vn * s.dt + 1e-9 * r;   // touch after ~10 steps, off the step grid
    if (dimension == 2) {
        Simulation sim(s);
        const Vec3 start(-10.0 * vt * s.dt, s.box.yMin + r + gap, 0.0);
        place(sim, 0, start, {vt, -vn, 0.0}, {0.0, 0.0, -w0});
        bool touched = false;
        for (int k = 0; k < 1000000; ++k) {
            sim.advance(s.dt);
            const bool inContact = sim.y()[0] - s.box.yMin < r;
            touched = touched || inContact;
            if (touched && !inContact) break;
        }
        return {sim.vx()[0], sim.vy()[0], -sim.omega()[0], 0.0};
    }
    SlabSystem sim(s);
    const Vec3 n = Vec3(0.3, 1.0, 0.4).normalized();
    const Vec3 t = n.cross(Vec3(0.0, 0.0, 1.0)).normalized();
    const Vec3 a = n.cross(t);
    const Vec3 onWall(0.0, -0.4 * size, 3.0 * mat.d);
    sim.addWall(onWall, n);
    sim.addParticle(0, onWall + (r + gap) * n - 10.0 * vt * s.dt * t, vt * t - vn * n, w0 * a);
    const PlaneWall3& wall = sim.walls().back();
    bool touched = false;
    for (int k = 0; k < 1000000; ++k) {
        sim.advance(s.dt);
        const bool inContact = wall.distance(sim.particles().position(0)) < r;
        touched = touched || inContact;
        if (touched && !inContact) break;
    }
    const Vec3 v = sim.particles().velocity(0), w = sim.particles().spin(0);
    const double out = std::max({std::abs(v.dot(a)), std::abs(w.dot(t)), std::abs(w.dot(n))});
    return {v.dot(t), v.dot(n), w.dot(a), out};
}

/// The impact at speed V and incidence angle theta (degrees from the normal), without spin.
inline Rebound angledImpact(int dimension, const Material& mat, double V, double thetaDeg,
                            double stepsPerContact)
{
    const double th = thetaDeg * pi / 180.0;
    return wallImpact(dimension, mat, V * std::sin(th), V * std::cos(th), 0.0, stepsPerContact);
}

} // namespace dem::verification
