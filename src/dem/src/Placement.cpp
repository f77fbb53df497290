// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Laying a bed recipe's placed particles (Placement.hpp): fixed positions checked, random
// ones drawn on the region's floor, apart from the positions' stream of the packing; in 3D
// both clear of the walls of Settings::walls too.

#include "Placement.hpp"

#include "SlabWalls.hpp"
#include "dem/Random.hpp"

#include <algorithm>
#include <cmath>

namespace dem {

namespace {

std::string positionText(const Vector3& p, bool slab)
{
    return "(" + formatValue(p.x) + ", " + formatValue(p.y)
           + (slab ? ", " + formatValue(p.z) : std::string()) + ") m";
}

double squaredDistance(const Vector3& a, const Vector3& b, bool slab)
{
    const double dx = a.x - b.x, dy = a.y - b.y, dz = slab ? a.z - b.z : 0.0;
    return dx * dx + dy * dy + dz * dz;
}

/// The index of the first laid particle that `p` of diameter d overlaps, or -1. Touching
/// is allowed to round-off (1e-9 of the contact distance).
int overlapped(const std::vector<LaidParticle>& laid, const Vector3& p, double d, bool slab)
{
    for (std::size_t q = 0; q < laid.size(); ++q) {
        const double reach = 0.5 * (d + laid[q].diameter) * (1.0 - 1e-9);
        if (squaredDistance(laid[q].position, p, slab) < reach * reach) return static_cast<int>(q);
    }
    return -1;
}

/// The stream of the random placements: apart from the positions' (the seed itself) and
/// the classes' diameters (diameterSeed(seed, k), k >= 0).
std::uint64_t placementSeed(std::uint64_t seed) { return diameterSeed(seed, -1); }

} // namespace

void checkPlacements(const Settings& settings, const BedRecipe& recipe)
{
    std::vector<int> drawn;
    layPlacedParticles(settings, recipe, drawn);
}

std::string placedName(const Settings& settings, const BedRecipe& recipe, std::size_t q)
{
    const int k = recipe.placed[q].classIndex;
    const bool known = k >= 0 && k < static_cast<int>(settings.classes.size());
    return "placed particle " + std::to_string(q + 1) + " (class "
           + (known ? "'" + settings.classes[k].name + "'" : std::to_string(k)) + ")";
}

std::vector<LaidParticle> layPlacedParticles(const Settings& s, const BedRecipe& recipe,
                                             std::vector<int>& drawn)
{
    const int nClasses = static_cast<int>(s.classes.size());
    drawn.assign(s.classes.size(), 0);
    if (recipe.placed.empty()) return {};
    const bool slab = s.dimension == 3;
    if (recipe.countPerClass.size() != s.classes.size()) {
        throw Error("countPerClass has " + std::to_string(recipe.countPerClass.size())
                    + " entries, outside [" + std::to_string(nClasses) + ", "
                    + std::to_string(nClasses) + "] (one per size class)");
    }
    for (std::size_t q = 0; q < recipe.placed.size(); ++q) {
        const int k = recipe.placed[q].classIndex;
        if (k < 0 || k >= nClasses) {
            throw Error(placedName(s, recipe, q) + ": class index " + std::to_string(k)
                        + " is outside [0, " + std::to_string(nClasses - 1) + "]");
        }
        if (++drawn[k] > recipe.countPerClass[k]) {
            throw Error("class '" + s.classes[k].name + "' has "
                        + std::to_string(std::count_if(recipe.placed.begin(), recipe.placed.end(),
                                                       [&](const PlacedParticle& p) {
                                                           return p.classIndex == k;
                                                       }))
                        + " placed particles, outside [0, "
                        + std::to_string(recipe.countPerClass[k])
                        + "] (its count, which the placed particles are part of)");
        }
    }
    // Each class's diameters in the order drawn: the placed ones take the first
    std::vector<std::vector<double>> diameters(s.classes.size());
    for (int k = 0; k < nClasses; ++k) {
        diameters[k] = drawClassDiameters(s.classes[k], k, drawn[k], recipe.seed);
    }
    std::vector<int> next(s.classes.size(), 0);

    const Box& region = recipe.region;
    const double depth = s.slabDepth;
    Random random(placementSeed(recipe.seed));
    constexpr int maxAttempts = 100000;
    std::vector<LaidParticle> laid;
    // Fixed positions first, then random ones on the floor among them
    for (const bool randomPass : {false, true}) {
        for (std::size_t q = 0; q < recipe.placed.size(); ++q) {
            const PlacedParticle& placed = recipe.placed[q];
            if (placed.random != randomPass) continue;
            const int k = placed.classIndex;
            const double d = diameters[k][next[k]++];
            const double r = 0.5 * d;
            const std::string what = placedName(s, recipe, q);
            if (region.xMax - region.xMin < d || (slab && depth < d)) {
                throw Error(what + " of diameter " + formatValue(d) + " m does not fit in the "
                            "packing region's width " + formatValue(region.xMax - region.xMin)
                            + " m" + (slab ? " or the slab's depth " + formatValue(depth) + " m" : ""));
            }
            if (!randomPass) {
                const Vector3& p = placed.position;
                auto inside = [&](double v, double lo, double hi) { return v >= lo && v <= hi; };
                const bool ok = inside(p.x, region.xMin + r, region.xMax - r)
                                && inside(p.y, region.yMin + r, region.yMax - r)
                                && (!slab || inside(p.z, r, depth - r));
                if (!ok) {
                    throw Error(what + " at " + positionText(p, slab) + " is outside the packing "
                                "region clear of its walls by its radius " + formatValue(r)
                                + " m: allowed x in [" + formatValue(region.xMin + r) + ", "
                                + formatValue(region.xMax - r) + "], y in ["
                                + formatValue(region.yMin + r) + ", " + formatValue(region.yMax - r)
                                + "]" + (slab ? ", z in [" + formatValue(r) + ", "
                                                    + formatValue(depth - r) + "]" : std::string())
                                + " m");
                }
                const int wall = slab ? wallPokedThrough(s, {p.x, p.y, p.z}, r) : -1;
                if (wall >= 0) {
                    throw Error(what + " at " + positionText(p, slab) + " is not clear of "
                                + wallEntryName(s, static_cast<std::size_t>(wall)) + " by its "
                                "radius " + formatValue(r) + " m: "
                                + wallAllowance(s, static_cast<std::size_t>(wall), r));
                }
                const int other = overlapped(laid, p, d, slab);
                if (other >= 0) {
                    throw Error(what + " at " + positionText(p, slab) + " overlaps the one at "
                                + positionText(laid[other].position, slab) + ": allowed a centre "
                                "distance of at least " + formatValue(0.5 * (d + laid[other].diameter))
                                + " m (the sum of their radii)");
                }
                laid.push_back({k, d, slab ? p : Vector3{p.x, p.y, 0.0}});
                continue;
            }
            bool done = false;
            for (int attempt = 0; attempt < maxAttempts && !done; ++attempt) {
                Vector3 p;
                p.x = random.uniform(region.xMin + r, region.xMax - r);
                p.y = region.yMin + r;
                p.z = slab ? random.uniform(r, depth - r) : 0.0;
                if (overlapped(laid, p, d, slab) >= 0) continue;
                if (slab && wallPokedThrough(s, {p.x, p.y, p.z}, r) >= 0) continue;
                laid.push_back({k, d, p});
                done = true;
            }
            if (!done) {
                throw Error(what + ": no room on the floor of the packing region after "
                            + std::to_string(maxAttempts) + " attempts; place fewer particles "
                            "or make the region wider");
            }
        }
    }
    return laid;
}

} // namespace dem
