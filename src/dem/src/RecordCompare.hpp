// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the comparisons of settings keys (StateRecord.cpp) and of bed recipes (BedRecord.cpp)
// share: a difference of two numbers as text, and box coordinates the same to round-off.

#include "dem/StateRecord.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace dem {

/// The difference of entry `name`, its two values as text told apart (textsApart), `unit`
/// after each.
inline Difference differ(const std::string& name, double inFile, double here,
                         const std::string& unit = "")
{
    const auto [a, b] = textsApart(inFile, here);
    return {name, a + unit, b + unit};
}

/// Box coordinates the same to round-off: a mesh of other cell counts puts its bounds a last
/// digit apart (blockMesh sums its cells), which is no other bed. 1e-12 of the box's extent.
inline bool sameCoordinate(double a, double b, double extent)
{
    return a == b || std::abs(a - b) <= 1e-12 * extent;
}

/// The larger of a box's width and height, m.
inline double extentOf(const Box& b)
{
    return std::max(std::abs(b.xMax - b.xMin), std::abs(b.yMax - b.yMin));
}

} // namespace dem
