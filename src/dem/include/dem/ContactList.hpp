// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Candidate contacts from the last neighbour-list build, each with its contact history,
// ordered in blocks of particles so that threads can add pair forces without races.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace dem {

/// Blocks of consecutive particle numbers (as numbered when the list was built). A fixed
/// number, not the thread count: the order in which a particle receives its pair forces
/// depends on the blocks only, so any number of threads gives the same bits.
constexpr int nPairBlocks = 8;

/// Groups of pairs, in the order their forces are added: the pairs within each block
/// (groups 0-7, in parallel), the pairs across the boundary of blocks m and m + 1 (group
/// 8 + m; even m in parallel, then odd m: two groups of one phase share no particle),
/// and the rest (the last group, on one thread).
constexpr int nPairGroups = 2 * nPairBlocks;

/// Block of particle i out of n.
inline int pairBlock(int i, std::size_t n)
{
    return static_cast<int>(static_cast<std::int64_t>(i) * nPairBlocks
                            / static_cast<std::int64_t>(n));
}

/// First particle of block b (b = nPairBlocks: n).
inline std::size_t pairBlockBegin(int b, std::size_t n)
{
    return (static_cast<std::size_t>(b) * n + nPairBlocks - 1) / nPairBlocks;
}

/// Group of the pair (i, j), i < j, out of n particles.
inline int pairGroup(int i, int j, std::size_t n)
{
    const int bi = pairBlock(i, n);
    const int bj = pairBlock(j, n);
    if (bi == bj) return bi;
    if (bj == bi + 1) return nPairBlocks + bi;
    return nPairGroups - 1;
}

/// Particle-particle candidates (i < j) as arrays; a candidate keeps its tangential
/// history while it touches and has it reset to zero when it separates. History: a scalar
/// along tHat in 2D, a 3-vector in the slab.
///
/// Order: group g's pairs are groupStart[g] .. groupStart[g+1], each group in the search's
/// order. With particles numbered by cell (sortByCell, or the packing's bands) nearly all
/// pairs lie within a block or across neighbouring blocks.
template <class History> struct PairListT {
    std::vector<int> i, j;
    std::vector<int> law;          ///< index into the pair-law table
    std::vector<History> xi;       ///< tangential spring displacement, m (history)
    std::vector<int> groupStart;   ///< nPairGroups + 1 entries

    std::size_t size() const { return i.size(); }
};

/// Particle-wall candidates grouped by particle: particle p's are start[p] .. start[p+1].
template <class History> struct WallListT {
    std::vector<int> start;
    std::vector<int> wall;
    std::vector<History> xi;       ///< tangential spring displacement, m (history)

    std::size_t size() const { return wall.size(); }
};

using PairList = PairListT<double>;
using WallList = WallListT<double>;

} // namespace dem
