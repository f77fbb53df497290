// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Random packing: random sequential addition of non-overlapping particles in a region,
// largest class first (the small ones then fill the gaps; within a class with a diameter
// distribution the largest diameters first), positions uniform for every class so that the
// mixture is well mixed. Draws come from dem::Random (reproducible): the positions from the
// seed, each class's diameters from a stream of its own (drawClassDiameters). packBed lays
// the placed particles first (Placement.cpp), adds the settling and keeps the recipe, which
// the state file records.

#include "dem/Random.hpp"
#include "dem/StateRecord.hpp"
#include "dem/System.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>

namespace dem {

namespace {

std::string boxText(const Box& b)
{
    return "[" + formatValue(b.xMin) + ", " + formatValue(b.xMax) + "] x [" + formatValue(b.yMin)
           + ", " + formatValue(b.yMax) + "] m";
}

/// Coarse bins for the overlap test of the packing (not the hot loop: vectors are fine).
class PackingGrid {
public:
    PackingGrid(const Box& box, double cell)
        : box_(box), cell_(cell),
          nx_(std::max(1, static_cast<int>((box.xMax - box.xMin) / cell))),
          ny_(std::max(1, static_cast<int>((box.yMax - box.yMin) / cell))),
          bins_(static_cast<std::size_t>(nx_) * ny_)
    {
    }
    int column(double x) const { return std::clamp(static_cast<int>((x - box_.xMin) / cell_), 0, nx_ - 1); }
    int row(double y) const { return std::clamp(static_cast<int>((y - box_.yMin) / cell_), 0, ny_ - 1); }
    void insert(int index, double x, double y) { bins_[row(y) * nx_ + column(x)].push_back(index); }
    template <class F> bool anyNeighbour(double x, double y, F&& overlaps) const
    {
        const int c = column(x), r = row(y);
        for (int rr = std::max(0, r - 1); rr <= std::min(ny_ - 1, r + 1); ++rr) {
            for (int cc = std::max(0, c - 1); cc <= std::min(nx_ - 1, c + 1); ++cc) {
                for (int k : bins_[rr * nx_ + cc]) {
                    if (overlaps(k)) return true;
                }
            }
        }
        return false;
    }

private:
    Box box_;
    double cell_;
    int nx_, ny_;
    std::vector<std::vector<int>> bins_;
};

} // namespace

std::vector<double> restOfClass(const ParticleClass& c, int k, int drawnBefore, int n,
                                std::uint64_t seed)
{
    std::vector<double> d = drawClassDiameters(c, k, drawnBefore + n, seed);
    d.erase(d.begin(), d.begin() + drawnBefore);
    std::stable_sort(d.begin(), d.end(), std::greater<double>());
    return d;
}

void System::packRandom(const std::vector<int>& countPerClass, const Box& region, std::uint64_t seed)
{
    packRest(countPerClass, region, seed, std::vector<int>(settings_.classes.size(), 0));
}

void System::appendAtRest(int cls, double d, const Vector3& position)
{
    checkClass(cls);
    p_.append(cls, d, settings_.classes[cls].density, position.x, position.y, 0.0, 0.0, 0.0);
    listValid_ = false;
    forcesValid_ = false;
}

void System::packRest(const std::vector<int>& countPerClass, const Box& region, std::uint64_t seed,
                      const std::vector<int>& drawnBefore)
{
    if (static_cast<int>(countPerClass.size()) != nClasses_) {
        throw Error("countPerClass has " + std::to_string(countPerClass.size())
                    + " entries, outside [" + std::to_string(nClasses_) + ", "
                    + std::to_string(nClasses_) + "] (one per size class)");
    }
    for (int k = 0; k < nClasses_; ++k) {
        if (countPerClass[k] + drawnBefore[k] < 1) {
            throw Error("countPerClass[" + std::to_string(k) + "] ('" + settings_.classes[k].name
                        + "') = " + std::to_string(countPerClass[k])
                        + " is outside [1, inf): an empty size class");
        }
    }
    const Box& b = settings_.box;
    if (!(region.xMin >= b.xMin && region.xMax <= b.xMax && region.yMin >= b.yMin
          && region.yMax <= b.yMax && region.xMax > region.xMin && region.yMax > region.yMin)) {
        throw Error("packing region " + boxText(region) + " is outside the box " + boxText(b));
    }

    double dMax = 0.0;
    for (const auto& c : settings_.classes) dMax = std::max(dMax, largestDiameter(c));
    for (double d : p_.diameter) dMax = std::max(dMax, d);

    // Existing particles take part in the overlap test.
    std::vector<double> px(p_.x), py(p_.y), pr(p_.radius);
    std::vector<int> pc;
    std::vector<double> pd;   // the new particles' diameters
    PackingGrid grid(b, dMax);
    for (std::size_t k = 0; k < px.size(); ++k) grid.insert(static_cast<int>(k), px[k], py[k]);
    const std::size_t firstNew = px.size();

    const std::vector<int> order = classesLargestFirst(settings_);

    Random random(seed);
    constexpr int maxAttempts = 100000;
    for (int k : order) {
        const double rMax = 0.5 * largestDiameter(settings_.classes[k]);
        if (region.xMax - region.xMin < 2.0 * rMax || region.yMax - region.yMin < 2.0 * rMax) {
            throw Error("packing region " + boxText(region) + " is narrower than a particle of class '"
                        + settings_.classes[k].name + "'");
        }
        const std::vector<double> diameters = restOfClass(settings_.classes[k], k, drawnBefore[k],
                                                          countPerClass[k], seed);
        for (int count = 0; count < countPerClass[k]; ++count) {
            const double r = 0.5 * diameters[count];
            bool placed = false;
            for (int attempt = 0; attempt < maxAttempts && !placed; ++attempt) {
                const double x = random.uniform(region.xMin + r, region.xMax - r);
                const double y = random.uniform(region.yMin + r, region.yMax - r);
                const bool blocked = grid.anyNeighbour(x, y, [&](int q) {
                    const double dx = px[q] - x, dy = py[q] - y;
                    const double reach = pr[q] + r;
                    return dx * dx + dy * dy < reach * reach;
                });
                if (blocked) continue;
                const int index = static_cast<int>(px.size());
                px.push_back(x);
                py.push_back(y);
                pr.push_back(r);
                pc.push_back(k);
                pd.push_back(diameters[count]);
                grid.insert(index, x, y);
                placed = true;
            }
            if (!placed) {
                throw Error("packRandom: no room for particle " + std::to_string(count + 1) + " of "
                            + std::to_string(countPerClass[k]) + " of class '"
                            + settings_.classes[k].name + "' after " + std::to_string(maxAttempts)
                            + " attempts; make the packing region " + boxText(region) + " larger");
            }
        }
    }

    // Number the new particles in horizontal bands, bottom to top, so that neighbours in
    // space are neighbours in memory (cache locality of the settled bed).
    const std::size_t nNew = px.size() - firstNew;
    std::vector<std::size_t> rank(nNew);
    std::iota(rank.begin(), rank.end(), 0);
    auto band = [&](std::size_t q) { return static_cast<long>((py[firstNew + q] - region.yMin) / dMax); };
    std::sort(rank.begin(), rank.end(), [&](std::size_t a, std::size_t c) {
        const long ba = band(a), bc = band(c);
        if (ba != bc) return ba < bc;
        if (px[firstNew + a] != px[firstNew + c]) return px[firstNew + a] < px[firstNew + c];
        return a < c;
    });
    for (std::size_t q : rank) {
        const int k = pc[q];
        p_.append(k, pd[q], settings_.classes[k].density,
                  px[firstNew + q], py[firstNew + q], 0.0, 0.0, 0.0);
    }
    listValid_ = false;
    forcesValid_ = false;
    recipe_.reset();   // packBed sets it once the bed has settled
}

} // namespace dem
