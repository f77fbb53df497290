#pragma once
// Candidate contacts from the last neighbour-list build, each with its contact history,
// and the per-particle index that gathers pair forces in a fixed order.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace dem {

/// Force of one pair from the last evaluation, stored together for the gather.
struct StoredForce {
    double fx, fy;   ///< on i (j receives the opposite), N
    double ft;       ///< tangential force along tHat; torque on either partner is r ft, N
};

/// Particle-particle candidates (i < j) as arrays; a candidate keeps its tangential
/// history while it touches and has it reset to zero when it separates.
struct PairList {
    std::vector<int> i, j;
    std::vector<int> law;          ///< index into the pair-law table
    std::vector<double> xiT;       ///< tangential spring displacement, m (history)
    std::vector<StoredForce> force;   ///< of the last evaluation
    /// Gather index: particle p's pairs are entries[start[p] .. start[p+1]), each
    /// 2 * pair + (0 if p is i, 1 if p is j), in pair order.
    std::vector<int> start, entries;

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
