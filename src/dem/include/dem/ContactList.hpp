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

/// Block of particle i out of n.
inline int pairBlock(int i, std::size_t n)
{
    return static_cast<int>(static_cast<std::int64_t>(i) * nPairBlocks
                            / static_cast<std::int64_t>(n));
}

/// Particle-particle candidates (i < j) as arrays; a candidate keeps its tangential
/// history while it touches and has it reset to zero when it separates.
///
/// Order: the pairs with both particles in block b are blockStart[b] .. blockStart[b+1]
/// (b < nPairBlocks), in the search's order; the pairs across blocks follow, from
/// blockStart[nPairBlocks] to size(). Threads take whole blocks, each adding forces only to
/// its own particles; the pairs across blocks come after, on one thread. With particles
/// numbered by cell (sortByCell) these are the few pairs that straddle 7 lines of the bed.
struct PairList {
    std::vector<int> i, j;
    std::vector<int> law;          ///< index into the pair-law table
    std::vector<double> xiT;       ///< tangential spring displacement, m (history)
    std::vector<int> blockStart;   ///< nPairBlocks + 1 entries

    std::size_t size() const { return i.size(); }
};

/// Particle-wall candidates grouped by particle: particle p's are start[p] .. start[p+1].
struct WallList {
    std::vector<int> start;
    std::vector<int> wall;
    std::vector<double> xiT;       ///< tangential spring displacement, m (history)

    std::size_t size() const { return wall.size(); }
};

} // namespace dem
