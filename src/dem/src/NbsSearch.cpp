// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "dem/NbsSearch.hpp"

#include <algorithm>
#include <cmath>

namespace dem {

CellMapper::CellMapper(double xMin, double xMax, double yMin, double yMax, double minCellSize)
    : xMin_(xMin), yMin_(yMin)
{
    // As many cells as fit with the minimum size; the cells then stretch to fill the box.
    nColumns_ = std::max(1, static_cast<int>(std::floor((xMax - xMin) / minCellSize)));
    nRows_ = std::max(1, static_cast<int>(std::floor((yMax - yMin) / minCellSize)));
    cellWidth_ = (xMax - xMin) / nColumns_;
    cellHeight_ = (yMax - yMin) / nRows_;
    invWidth_ = 1.0 / cellWidth_;
    invHeight_ = 1.0 / cellHeight_;
}

NbsSearch::NbsSearch(double xMin, double xMax, double yMin, double yMax, double minCellSize)
    : xMin_(xMin), xMax_(xMax), yMin_(yMin), yMax_(yMax), minCellSize_(minCellSize),
      mapper_(xMin, xMax, yMin, yMax, minCellSize)
{
}

void NbsSearch::setMinCellSize(double minCellSize)
{
    minCellSize_ = minCellSize;
    mapper_ = CellMapper(xMin_, xMax_, yMin_, yMax_, minCellSize);
}

template <bool Is3D>
void NbsSearch::walkRows(int first, int last, double margin, std::vector<IndexPair>& pairs) const
{
    const int nColumns = mapper_.nColumns();
    const int* start = cellStart_.data();
    const int* id = id_.data();
    const double* x = x_.data();
    const double* y = y_.data();
    const double* z = z_.data();
    const double* r = r_.data();
    std::size_t m = 0;   // pairs found; `pairs` is kept longer, written without a branch
    if (pairs.size() < 64) pairs.resize(64);
    // Tests sorted particle a against b in [b0, b1): every b is written, the count moves
    // on only for the pairs within reach.
    auto testRange = [&](int a, int b0, int b1) {
        if (b1 <= b0) return;
        if (pairs.size() < m + static_cast<std::size_t>(b1 - b0)) {
            pairs.resize(2 * (m + static_cast<std::size_t>(b1 - b0)));
        }
        IndexPair* out = pairs.data();
        const double xa = x[a], ya = y[a], ra = r[a] + margin;
        const int ia = id[a];
        for (int b = b0; b < b1; ++b) {
            const double dx = x[b] - xa;
            const double dy = y[b] - ya;
            const double reach = ra + r[b];
            double d2 = dx * dx + dy * dy;
            if constexpr (Is3D) {
                const double dz = z[b] - z[a];
                d2 += dz * dz;
            }
            const int ib = id[b];
            out[m] = IndexPair{std::min(ia, ib), std::max(ia, ib)};
            m += d2 < reach * reach;
        }
    };

    // Half stencil: own cell (later entries only) and east, one contiguous range; the
    // south-west, south and south-east cells, another: every neighbouring cell pair once.
    for (int row = first; row < last; ++row) {
        const int rowFirst = row * nColumns;
        if (start[rowFirst] == start[rowFirst + nColumns]) continue;   // an empty row
        for (int col = 0; col < nColumns; ++col) {
            const int c = rowFirst + col;
            const int eastEnd = start[rowFirst + std::min(col + 1, nColumns - 1) + 1];
            int belowBegin = 0, belowEnd = 0;
            if (row > 0) {
                belowBegin = start[c - nColumns + (col > 0 ? -1 : 0)];
                belowEnd = start[c - nColumns + (col + 1 < nColumns ? 2 : 1)];
            }
            for (int a = start[c]; a < start[c + 1]; ++a) {
                testRange(a, a + 1, eastEnd);
                testRange(a, belowBegin, belowEnd);
            }
        }
    }
    pairs.resize(m);
}

void NbsSearch::findPairs(const double* x, const double* y, const double* r, std::size_t n,
                          double margin, std::vector<IndexPair>& pairs, int nThreads)
{
    find<false>(x, y, nullptr, r, n, margin, pairs, nThreads);
}

void NbsSearch::findPairs(const double* x, const double* y, const double* z, const double* r,
                          std::size_t n, double margin, std::vector<IndexPair>& pairs,
                          int nThreads)
{
    find<true>(x, y, z, r, n, margin, pairs, nThreads);
}

template <bool Is3D>
void NbsSearch::find(const double* x, const double* y, const double* z, const double* r,
                     std::size_t n, double margin, std::vector<IndexPair>& pairs, int nThreads)
{
    const int nRows = mapper_.nRows();
    const int nColumns = mapper_.nColumns();
    const std::size_t nCells = static_cast<std::size_t>(nRows) * nColumns;

    // The particles too large for a cell: any pair of two in cells is then within reach of
    // the stencil, r_i + r_j + margin <= minCellSize.
    largeId_.clear();
    isLarge_.assign(n, 0);
    for (std::size_t k = 0; k < n; ++k) {
        if (2.0 * r[k] + margin > minCellSize_) {
            largeId_.push_back(static_cast<int>(k));
            isLarge_[k] = 1;
        }
    }
    const std::size_t nInCells = n - largeId_.size();

    // Counting sort by cell (stable: a cell's particles in increasing index).
    cellStart_.assign(nCells + 1, 0);
    cellOf_.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        if (isLarge_[k]) continue;
        cellOf_[k] = mapper_.cell(x[k], y[k]);
        ++cellStart_[cellOf_[k] + 1];
    }
    for (std::size_t c = 0; c < nCells; ++c) cellStart_[c + 1] += cellStart_[c];
    id_.resize(nInCells);
    x_.resize(nInCells);
    y_.resize(nInCells);
    r_.resize(nInCells);
    z_.resize(Is3D ? nInCells : 0);
    for (std::size_t k = 0; k < n; ++k) {
        if (isLarge_[k]) continue;
        const int q = cellStart_[cellOf_[k]]++;
        id_[q] = static_cast<int>(k);
        x_[q] = x[k];
        y_[q] = y[k];
        r_[q] = r[k];
        if constexpr (Is3D) z_[q] = z[k];
    }
    // The fill moved each start to the next cell's: shift back.
    for (std::size_t c = nCells; c > 0; --c) cellStart_[c] = cellStart_[c - 1];
    cellStart_[0] = 0;

    // Bands of rows with about n / nBands particles each.
    const int nBands = std::max(1, nThreads);
    bandPairs_.resize(nBands);
    std::vector<int> bandStart(nBands + 1, nRows);
    bandStart[0] = 0;
    for (int row = 0, b = 1; row < nRows && b < nBands; ++row) {
        const auto seen = static_cast<std::size_t>(cellStart_[(row + 1) * nColumns]);
        while (b < nBands && seen * nBands >= static_cast<std::size_t>(b) * nInCells) bandStart[b++] = row + 1;
    }

#pragma omp parallel for num_threads(nBands) schedule(static, 1)
    for (int b = 0; b < nBands; ++b) walkRows<Is3D>(bandStart[b], bandStart[b + 1], margin, bandPairs_[b]);

    pairs.clear();
    for (const auto& band : bandPairs_) pairs.insert(pairs.end(), band.begin(), band.end());
    addLargePairs<Is3D>(x, y, z, r, n, margin, pairs);
}

template <bool Is3D>
void NbsSearch::addLargePairs(const double* x, const double* y, const double* z, const double* r,
                              std::size_t n, double margin, std::vector<IndexPair>& pairs) const
{
    for (const int a : largeId_) {
        const double ra = r[a] + margin;
        for (std::size_t k = 0; k < n; ++k) {
            const int b = static_cast<int>(k);
            if (b == a || (isLarge_[k] && b < a)) continue;   // a pair of two large ones once
            const double dx = x[b] - x[a];
            const double dy = y[b] - y[a];
            const double reach = ra + r[b];
            double d2 = dx * dx + dy * dy;
            if constexpr (Is3D) {
                const double dz = z[b] - z[a];
                d2 += dz * dz;
            }
            if (d2 < reach * reach) pairs.push_back(IndexPair{std::min(a, b), std::max(a, b)});
        }
    }
}

std::size_t NbsSearch::memoryBytes() const
{
    std::size_t bytes = sizeof(int) * (cellStart_.capacity() + cellOf_.capacity() + id_.capacity()
                                       + largeId_.capacity())
                        + isLarge_.capacity()
                        + sizeof(double) * (x_.capacity() + y_.capacity() + z_.capacity()
                                            + r_.capacity());
    for (const auto& band : bandPairs_) bytes += sizeof(IndexPair) * band.capacity();
    return bytes;
}

} // namespace dem
