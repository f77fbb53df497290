// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The slab's walls as the settings give them (internal): their checks, their names and
// allowed ranges in messages, the test that a sphere clears them, and their record in the
// state file's settings key.

#include "dem/CylinderWall.hpp"
#include "dem/Facade.hpp"
#include "dem/StateRecord.hpp"

#include <Eigen/Core>
#include <string>
#include <vector>

namespace dem {

/// Throws dem::Error naming the first bad entry of Settings::walls and its allowed range: any
/// entry in 2D; in 3D a point or direction not finite, a zero normal, an axis not of unit
/// length (within 1e-6), a cylinder's radius below the largest diameter. The classes are
/// valid.
void validateWalls(const Settings& settings);

/// "walls[1] (cylinder)": entry k of Settings::walls in messages.
std::string wallEntryName(const Settings& settings, std::size_t k);

/// The name of wall w of a slab engine whose walls are the settings' and then planes added
/// by addWall, `planes` planes in all (SlabSystem::wallCount's order: planes, cylinders).
std::string slabWallName(const Settings& settings, int w, int planes);

/// The allowed range of a sphere centre's distance from a wall, `clearance` the least signed
/// distance allowed, for messages: "allowed a distance from it of at least 0.00074 m" (a
/// plane, cylinder null) or "allowed a distance from its axis of at most 0.0093 m".
std::string wallAllowance(double clearance, const CylinderWall* cylinder);
/// The same for entry k of Settings::walls.
std::string wallAllowance(const Settings& settings, std::size_t k, double clearance);

/// The first entry of Settings::walls that a sphere of radius r at p pokes through (its
/// distance below r, less a round-off of 1e-9 r), or -1 if it clears them all (and if there
/// are none: the slab's six, which the packing region and the depth keep clear).
int wallPokedThrough(const Settings& settings, const Eigen::Vector3d& p, double r);

/// Settings::walls appended to a settings key, for a restart made with other walls to be
/// refused: eight values each (shape 0 plane or 1 cylinder, the point, the normal or axis as
/// given, the radius or 0), then minus their number. Nothing if there are none: the key
/// then ends in the slab's depth (> 0), so the slab's six keep their key.
void appendWallsRecord(std::vector<double>& key, const Settings& settings);

/// A slab key split into the key without the walls and the walls' record (empty if none).
struct SplitKey {
    std::vector<double> rest;
    std::vector<double> walls;
};
SplitKey splitWallsRecord(const std::vector<double>& key);

/// The entries of two walls' records that differ, named after Settings::walls.
std::vector<Difference> compareWallsRecords(const std::vector<double>& inFile,
                                            const std::vector<double>& here);

} // namespace dem
