// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Contact detection on a grid of cells (after NBS, Munjiza & Andrews 1998): the particles
// counting-sorted by cell into contiguous arrays, each tested only against its own and the
// neighbouring cells, which lie in two contiguous ranges of the sorted arrays. A particle
// too large for the cells is left out of the grid and tested against every particle: a few
// large intruders in a bed of small beads then need no cells sized by them.

#include "dem/CellMapper.hpp"

#include <cstddef>
#include <vector>

namespace dem {

/// A candidate pair, i < j.
struct IndexPair {
    int i;
    int j;
};

/// No-binary-search neighbour search over a CellMapper.
class NbsSearch {
public:
    /// Search grid over the rectangle, cells no smaller than the largest diameter + margin.
    NbsSearch(double xMin, double xMax, double yMin, double yMax, double minCellSize);

    /// The same rectangle with cells no smaller than minCellSize (an adaptive skin's).
    void setMinCellSize(double minCellSize);

    /// All pairs with |x_j - x_i| < r_i + r_j + margin, i < j, in a fixed order (the walk's),
    /// replacing the contents of `pairs`.
    /// Rows are walked by up to nThreads threads in bands and the bands' pairs joined in
    /// row order: the same pairs in the same order for any thread count.
    /// The walk: cell by cell, each particle of a cell (in particle order) against the later
    /// ones of its cell and those of the east cell, then of the three cells of the row below.
    /// A particle with 2 r + margin > minCellSize is in no cell: after the walk, each such
    /// particle in index order is tested against all the others in index order (those of
    /// them in no cell only once), n tests each.
    void findPairs(const double* x, const double* y, const double* r, std::size_t n,
                   double margin, std::vector<IndexPair>& pairs, int nThreads = 1);

    /// The same for spheres in a slab: the cells are columns through the whole depth (the
    /// slab is a few diameters deep, so a 2D grid in x-y is as fine as a 3D one could be
    /// where it matters) and a pair is kept by its 3D distance, |x_j - x_i| < r_i + r_j +
    /// margin. Exact: a pair within reach in 3D is within reach in x-y.
    void findPairs(const double* x, const double* y, const double* z, const double* r,
                   std::size_t n, double margin, std::vector<IndexPair>& pairs, int nThreads = 1);

    const CellMapper& mapper() const { return mapper_; }
    /// Heap memory of the search arrays, bytes.
    std::size_t memoryBytes() const;

private:
    /// Pairs of rows [first, last) into `pairs` (the sorted arrays filled).
    template <bool Is3D>
    void walkRows(int first, int last, double margin, std::vector<IndexPair>& pairs) const;
    template <bool Is3D>
    void find(const double* x, const double* y, const double* z, const double* r, std::size_t n,
              double margin, std::vector<IndexPair>& pairs, int nThreads);

    /// Appends the pairs of the particles in no cell (largeId_).
    template <bool Is3D>
    void addLargePairs(const double* x, const double* y, const double* z, const double* r,
                       std::size_t n, double margin, std::vector<IndexPair>& pairs) const;

    double xMin_, xMax_, yMin_, yMax_, minCellSize_;
    CellMapper mapper_;
    std::vector<int> largeId_;      // the particles in no cell, ascending
    std::vector<char> isLarge_;     // by particle index
    // The particles sorted by cell: cell c's are cellStart_[c] .. cellStart_[c + 1]
    std::vector<int> cellStart_, cellOf_, id_;
    std::vector<double> x_, y_, z_, r_;
    std::vector<std::vector<IndexPair>> bandPairs_;   // per band of rows
};

/// Test oracle: every pair tested, O(N^2). Same contract as NbsSearch::findPairs, pairs
/// ordered by (i, j).
void bruteForcePairs(const double* x, const double* y, const double* r, std::size_t n,
                     double margin, std::vector<IndexPair>& pairs);
/// Test oracle in 3D.
void bruteForcePairs(const double* x, const double* y, const double* z, const double* r,
                     std::size_t n, double margin, std::vector<IndexPair>& pairs);

} // namespace dem
