// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The placed particles of a bed recipe (BedRecipe::placed) laid out before the random
// packing of the rest, for both engines.

#include "dem/Facade.hpp"

#include <vector>

namespace dem {

/// A particle laid out: its class, diameter (m) and centre (m; z 0 in 2D).
struct LaidParticle {
    int classIndex;
    double diameter;
    Vector3 position;
};

/// The recipe's placed particles laid out in their order, each clear of the walls (the
/// region's sides and floor, the slab's front and back and Settings::walls in 3D) and of
/// those before it; their
/// diameters the first of their classes' drawClassDiameters. `drawn[k]` is set to the number
/// of class k's diameters they take. Throws dem::Error naming the placed particle (its
/// number, class and position) and the allowed range: a class outside the classes, more
/// placed particles of a class than its count, a centre outside the region (clear of its
/// walls) or overlapping another placed particle, no room on the floor for a random one.
std::vector<LaidParticle> layPlacedParticles(const Settings& settings, const BedRecipe& recipe,
                                             std::vector<int>& drawn);

/// The message's name of placed particle q: "placed particle 2 (class 'large')".
std::string placedName(const Settings& settings, const BedRecipe& recipe, std::size_t q);

} // namespace dem
