// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a state file records of its settings and of how its bed was made, and the
// comparisons that name every entry that differs, for the messages of refused files.

#include "dem/Facade.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace dem {

/// One recorded entry that differs between a file and the settings it is read with.
struct Difference {
    std::string name;     ///< e.g. "class 'small' count"
    std::string inFile;   ///< the file's value, as text
    std::string here;     ///< the value asked for now, as text
};

/// The settings a trajectory depends on, flattened as the state file stores them: number of
/// classes, diameter and density of each, contact, box, gravity, dt, the contact law (0
/// linear, 1 HertzMindlin), tangential damping ratio, rolling friction, the walls' and each
/// class's Young's modulus and Poisson's ratio, then, if some pair's or class-wall contact's
/// own coefficient differs from its global entry, the coefficients of every pair of classes
/// a <= b and of every class on the walls (restitution, friction, rolling friction each),
/// then, if some class has a diameter distribution, each class's (its type, the normal's
/// mean, standard deviation, min and max, the samples' count and checksum; a class's
/// diameter entry holds its mean diameter then), and the neighbour skin last (nThreads and impactSpeed, which sets the printed step bounds
/// only, do not count).
std::vector<double> settingsKey(const Settings& s, double skin);

/// The entries of two settings keys that differ, named after `s` (the reader's settings),
/// the skin left out (a state continues with another skin), the moduli too when both laws
/// are linear and kn, kt when both are HertzMindlin (neither law reads them). A key without
/// the own coefficients stands for contacts that all take the global entries; a contact's
/// coefficient is named where it differs and one side has its own. Keys of another number
/// of classes give that one difference.
std::vector<Difference> compareSettingsKeys(const std::vector<double>& inFile,
                                            const std::vector<double>& here, const Settings& s);

/// The entries of two bed recipes that differ, classes named after `s` (this and the bed
/// recipe's other functions below: BedRecord.cpp).
std::vector<Difference> compareRecipes(const BedRecipe& inFile, const BedRecipe& here,
                                       const Settings& s);

/// A recipe's placed particles as a state file stores them: five values each (class index,
/// 1 if random else 0, x, y, z).
std::vector<double> placedRecord(const BedRecipe& recipe);
/// The placed particles of such a record; false if its length is not a multiple of five.
bool placedOfRecord(const std::vector<double>& record, std::vector<PlacedParticle>& placed);

/// A recipe's settle friction as a state file stores it: none (not set) or one value.
std::vector<double> settleFrictionRecord(const BedRecipe& recipe);
/// The settle friction of such a record; false if it holds more than one value.
bool settleFrictionOfRecord(const std::vector<double>& record,
                            std::optional<double>& settleFriction);

/// Counts per class of the particles against those wanted, classes named after `s`.
std::vector<Difference> compareCounts(const std::vector<int>& inFile, const std::vector<int>& here,
                                      const Settings& s);

/// Throws unless a bed can be packed as `recipe` says into a simulation holding `particles`
/// particles (it must be empty; settling time, tolerance and settle friction if set finite
/// and >= 0).
void checkPackBed(std::size_t particles, const BedRecipe& recipe);

/// What differs between a loaded bed and the recipe wanted here: the file's recipe against
/// it if the file has one, else the particles' counts per class (`classIndex` of each).
std::vector<Difference> compareBed(const BedRecipe* inFile, const std::vector<int>& classIndex,
                                   const BedRecipe& here, const Settings& s);

/// "a = 1 in the file, 2 here; b = ..." (empty if there is no difference).
std::string describe(const std::vector<Difference>& differences);

/// Two values as text with the fewest significant digits (6 at least) that tell them
/// apart, so that values that differ never print alike.
std::pair<std::string, std::string> textsApart(double a, double b);

} // namespace dem
