#pragma once
// A plane wall: a point on it and the unit normal pointing into the domain.

#include "dem/Facade.hpp"

#include <Eigen/Core>
#include <vector>

namespace dem {

/// Infinite plane wall at any angle in the x-y plane.
struct PlaneWall {
    Eigen::Vector2d point;   ///< a point on the wall, m
    Eigen::Vector2d nHat;    ///< unit normal pointing into the domain

    /// Signed distance of p from the wall, positive inside the domain, m.
    double distance(const Eigen::Vector2d& p) const { return (p - point).dot(nHat); }
};

/// The four walls of a box: floor, right, ceiling, left.
std::vector<PlaneWall> boxWalls(const Box& box);

} // namespace dem
