// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A cylinder wall of the slab mode, the particles inside it, and where a sphere's centre
// stands against a wall of either shape: the one place of the walls' contact geometry that
// the slab's wall loops read (SlabSystem::wallSide).

#include "dem/PlaneWall.hpp"

#include <Eigen/Core>

namespace dem {

/// Where a point stands against a wall: its signed distance, positive inside the domain, and
/// the wall's unit normal at the wall's point nearest it, pointing into the domain. A sphere
/// of radius r there touches the wall with the overlap r - distance, at the contact point
/// p - distance nHat.
struct WallSide {
    double distance;        ///< m
    Eigen::Vector3d nHat;

    /// The wall's point nearest p, the point this was taken at, m.
    Eigen::Vector3d nearestPoint(const Eigen::Vector3d& p) const { return p - distance * nHat; }
};

/// An infinite cylinder around the axis through `point` along the unit `axis`, of `radius`;
/// the domain is its inside.
struct CylinderWall {
    Eigen::Vector3d point;  ///< a point on the axis, m
    Eigen::Vector3d axis;   ///< unit direction of the axis
    double radius;          ///< m

    /// p's offset from the axis, perpendicular to it, m.
    Eigen::Vector3d offset(const Eigen::Vector3d& p) const
    {
        const Eigen::Vector3d d = p - point;
        return d - d.dot(axis) * axis;
    }
    /// Signed distance of p from the wall, positive inside, m.
    double distance(const Eigen::Vector3d& p) const { return radius - offset(p).norm(); }
    /// The distance (as distance()) and the normal towards the axis, for p off the axis
    /// (a sphere that touches the wall is: the radius is at least its diameter).
    WallSide side(const Eigen::Vector3d& p) const
    {
        const Eigen::Vector3d o = offset(p);
        const double rho = o.norm();
        return {radius - rho, -o / rho};
    }
};

/// The plane's distance and its own normal, as PlaneWallT::distance computes it.
inline WallSide planeSide(const PlaneWall3& w, const Eigen::Vector3d& p)
{
    return {w.distance(p), w.nHat};
}

} // namespace dem
