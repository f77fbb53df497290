// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The bed recipe of state files (StateRecord.hpp): its records of the placed particles and
// the settle friction, the check of a recipe before packBed, and the comparisons that name
// every entry in which a bed differs from the recipe asked for.

#include "dem/StateRecord.hpp"

#include "RecordCompare.hpp"

#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace dem {

namespace {

std::string className(const Settings& s, std::size_t k)
{
    return k < s.classes.size() ? "'" + s.classes[k].name + "'" : std::to_string(k);
}

bool sameBox(const Box& a, const Box& b)
{
    const double extent = extentOf(b);
    return sameCoordinate(a.xMin, b.xMin, extent) && sameCoordinate(a.xMax, b.xMax, extent)
           && sameCoordinate(a.yMin, b.yMin, extent) && sameCoordinate(a.yMax, b.yMax, extent);
}

std::pair<std::string, std::string> apart(const Box& a, const Box& b)
{
    const auto [x0a, x0b] = textsApart(a.xMin, b.xMin);
    const auto [x1a, x1b] = textsApart(a.xMax, b.xMax);
    const auto [y0a, y0b] = textsApart(a.yMin, b.yMin);
    const auto [y1a, y1b] = textsApart(a.yMax, b.yMax);
    return {"[" + x0a + ", " + x1a + "] x [" + y0a + ", " + y1a + "] m",
            "[" + x0b + ", " + x1b + "] x [" + y0b + ", " + y1b + "] m"};
}

std::string placedText(const Settings& s, const PlacedParticle& p)
{
    const bool known = p.classIndex >= 0 && p.classIndex < static_cast<int>(s.classes.size());
    const std::string cls = known ? "'" + s.classes[p.classIndex].name + "'"
                                  : std::to_string(p.classIndex);
    if (p.random) return cls + " at random";
    return cls + " at (" + formatValue(p.position.x) + ", " + formatValue(p.position.y)
           + (s.dimension == 3 ? ", " + formatValue(p.position.z) : std::string()) + ") m";
}

bool samePlaced(const PlacedParticle& a, const PlacedParticle& b, int dimension)
{
    if (a.classIndex != b.classIndex || a.random != b.random) return false;
    if (a.random) return true;
    return a.position.x == b.position.x && a.position.y == b.position.y
           && (dimension != 3 || a.position.z == b.position.z);
}

/// A settle friction as messages give it: its value (told apart from `other`'s where both are
/// set), or the contacts' own when not set.
std::string settleFrictionText(const std::optional<double>& mu,
                               const std::optional<double>& other)
{
    if (!mu) return "the contacts' own";
    return other ? textsApart(*mu, *other).first : formatValue(*mu);
}

} // namespace

std::vector<Difference> compareCounts(const std::vector<int>& inFile, const std::vector<int>& here,
                                      const Settings& s)
{
    if (inFile.size() != here.size()) {
        return {{"number of size classes", std::to_string(inFile.size()),
                 std::to_string(here.size())}};
    }
    std::vector<Difference> d;
    for (std::size_t k = 0; k < here.size(); ++k) {
        if (inFile[k] != here[k]) {
            d.push_back({"class " + className(s, k) + " count", std::to_string(inFile[k]),
                         std::to_string(here[k])});
        }
    }
    return d;
}

std::vector<Difference> compareRecipes(const BedRecipe& inFile, const BedRecipe& here,
                                       const Settings& s)
{
    std::vector<Difference> d = compareCounts(inFile.countPerClass, here.countPerClass, s);
    const Box& a = inFile.region;
    const Box& b = here.region;
    if (!sameBox(a, b)) {
        const auto [inA, inB] = apart(a, b);
        d.push_back({"packing region", inA, inB});
    }
    if (inFile.seed != here.seed) {
        d.push_back({"seed", std::to_string(inFile.seed), std::to_string(here.seed)});
    }
    if (inFile.settleTime != here.settleTime) {
        d.push_back(differ("settle time", inFile.settleTime, here.settleTime, " s"));
    }
    if (inFile.keTolerance != here.keTolerance) {
        d.push_back(differ("settling tolerance", inFile.keTolerance, here.keTolerance, " J"));
    }
    if (inFile.settleFriction != here.settleFriction) {
        d.push_back({"settle friction",
                     settleFrictionText(inFile.settleFriction, here.settleFriction),
                     settleFrictionText(here.settleFriction, inFile.settleFriction)});
    }
    if (inFile.placed.size() != here.placed.size()) {
        d.push_back({"placed particles", std::to_string(inFile.placed.size()),
                     std::to_string(here.placed.size())});
    } else {
        for (std::size_t q = 0; q < here.placed.size(); ++q) {
            if (samePlaced(inFile.placed[q], here.placed[q], s.dimension)) continue;
            d.push_back({"placed particle " + std::to_string(q + 1),
                         placedText(s, inFile.placed[q]), placedText(s, here.placed[q])});
        }
    }
    return d;
}

std::vector<double> placedRecord(const BedRecipe& recipe)
{
    std::vector<double> out;
    for (const PlacedParticle& p : recipe.placed) {
        for (double v : {static_cast<double>(p.classIndex), p.random ? 1.0 : 0.0, p.position.x,
                         p.position.y, p.position.z}) {
            out.push_back(v);
        }
    }
    return out;
}

bool placedOfRecord(const std::vector<double>& record, std::vector<PlacedParticle>& placed)
{
    placed.clear();
    if (record.size() % 5 != 0) return false;
    for (std::size_t q = 0; q < record.size(); q += 5) {
        placed.push_back({static_cast<int>(record[q]), record[q + 1] != 0.0,
                          {record[q + 2], record[q + 3], record[q + 4]}});
    }
    return true;
}

std::vector<double> settleFrictionRecord(const BedRecipe& recipe)
{
    return recipe.settleFriction ? std::vector<double>{*recipe.settleFriction}
                                 : std::vector<double>{};
}

bool settleFrictionOfRecord(const std::vector<double>& record, std::optional<double>& settleFriction)
{
    settleFriction.reset();
    if (record.size() > 1) return false;
    if (!record.empty()) settleFriction = record.front();
    return true;
}

void checkPackBed(std::size_t particles, const BedRecipe& recipe)
{
    if (particles != 0) {
        throw Error("packBed: the simulation has " + std::to_string(particles)
                    + " particles already; a bed is packed into an empty one");
    }
    if (!(recipe.settleTime >= 0.0) || !std::isfinite(recipe.settleTime)) {
        throw Error("settle time = " + formatValue(recipe.settleTime) + " s is outside [0, inf)");
    }
    if (!(recipe.keTolerance >= 0.0) || !std::isfinite(recipe.keTolerance)) {
        throw Error("settling tolerance = " + formatValue(recipe.keTolerance)
                    + " J is outside [0, inf)");
    }
    if (recipe.settleFriction
        && (!(*recipe.settleFriction >= 0.0) || !std::isfinite(*recipe.settleFriction))) {
        throw Error("settle friction = " + formatValue(*recipe.settleFriction)
                    + " is outside [0, inf)");
    }
}

std::vector<Difference> compareBed(const BedRecipe* inFile, const std::vector<int>& classIndex,
                                   const BedRecipe& here, const Settings& s)
{
    if (inFile) return compareRecipes(*inFile, here, s);
    // No record of how it was made: its counts per class still show a wrong mix.
    std::vector<int> counts(s.classes.size(), 0);
    for (int k : classIndex) ++counts[static_cast<std::size_t>(k)];
    return compareCounts(counts, here.countPerClass, s);
}

std::string bedDifferences(const Settings& settings, const BedRecipe& inFile,
                           const BedRecipe& here)
{
    return describe(compareRecipes(inFile, here, settings));
}

} // namespace dem
