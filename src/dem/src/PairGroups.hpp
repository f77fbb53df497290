// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The thread loop over the pair groups of ContactList.hpp, shared by the 2D and slab
// engines' pair forces (internal: the OpenMP pragmas stay in the library's sources).

#include "dem/ContactList.hpp"

#include <cstddef>
#include <utility>

#include <omp.h>

namespace dem {

/// The calling thread's share [first, last) of n particles in an OpenMP parallel region:
/// the same for every loop of the region, so the loops need no barrier between them.
inline std::pair<std::ptrdiff_t, std::ptrdiff_t> threadShare(std::ptrdiff_t n)
{
    const std::ptrdiff_t nThreads = omp_get_num_threads();
    const std::ptrdiff_t thread = omp_get_thread_num();
    return {n * thread / nThreads, n * (thread + 1) / nThreads};
}

/// Runs group(g, touching, maxOverlap) over every pair group: the blocks (each after
/// zeroBlock(first, last) of its particles' sums, by the thread that sums them and kicks
/// them next, so the sums stay in its core's cache), then the boundaries between even and
/// odd blocks, then between odd and even ones, in parallel; the last group on one thread.
/// Groups that run together share no particle, so a particle gets its forces in the same
/// order whatever the thread count. Returns the touching count and the largest overlap.
template <class ZeroBlock, class Group>
void sumPairGroups(int nThreads, std::size_t n, ZeroBlock&& zeroBlock, Group&& group,
                   std::size_t& touchingOut, double& maxOverlapOut)
{
    std::size_t touching = 0;
    double maxOverlap = 0.0;
#pragma omp parallel num_threads(nThreads) reduction(+ : touching) reduction(max : maxOverlap)
    {
#pragma omp for schedule(static)
        for (int b = 0; b < nPairBlocks; ++b) {
            zeroBlock(pairBlockBegin(b, n), pairBlockBegin(b + 1, n));
            group(b, touching, maxOverlap);
        }
#pragma omp for schedule(static)
        for (int m = 0; m < nPairBlocks - 1; m += 2) group(nPairBlocks + m, touching, maxOverlap);
#pragma omp for schedule(static)
        for (int m = 1; m < nPairBlocks - 1; m += 2) group(nPairBlocks + m, touching, maxOverlap);
    }
    group(nPairGroups - 1, touching, maxOverlap);
    touchingOut = touching;
    maxOverlapOut = maxOverlap;
}

} // namespace dem
