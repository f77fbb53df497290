// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The slab's random packing: sequential addition in the region through the slab's depth,
// clear of the particles there and of the walls of Settings::walls, largest class first,
// numbered in horizontal bands.

#include "SlabWalls.hpp"
#include "dem/Random.hpp"
#include "dem/SlabSystem.hpp"

#include <algorithm>
#include <numeric>

namespace dem {

void SlabSystem::packRandom(const std::vector<int>& countPerClass, const Box& region,
                            std::uint64_t seed)
{
    packRest(countPerClass, region, seed, std::vector<int>(settings_.classes.size(), 0));
}

void SlabSystem::appendAtRest(int cls, double d, const Vector3& position)
{
    checkClass(cls);
    p_.append(cls, d, settings_.classes[cls].density,
              Eigen::Vector3d(position.x, position.y, position.z), Eigen::Vector3d::Zero(),
              Eigen::Vector3d::Zero());
    listValid_ = false;
    forcesValid_ = false;
}

void SlabSystem::packRest(const std::vector<int>& countPerClass, const Box& region,
                          std::uint64_t seed, const std::vector<int>& drawnBefore)
{
    recipe_.reset();   // packBed sets it once the bed has settled
    if (static_cast<int>(countPerClass.size()) != nClasses_) {
        throw Error("countPerClass has " + std::to_string(countPerClass.size())
                    + " entries, outside [" + std::to_string(nClasses_) + ", "
                    + std::to_string(nClasses_) + "] (one per size class)");
    }
    const Box& b = settings_.box;
    if (!(region.xMin >= b.xMin && region.xMax <= b.xMax && region.yMin >= b.yMin
          && region.yMax <= b.yMax && region.xMax > region.xMin && region.yMax > region.yMin)) {
        throw Error("packing region is outside the box");
    }
    double dMax = 0.0;
    for (const auto& c : settings_.classes) dMax = std::max(dMax, largestDiameter(c));

    // Bins of dMax in x-y through the whole depth (the slab is a few diameters deep).
    const int nx = std::max(1, static_cast<int>((b.xMax - b.xMin) / dMax));
    const int ny = std::max(1, static_cast<int>((b.yMax - b.yMin) / dMax));
    std::vector<std::vector<int>> bins(static_cast<std::size_t>(nx) * ny);
    auto column = [&](double x) { return std::clamp(static_cast<int>((x - b.xMin) / dMax), 0, nx - 1); };
    auto row = [&](double y) { return std::clamp(static_cast<int>((y - b.yMin) / dMax), 0, ny - 1); };
    std::vector<Eigen::Vector3d> pos;
    std::vector<double> rad;
    std::vector<int> cls;
    std::vector<double> diam;   // the new particles' diameters, from firstNew
    for (std::size_t k = 0; k < p_.size(); ++k) {
        bins[row(p_.y[k]) * nx + column(p_.x[k])].push_back(static_cast<int>(pos.size()));
        pos.push_back(p_.position(k));
        rad.push_back(p_.radius[k]);
        cls.push_back(-1);
    }
    const std::size_t firstNew = pos.size();

    const std::vector<int> order = classesLargestFirst(settings_);
    Random random(seed);
    constexpr int maxAttempts = 100000;
    const double depth = settings_.slabDepth;
    // Walls of the settings, a cylinder's say, may cut into the region and the slab
    const bool ownWalls = !settings_.walls.empty();
    for (int k : order) {
        const std::vector<double> diameters = restOfClass(settings_.classes[k], k, drawnBefore[k],
                                                          countPerClass[k], seed);
        for (int count = 0; count < countPerClass[k]; ++count) {
            const double r = 0.5 * diameters[count];
            bool placed = false;
            for (int attempt = 0; attempt < maxAttempts && !placed; ++attempt) {
                const Eigen::Vector3d q(random.uniform(region.xMin + r, region.xMax - r),
                                        random.uniform(region.yMin + r, region.yMax - r),
                                        random.uniform(r, depth - r));
                if (ownWalls && wallPokedThrough(settings_, q, r) >= 0) continue;
                const int c = column(q.x()), rr = row(q.y());
                bool blocked = false;
                for (int y = std::max(0, rr - 1); y <= std::min(ny - 1, rr + 1) && !blocked; ++y) {
                    for (int x = std::max(0, c - 1); x <= std::min(nx - 1, c + 1) && !blocked; ++x) {
                        for (int o : bins[y * nx + x]) {
                            const double reach = rad[o] + r;
                            if ((pos[o] - q).squaredNorm() < reach * reach) {
                                blocked = true;
                                break;
                            }
                        }
                    }
                }
                if (blocked) continue;
                bins[rr * nx + c].push_back(static_cast<int>(pos.size()));
                pos.push_back(q);
                rad.push_back(r);
                cls.push_back(k);
                diam.push_back(diameters[count]);
                placed = true;
            }
            if (!placed) {
                throw Error("packRandom: no room for particle " + std::to_string(count + 1) + " of "
                            + std::to_string(countPerClass[k]) + " of class '"
                            + settings_.classes[k].name + "' after " + std::to_string(maxAttempts)
                            + " attempts; make the packing region larger");
            }
        }
    }
    // Numbered in horizontal bands bottom to top, as System::packRandom (cache locality).
    std::vector<std::size_t> rank(pos.size() - firstNew);
    std::iota(rank.begin(), rank.end(), firstNew);
    auto band = [&](std::size_t q) { return static_cast<long>((pos[q].y() - region.yMin) / dMax); };
    std::sort(rank.begin(), rank.end(), [&](std::size_t a, std::size_t c) {
        if (band(a) != band(c)) return band(a) < band(c);
        if (pos[a].x() != pos[c].x()) return pos[a].x() < pos[c].x();
        return a < c;
    });
    for (std::size_t q : rank) {
        p_.append(cls[q], diam[q - firstNew], settings_.classes[cls[q]].density,
                  pos[q], Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
    }
    listValid_ = false;
    forcesValid_ = false;
}

} // namespace dem
