// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A touching wall contact of particle i as contactForce sees it (internal): the normal from
// the particle into the wall, the contact point's velocity v_i + (r_i w_i) x nHat (the wall
// at rest), the particle's spin as the relative rolling; the history is the caller's to set.

#include "dem/ContactKernel.hpp"
#include "dem/Particles.hpp"
#include "dem/PlaneWall.hpp"
#include "dem/SlabSystem.hpp"

#include <cstddef>

namespace dem {

inline PairGeometry wallGeometry(const Particles& p, std::size_t i, const PlaneWall& w,
                                 double overlap)
{
    const double ri = p.radius[i];
    PairGeometry g;
    g.overlap = overlap;
    g.nHat = -w.nHat;
    const Eigen::Vector2d tHat(-g.nHat.y(), g.nHat.x());
    g.vRel = Eigen::Vector2d(p.vx[i], p.vy[i]) + p.omega[i] * ri * tHat;
    g.rI = ri;
    g.rJ = 0.0;
    g.omegaRel = p.omega[i];
    return g;
}

/// In 3D of the wall's normal at the contact, pointing into the domain (WallSide::nHat: a
/// plane's own, a cylinder's towards its axis).
inline PairGeometry3 wallGeometry(const SlabParticles& p, std::size_t i,
                                  const Eigen::Vector3d& wallNHat, double overlap)
{
    const double ri = p.radius[i];
    PairGeometry3 c;
    c.overlap = overlap;
    c.nHat = -wallNHat;
    c.vRel = p.velocity(i) + (ri * p.spin(i)).cross(c.nHat);
    c.rI = ri;
    c.rJ = 0.0;
    c.omegaRel = p.spin(i);
    return c;
}

} // namespace dem
