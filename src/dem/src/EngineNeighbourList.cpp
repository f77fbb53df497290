// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The neighbour list of the 2D and slab engines (EngineBase.hpp): its rebuild by NBS with
// the contacts' history carried over, the pairs' groups for the threads, and the skin.

#include "dem/Diameters.hpp"
#include "dem/EngineBase.hpp"
#include "dem/SlabSystem.hpp"
#include "dem/System.hpp"

#include "PairGroups.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include <omp.h>

namespace dem {

namespace {

using Index = std::ptrdiff_t;   // OpenMP loop index

} // namespace

template <class Derived, class Traits>
void EngineBase<Derived, Traits>::rebuildNeighbourList()
{
    const std::size_t n = p_.size();
    const int ni = static_cast<int>(n);

    const int nThreads = threads_;
    const Index npOld = static_cast<Index>(pairs_.size());

    // Old history by particle i (only non-zero entries matter: a zero is a fresh contact).
    // Filled in parallel in any order: a pair (i, j) is in the list once, so the lookup
    // below finds the same entry whatever the order within i's.
    std::vector<int> oldStart(n + 1, 0);
#pragma omp parallel for num_threads(nThreads) schedule(static)
    for (Index k = 0; k < npOld; ++k) {
        if (!Traits::isZero(pairs_.xi[k])) {
#pragma omp atomic
            ++oldStart[pairs_.i[k] + 1];
        }
    }
    for (std::size_t q = 0; q < n; ++q) oldStart[q + 1] += oldStart[q];
    std::vector<int> oldPartner(oldStart[n]);
    std::vector<History> oldXi(oldStart[n]);
    {
        std::vector<int> fill(oldStart.begin(), oldStart.end() - 1);
#pragma omp parallel for num_threads(nThreads) schedule(static)
        for (Index k = 0; k < npOld; ++k) {
            if (!Traits::isZero(pairs_.xi[k])) {
                int slot;
#pragma omp atomic capture
                slot = fill[pairs_.i[k]]++;
                oldPartner[slot] = pairs_.j[k];
                oldXi[slot] = pairs_.xi[k];
            }
        }
    }

    fitSearchCells();
    Traits::findPairs(search_, p_, skin_, found_, nThreads);

    // Stable counting sort of the found pairs into their groups, in parallel over chunks
    // of the found list: a stable sort has one result, whatever the chunks.
    const std::size_t np = found_.size();
    const Index npi = static_cast<Index>(np);
    std::vector<int>& blockOf = blockScratch_;
    blockOf.resize(n);
    for (int b = 0; b < nPairBlocks; ++b) {
        std::fill(blockOf.begin() + pairBlockBegin(b, n), blockOf.begin() + pairBlockBegin(b + 1, n), b);
    }
    auto groupOf = [&](const IndexPair& q) {
        const int bi = blockOf[q.i];
        const int bj = blockOf[q.j];
        return bi == bj ? bi : bj == bi + 1 ? nPairBlocks + bi : nPairGroups - 1;
    };
    std::vector<int>& dest = rebuildScratch_;
    dest.resize(np);
    std::vector<int> chunkCount(static_cast<std::size_t>(nThreads) * nPairGroups, 0);
    pairs_.groupStart.assign(nPairGroups + 1, 0);
#pragma omp parallel num_threads(nThreads)
    {
        const Index t = omp_get_thread_num();
        const Index nt = omp_get_num_threads();
        const Index first = npi * t / nt;
        const Index last = npi * (t + 1) / nt;
        int* count = chunkCount.data() + t * nPairGroups;
        for (Index q = first; q < last; ++q) {
            dest[q] = groupOf(found_[q]);
            ++count[dest[q]];
        }
#pragma omp barrier
#pragma omp single
        {
            // Each chunk's first slot per group: the group's start plus the earlier chunks'.
            int total = 0;
            for (int g = 0; g < nPairGroups; ++g) {
                pairs_.groupStart[g] = total;
                for (Index u = 0; u < nt; ++u) {
                    const int c = chunkCount[u * nPairGroups + g];
                    chunkCount[u * nPairGroups + g] = total;
                    total += c;
                }
            }
            pairs_.groupStart[nPairGroups] = total;
        }
        for (Index q = first; q < last; ++q) dest[q] = count[dest[q]]++;
    }

    pairs_.i.resize(np);
    pairs_.j.resize(np);
    pairs_.law.resize(np);
    pairs_.xi.resize(np);
#pragma omp parallel for num_threads(nThreads) schedule(static)
    for (Index q = 0; q < npi; ++q) {
        const int k = dest[q];
        const int i = found_[q].i;
        const int j = found_[q].j;
        pairs_.i[k] = i;
        pairs_.j[k] = j;
        pairs_.law[k] = p_.classIndex[i] * nClasses_ + p_.classIndex[j];
        History xi = History(Traits::zeroHistory());
        for (int s = oldStart[i]; s < oldStart[i + 1]; ++s) {
            if (oldPartner[s] == j) {
                xi = oldXi[s];
                break;
            }
        }
        pairs_.xi[k] = xi;
    }

    // Walls: candidates within radius + skin, history carried over by (particle, wall);
    // counted per particle, then filled, both in parallel. The engine's walls by its
    // wallCount and wallDistance: a plane's or a cylinder's distance changes by at most the
    // particle's displacement, which the skin covers until the next build.
    const int nWalls = derived().wallCount();
    auto isCandidate = [&](int i, int w) {
        return derived().wallDistance(w, Traits::position(p_, i)) < p_.radius[i] + skin_;
    };
    WallListT<History> next;
    next.start.assign(n + 1, 0);
#pragma omp parallel for num_threads(nThreads) schedule(static)
    for (int i = 0; i < ni; ++i) {
        int count = 0;
        for (int w = 0; w < nWalls; ++w) count += isCandidate(i, w);
        next.start[i + 1] = count;
    }
    for (std::size_t q = 0; q < n; ++q) next.start[q + 1] += next.start[q];
    next.wall.resize(next.start[n]);
    next.xi.resize(next.start[n]);
    const bool haveOld = wallContacts_.start.size() == n + 1;
#pragma omp parallel for num_threads(nThreads) schedule(static)
    for (int i = 0; i < ni; ++i) {
        int s = next.start[i];
        for (int w = 0; w < nWalls; ++w) {
            if (!isCandidate(i, w)) continue;
            History xi = History(Traits::zeroHistory());
            if (haveOld) {
                for (int o = wallContacts_.start[i]; o < wallContacts_.start[i + 1]; ++o) {
                    if (wallContacts_.wall[o] == w) xi = wallContacts_.xi[o];
                }
            }
            next.wall[s] = w;
            next.xi[s] = xi;
            ++s;
        }
    }
    wallContacts_ = std::move(next);

    for (const AxisArrays& a : Traits::axes(p_)) *a.xRef = *a.x;
    listValid_ = true;
    ++listBuilds_;
    lastBuildStep_ = stepCount_;
}

template <class Derived, class Traits>
void EngineBase<Derived, Traits>::adaptSkin(double maxDisplacement2)
{
    const std::int64_t interval = stepCount_ - lastBuildStep_;   // drifts since the build
    if (lastBuildStep_ < 0 || interval < 1) return;   // no build to judge by: keep it
    // The fastest particle moved sqrt(maxDisplacement2) in `interval` steps. At most a
    // factor 2 per build either way.
    const double perStep = std::sqrt(maxDisplacement2) / static_cast<double>(interval);
    const double wanted = std::sqrt(skinCostRatio * smallestDiameter_ * perStep);
    const double next = std::clamp(std::clamp(wanted, 0.5 * skin_, 2.0 * skin_), skinMin_, skinMax_);
    if (next != skin_) setSkin(next);
}

template <class Derived, class Traits>
void EngineBase<Derived, Traits>::setSkin(double skin)
{
    skin_ = skin;
    search_.setMinCellSize(cellDiameter_ + skin);
}

template <class Derived, class Traits>
void EngineBase<Derived, Traits>::fitSearchCells()
{
    const double cellDiameter = searchCellDiameter();
    if (cellDiameter != cellDiameter_) {
        cellDiameter_ = cellDiameter;
        search_.setMinCellSize(cellDiameter_ + skin_);
    }
}

template <class Derived, class Traits>
double EngineBase<Derived, Traits>::searchCellDiameter() const
{
    const std::vector<ParticleClass>& cls = settings_.classes;
    std::vector<std::size_t> count(cls.size(), 0);
    for (const int k : p_.classIndex) ++count[k];
    std::vector<int> order(cls.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
        return dem::largestDiameter(cls[a]) > dem::largestDiameter(cls[b]);
    });
    // The deepest cut in the classes by size, below at most the allowed number of particles,
    // at which the size falls by more than largeRatio.
    const std::size_t allowed = std::min<std::size_t>(
        maxLarge, static_cast<std::size_t>(largeFraction * static_cast<double>(p_.size())));
    double d = largestDiameter_;
    std::size_t above = 0;
    for (std::size_t k = 0; k + 1 < order.size(); ++k) {
        above += count[order[k]];
        if (above > allowed) break;
        const double next = dem::largestDiameter(cls[order[k + 1]]);
        if (dem::largestDiameter(cls[order[k]]) > largeRatio * next) d = next;
    }
    return d;
}

template <class Derived, class Traits>
std::size_t EngineBase<Derived, Traits>::listMemoryBytes() const
{
    std::size_t bytes = search_.memoryBytes() + found_.capacity() * sizeof(IndexPair);
    auto add = [&](const auto& a) { bytes += a.capacity() * sizeof(a[0]); };
    add(pairs_.i); add(pairs_.j); add(pairs_.law); add(pairs_.xi); add(pairs_.groupStart);
    add(wallContacts_.start); add(wallContacts_.wall); add(wallContacts_.xi);
    return bytes;
}

// The members defined here, for both engines (the class itself: EngineBase.cpp)
#define DEM_NEIGHBOUR_LIST_MEMBERS(Derived, Traits)                                   \
    template void EngineBase<Derived, Traits>::rebuildNeighbourList();               \
    template void EngineBase<Derived, Traits>::adaptSkin(double);                    \
    template void EngineBase<Derived, Traits>::setSkin(double);                      \
    template void EngineBase<Derived, Traits>::fitSearchCells();                     \
    template double EngineBase<Derived, Traits>::searchCellDiameter() const;         \
    template std::size_t EngineBase<Derived, Traits>::listMemoryBytes() const;

DEM_NEIGHBOUR_LIST_MEMBERS(System, DiscTraits)
DEM_NEIGHBOUR_LIST_MEMBERS(SlabSystem, SphereTraits)

#undef DEM_NEIGHBOUR_LIST_MEMBERS

} // namespace dem
