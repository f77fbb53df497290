// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A plane wall: a point on it and the unit normal pointing into the domain.

#include "dem/Facade.hpp"

#include <Eigen/Core>
#include <vector>

namespace dem {

/// Infinite plane wall: a line in the x-y plane (Dim = 2) or a plane in any orientation
/// (Dim = 3, the slab mode).
template <int Dim> struct PlaneWallT {
    using Vector = Eigen::Matrix<double, Dim, 1>;
    Vector point;   ///< a point on the wall, m
    Vector nHat;    ///< unit normal pointing into the domain

    /// Signed distance of p from the wall, positive inside the domain, m.
    double distance(const Vector& p) const { return (p - point).dot(nHat); }
};

using PlaneWall = PlaneWallT<2>;
using PlaneWall3 = PlaneWallT<3>;

/// The four walls of a box: floor, right, ceiling, left.
std::vector<PlaneWall> boxWalls(const Box& box);

} // namespace dem
