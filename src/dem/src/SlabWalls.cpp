// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The slab's walls from the settings (SlabWalls.hpp): the six of the slab or the planes and
// cylinders of Settings::walls, their checks, names and allowed ranges, and their record in
// the state file's settings key.

#include "SlabWalls.hpp"

#include "RecordCompare.hpp"
#include "dem/Diameters.hpp"
#include "dem/SlabSystem.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <utility>

namespace dem {

namespace {

using Vec3 = Eigen::Vector3d;

Vec3 vec(const Vector3& v) { return {v.x, v.y, v.z}; }

std::string text(const Vector3& v)
{
    return "(" + formatValue(v.x) + ", " + formatValue(v.y) + ", " + formatValue(v.z) + ")";
}

/// v and its length with the digits (6 at least) that tell the length from 1: an axis a
/// last digit off unit length does not print as a unit one.
std::pair<std::string, std::string> textsOfAxis(const Vector3& v, double length)
{
    int digits = 6;
    auto at = [&digits](double x) {
        std::ostringstream s;
        s << std::setprecision(digits) << x;
        return s.str();
    };
    while (digits < 17 && at(length) == at(1.0)) ++digits;
    return {"(" + at(v.x) + ", " + at(v.y) + ", " + at(v.z) + ")", at(length)};
}

bool finite(const Vector3& v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

const char* shapeName(WallShape shape)
{
    return shape == WallShape::cylinder ? "cylinder" : "plane";
}

PlaneWall3 plane(const WallSettings& w)
{
    const Vec3 n = vec(w.normal);
    return {vec(w.point), n / n.norm()};
}

CylinderWall cylinder(const WallSettings& w)
{
    const Vec3 a = vec(w.axis);
    return {vec(w.point), a / a.norm(), w.radius};
}

constexpr std::size_t recordValues = 8;   // per wall in the key

// An axis's length may miss 1 by this: a unit direction typed to six digits passes
constexpr double axisLengthTolerance = 1e-6;

} // namespace

std::vector<PlaneWall3> slabWalls(const Box& box, double depth)
{
    return {
        {Vec3(box.xMin, box.yMin, 0.0), Vec3(0.0, 1.0, 0.0)},    // floor
        {Vec3(box.xMax, box.yMin, 0.0), Vec3(-1.0, 0.0, 0.0)},   // right
        {Vec3(box.xMin, box.yMax, 0.0), Vec3(0.0, -1.0, 0.0)},   // ceiling
        {Vec3(box.xMin, box.yMin, 0.0), Vec3(1.0, 0.0, 0.0)},    // left
        {Vec3(box.xMin, box.yMin, 0.0), Vec3(0.0, 0.0, 1.0)},    // front, z = 0
        {Vec3(box.xMin, box.yMin, depth), Vec3(0.0, 0.0, -1.0)}, // back, z = depth
    };
}

std::vector<PlaneWall3> planeWalls(const Settings& s)
{
    if (s.walls.empty()) return slabWalls(s.box, s.slabDepth);
    std::vector<PlaneWall3> planes;
    for (const WallSettings& w : s.walls) {
        if (w.shape == WallShape::plane) planes.push_back(plane(w));
    }
    return planes;
}

std::vector<CylinderWall> cylinderWalls(const Settings& s)
{
    std::vector<CylinderWall> cylinders;
    for (const WallSettings& w : s.walls) {
        if (w.shape == WallShape::cylinder) cylinders.push_back(cylinder(w));
    }
    return cylinders;
}

std::string wallEntryName(const Settings& s, std::size_t k)
{
    return "walls[" + std::to_string(k) + "] (" + shapeName(s.walls[k].shape) + ")";
}

void validateWalls(const Settings& s)
{
    if (s.walls.empty()) return;
    if (s.dimension != 3) {
        throw Error("walls has " + std::to_string(s.walls.size()) + " entries, outside [0, 0] "
                    "in 2D: walls of their own are the slab mode's (dimension 3); the 2D "
                    "engine's are the box's");
    }
    double dMax = 0.0;
    for (const auto& c : s.classes) dMax = std::max(dMax, largestDiameter(c));
    for (std::size_t k = 0; k < s.walls.size(); ++k) {
        const WallSettings& w = s.walls[k];
        if (w.shape != WallShape::plane && w.shape != WallShape::cylinder) {
            throw Error("walls[" + std::to_string(k) + "] shape = "
                        + std::to_string(static_cast<int>(w.shape))
                        + " is outside {plane, cylinder}");
        }
        const std::string name = wallEntryName(s, k);
        if (!finite(w.point)) {
            throw Error(name + " point = " + text(w.point) + " m is outside the finite vectors");
        }
        const bool isPlane = w.shape == WallShape::plane;
        const Vector3& direction = isPlane ? w.normal : w.axis;
        const double length = vec(direction).norm();
        if (!finite(direction) || !(length > 0.0) || !std::isfinite(length)) {
            throw Error(name + (isPlane ? " normal = " : " axis = ") + text(direction)
                        + " is outside the finite vectors of length > 0");
        }
        // A plane's normal gives its sense alone; an axis of another length is taken for a
        // mistyped direction (its radius is given apart)
        if (!isPlane && !(std::abs(length - 1.0) <= axisLengthTolerance)) {
            const auto [axis, axisLength] = textsOfAxis(direction, length);
            throw Error(name + " axis = " + axis + " of length " + axisLength + " is outside "
                        "the unit vectors (length 1 within " + formatValue(axisLengthTolerance)
                        + ")");
        }
        if (!isPlane && !(w.radius >= dMax && std::isfinite(w.radius))) {
            throw Error(name + " radius = " + formatValue(w.radius) + " m is outside ["
                        + formatValue(dMax) + ", inf): the cylinder must hold the largest "
                        "diameter");
        }
    }
}

std::string slabWallName(const Settings& s, int w, int planes)
{
    static const char* const six[] = {"the floor (y = yMin)", "the right wall (x = xMax)",
                                      "the ceiling (y = yMax)", "the left wall (x = xMin)",
                                      "the front wall (z = 0)", "the back wall (z = slabDepth)"};
    if (s.walls.empty()) {
        return w < 6 ? six[w] : "added wall " + std::to_string(w);
    }
    // The settings' planes, the added planes, then the settings' cylinders
    const int ownPlanes = static_cast<int>(std::count_if(
        s.walls.begin(), s.walls.end(), [](const WallSettings& e) { return e.shape == WallShape::plane; }));
    if (w >= ownPlanes && w < planes) return "added wall " + std::to_string(w);
    const WallShape shape = w < planes ? WallShape::plane : WallShape::cylinder;
    int ofShape = w < planes ? w : w - planes;
    for (std::size_t k = 0; k < s.walls.size(); ++k) {
        if (s.walls[k].shape == shape && ofShape-- == 0) return wallEntryName(s, k);
    }
    return "wall " + std::to_string(w);
}

std::string wallAllowance(double clearance, const CylinderWall* cylinder)
{
    if (cylinder) {
        return "allowed a distance from its axis of at most "
               + formatValue(cylinder->radius - clearance) + " m";
    }
    return "allowed a distance from it of at least " + formatValue(clearance) + " m";
}

std::string wallAllowance(const Settings& s, std::size_t k, double clearance)
{
    if (s.walls[k].shape != WallShape::cylinder) return wallAllowance(clearance, nullptr);
    const CylinderWall c = cylinder(s.walls[k]);
    return wallAllowance(clearance, &c);
}

int wallPokedThrough(const Settings& s, const Eigen::Vector3d& p, double r)
{
    const double clear = r * (1.0 - 1e-9);
    for (std::size_t k = 0; k < s.walls.size(); ++k) {
        const WallSettings& w = s.walls[k];
        const double distance =
            w.shape == WallShape::plane ? plane(w).distance(p) : cylinder(w).distance(p);
        if (!(distance >= clear)) return static_cast<int>(k);
    }
    return -1;
}

void appendWallsRecord(std::vector<double>& key, const Settings& s)
{
    if (s.walls.empty()) return;
    for (const WallSettings& w : s.walls) {
        const bool isPlane = w.shape == WallShape::plane;
        const Vector3& d = isPlane ? w.normal : w.axis;
        key.insert(key.end(), {isPlane ? 0.0 : 1.0, w.point.x, w.point.y, w.point.z, d.x, d.y,
                               d.z, isPlane ? 0.0 : w.radius});
    }
    key.push_back(-static_cast<double>(s.walls.size()));
}

SplitKey splitWallsRecord(const std::vector<double>& key)
{
    if (!key.empty() && key.back() < 0.0) {
        const double count = -key.back();
        const double values = count * static_cast<double>(recordValues);
        if (count == std::floor(count) && values + 1.0 <= static_cast<double>(key.size())) {
            const auto first = key.end() - 1 - static_cast<std::ptrdiff_t>(values);
            return {std::vector<double>(key.begin(), first), std::vector<double>(first, key.end() - 1)};
        }
    }
    return {key, {}};
}

std::vector<Difference> compareWallsRecords(const std::vector<double>& inFile,
                                            const std::vector<double>& here)
{
    auto described = [](const std::vector<double>& r) {
        if (r.empty()) return std::string("none (the slab's six)");
        std::string shapes;
        for (std::size_t k = 0; k < r.size(); k += recordValues) {
            shapes += std::string(shapes.empty() ? "" : ", ") + (r[k] == 0.0 ? "plane" : "cylinder");
        }
        return std::to_string(r.size() / recordValues) + " (" + shapes + ")";
    };
    if (inFile.size() != here.size()) return {{"walls", described(inFile), described(here)}};
    std::vector<Difference> d;
    for (std::size_t k = 0; k < here.size(); k += recordValues) {
        const std::string name = "walls[" + std::to_string(k / recordValues) + "]";
        if (inFile[k] != here[k]) {
            d.push_back({name + " shape", inFile[k] == 0.0 ? "plane" : "cylinder",
                         here[k] == 0.0 ? "plane" : "cylinder"});
            continue;
        }
        const char* direction = here[k] == 0.0 ? " normal " : " axis ";
        const std::string fields[recordValues] = {
            "", " point x", " point y", " point z", std::string(direction) + "x",
            std::string(direction) + "y", std::string(direction) + "z", " radius"};
        for (std::size_t f = 1; f < recordValues; ++f) {
            if (inFile[k + f] == here[k + f]) continue;
            const bool length = f < 4 || f == 7;
            d.push_back(differ(name + fields[f], inFile[k + f], here[k + f], length ? " m" : ""));
        }
    }
    return d;
}

} // namespace dem
