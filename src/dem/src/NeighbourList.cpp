// System's neighbour list: the build (search, history carried over, pair groups, wall
// candidates), the adaptive skin, and the renumbering of the particles by search cell.

#include "dem/System.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include <omp.h>

namespace dem {

namespace {

using Index = std::ptrdiff_t;   // OpenMP loop index

} // namespace

void System::rebuildNeighbourList()
{
    const std::size_t n = p_.size();
    const int ni = static_cast<int>(n);

    const int nThreads = settings_.nThreads;
    const Index npOld = static_cast<Index>(pairs_.size());

    // Old history by particle i (only non-zero entries matter: a zero is a fresh contact).
    // Filled in parallel in any order: a pair (i, j) is in the list once, so the lookup
    // below finds the same entry whatever the order within i's.
    std::vector<int> oldStart(n + 1, 0);
#pragma omp parallel for num_threads(nThreads) schedule(static)
    for (Index k = 0; k < npOld; ++k) {
        if (pairs_.xiT[k] != 0.0) {
#pragma omp atomic
            ++oldStart[pairs_.i[k] + 1];
        }
    }
    for (std::size_t q = 0; q < n; ++q) oldStart[q + 1] += oldStart[q];
    std::vector<int> oldPartner(oldStart[n]);
    std::vector<double> oldXi(oldStart[n]);
    {
        std::vector<int> fill(oldStart.begin(), oldStart.end() - 1);
#pragma omp parallel for num_threads(nThreads) schedule(static)
        for (Index k = 0; k < npOld; ++k) {
            if (pairs_.xiT[k] != 0.0) {
                int slot;
#pragma omp atomic capture
                slot = fill[pairs_.i[k]]++;
                oldPartner[slot] = pairs_.j[k];
                oldXi[slot] = pairs_.xiT[k];
            }
        }
    }

    search_.findPairs(p_.x.data(), p_.y.data(), p_.radius.data(), n, skin_, found_, nThreads);

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
    pairs_.xiT.resize(np);
#pragma omp parallel for num_threads(nThreads) schedule(static)
    for (Index q = 0; q < npi; ++q) {
        const int k = dest[q];
        const int i = found_[q].i;
        const int j = found_[q].j;
        pairs_.i[k] = i;
        pairs_.j[k] = j;
        pairs_.law[k] = p_.classIndex[i] * nClasses_ + p_.classIndex[j];
        double xi = 0.0;
        for (int s = oldStart[i]; s < oldStart[i + 1]; ++s) {
            if (oldPartner[s] == j) {
                xi = oldXi[s];
                break;
            }
        }
        pairs_.xiT[k] = xi;
    }

    // Walls: candidates within radius + skin, history carried over by (particle, wall);
    // counted per particle, then filled, both in parallel.
    const int nWalls = static_cast<int>(walls_.size());
    auto isCandidate = [&](int i, int w) {
        return walls_[w].distance(Eigen::Vector2d(p_.x[i], p_.y[i])) < p_.radius[i] + skin_;
    };
    WallList next;
    next.start.assign(n + 1, 0);
#pragma omp parallel for num_threads(nThreads) schedule(static)
    for (int i = 0; i < ni; ++i) {
        int count = 0;
        for (int w = 0; w < nWalls; ++w) count += isCandidate(i, w);
        next.start[i + 1] = count;
    }
    for (std::size_t q = 0; q < n; ++q) next.start[q + 1] += next.start[q];
    next.wall.resize(next.start[n]);
    next.xiT.resize(next.start[n]);
    const bool haveOld = wallContacts_.start.size() == n + 1;
#pragma omp parallel for num_threads(settings_.nThreads) schedule(static)
    for (int i = 0; i < ni; ++i) {
        int s = next.start[i];
        for (int w = 0; w < nWalls; ++w) {
            if (!isCandidate(i, w)) continue;
            double xi = 0.0;
            if (haveOld) {
                for (int o = wallContacts_.start[i]; o < wallContacts_.start[i + 1]; ++o) {
                    if (wallContacts_.wall[o] == w) xi = wallContacts_.xiT[o];
                }
            }
            next.wall[s] = w;
            next.xiT[s] = xi;
            ++s;
        }
    }
    wallContacts_ = std::move(next);

    p_.xRef = p_.x;
    p_.yRef = p_.y;
    listValid_ = true;
    ++listBuilds_;
    lastBuildStep_ = stepCount_;
}

void System::adaptSkin(double maxDisplacement2)
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

void System::setSkin(double skin)
{
    skin_ = skin;
    search_.setMinCellSize(largestDiameter_ + skin);
}

void System::sortByCell()
{
    const std::size_t n = p_.size();
    if (n == 0) return;
    const CellMapper& cells = search_.mapper();
    const int nCells = cells.nRows() * cells.nColumns();

    // Counting sort by cell (stable: ties keep their order): order[q] = old index of new q.
    std::vector<int> start(static_cast<std::size_t>(nCells) + 1, 0);
    std::vector<int> cellOf(n);
    for (std::size_t i = 0; i < n; ++i) {
        cellOf[i] = cells.row(p_.y[i]) * cells.nColumns() + cells.column(p_.x[i]);
        ++start[cellOf[i] + 1];
    }
    for (int c = 0; c < nCells; ++c) start[c + 1] += start[c];
    std::vector<int> order(n), newIndex(n);
    for (std::size_t i = 0; i < n; ++i) {
        const int q = start[cellOf[i]]++;
        order[q] = static_cast<int>(i);
        newIndex[i] = q;
    }

    p_.forEachArray([&](auto& a) {
        auto sorted = a;
        for (std::size_t q = 0; q < n; ++q) sorted[q] = a[order[q]];
        a = std::move(sorted);
    });

    // Pair history under the new numbers, kept as i < j. The stored tangential displacement
    // is symmetric in i and j (swapping them flips both nHat and the relative velocity, so
    // vRel . tHat is unchanged): no sign to change.
    for (std::size_t k = 0; k < pairs_.size(); ++k) {
        int i = newIndex[pairs_.i[k]];
        int j = newIndex[pairs_.j[k]];
        if (i > j) std::swap(i, j);
        pairs_.i[k] = i;
        pairs_.j[k] = j;
    }

    // Wall history: regroup by the new particle numbers.
    if (wallContacts_.start.size() == n + 1) {
        WallList next;
        next.start.assign(n + 1, 0);
        for (std::size_t q = 0; q < n; ++q) {
            const int i = order[q];
            for (int s = wallContacts_.start[i]; s < wallContacts_.start[i + 1]; ++s) {
                next.wall.push_back(wallContacts_.wall[s]);
                next.xiT.push_back(wallContacts_.xiT[s]);
            }
            next.start[q + 1] = static_cast<int>(next.wall.size());
        }
        wallContacts_ = std::move(next);
    }

    // A fresh list under the new numbers (it carries the remapped history over).
    rebuildNeighbourList();
}

} // namespace dem
