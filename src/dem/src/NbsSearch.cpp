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
    rowHead_.assign(nRows_, -1);
}

void CellMapper::linkRows(const double* y, std::size_t n)
{
    std::fill(rowHead_.begin(), rowHead_.end(), -1);
    rowNext_.resize(n);
    // Insert in reverse so that each row list runs in increasing particle index.
    for (std::size_t k = n; k-- > 0;) {
        const int r = row(y[k]);
        rowNext_[k] = rowHead_[r];
        rowHead_[r] = static_cast<int>(k);
    }
}

void CellMapper::linkColumns(int r, const double* x, std::vector<int>& heads,
                             std::vector<int>& columnNext) const
{
    // Pushing at the head reverses the row order; the walk order stays fixed either way.
    for (int i = rowHead_[r]; i >= 0; i = rowNext_[i]) {
        const int c = column(x[i]);
        columnNext[i] = heads[c];
        heads[c] = i;
    }
}

void CellMapper::unlinkColumns(int r, const double* x, std::vector<int>& heads) const
{
    for (int i = rowHead_[r]; i >= 0; i = rowNext_[i]) heads[column(x[i])] = -1;
}

NbsSearch::NbsSearch(double xMin, double xMax, double yMin, double yMax, double minCellSize)
    : xMin_(xMin), xMax_(xMax), yMin_(yMin), yMax_(yMax),
      mapper_(xMin, xMax, yMin, yMax, minCellSize)
{
}

void NbsSearch::setMinCellSize(double minCellSize)
{
    mapper_ = CellMapper(xMin_, xMax_, yMin_, yMax_, minCellSize);
}

template <bool Is3D>
void NbsSearch::walkRows(int first, int last, const double* x, const double* y, const double* r,
                         std::size_t n, double margin, Band& band) const
{
    const int nColumns = mapper_.nColumns();
    band.headsThisRow.assign(nColumns, -1);
    band.headsRowBelow.assign(nColumns, -1);
    band.columnNext.resize(n);
    std::vector<int>& columnNext = band.columnNext;
    std::vector<int>& headsThisRow = band.headsThisRow;
    std::vector<int>& headsRowBelow = band.headsRowBelow;
    std::vector<IndexPair>& pairs = band.pairs;
    pairs.clear();

    auto test = [&](int i, int j) {
        const double dx = x[j] - x[i];
        const double dy = y[j] - y[i];
        const double reach = r[i] + r[j] + margin;
        double d2 = dx * dx + dy * dy;
        if constexpr (Is3D) {
            const double dz = band.z[j] - band.z[i];
            d2 += dz * dz;
        }
        if (d2 < reach * reach) {
            pairs.push_back(i < j ? IndexPair{i, j} : IndexPair{j, i});
        }
    };
    auto testList = [&](int i, int head) {
        for (int j = head; j >= 0; j = columnNext[j]) test(i, j);
    };

    // Half stencil: own cell (later entries only), east, and the three cells of the row
    // below (south-west, south, south-east): every neighbouring cell pair is visited once.
    int linkedBelow = -1;   // row whose column lists are in headsRowBelow, -1 if none
    if (first > 0 && mapper_.rowHead(first - 1) >= 0) {
        mapper_.linkColumns(first - 1, x, headsRowBelow, columnNext);
        linkedBelow = first - 1;
    }
    for (int row = first; row < last; ++row) {
        if (mapper_.rowHead(row) < 0) continue;
        if (linkedBelow != row - 1 && linkedBelow >= 0) {
            mapper_.unlinkColumns(linkedBelow, x, headsRowBelow);
            linkedBelow = -1;
        }
        mapper_.linkColumns(row, x, headsThisRow, columnNext);
        const bool haveBelow = linkedBelow == row - 1;

        for (int i = mapper_.rowHead(row); i >= 0; i = mapper_.rowNext(i)) {
            const int c = mapper_.column(x[i]);
            testList(i, columnNext[i]);
            if (c + 1 < nColumns) testList(i, headsThisRow[c + 1]);
            if (haveBelow) {
                if (c > 0) testList(i, headsRowBelow[c - 1]);
                testList(i, headsRowBelow[c]);
                if (c + 1 < nColumns) testList(i, headsRowBelow[c + 1]);
            }
        }

        if (linkedBelow >= 0) mapper_.unlinkColumns(linkedBelow, x, headsRowBelow);
        std::swap(headsThisRow, headsRowBelow);
        linkedBelow = row;
    }
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
    mapper_.linkRows(y, n);
    const int nRows = mapper_.nRows();
    const int nBands = std::max(1, nThreads);
    bands_.resize(nBands);

    // Bands of rows with about n / nBands particles each.
    rowCount_.assign(nRows, 0);
    for (std::size_t k = 0; k < n; ++k) ++rowCount_[mapper_.row(y[k])];
    std::vector<int> bandStart(nBands + 1, nRows);
    bandStart[0] = 0;
    {
        std::size_t seen = 0;
        int b = 1;
        for (int row = 0; row < nRows && b < nBands; ++row) {
            seen += rowCount_[row];
            while (b < nBands && seen * nBands >= static_cast<std::size_t>(b) * n) bandStart[b++] = row + 1;
        }
    }

#pragma omp parallel for num_threads(nBands) schedule(static, 1)
    for (int b = 0; b < nBands; ++b) {
        bands_[b].z = z;
        walkRows<Is3D>(bandStart[b], bandStart[b + 1], x, y, r, n, margin, bands_[b]);
    }

    pairs.clear();
    for (const Band& band : bands_) pairs.insert(pairs.end(), band.pairs.begin(), band.pairs.end());
}

std::size_t NbsSearch::memoryBytes() const
{
    std::size_t bytes = sizeof(int) * (rowCount_.capacity()
                                       + 2 * static_cast<std::size_t>(mapper_.nRows()));
    for (const Band& b : bands_) {
        bytes += sizeof(int) * (b.headsThisRow.capacity() + b.headsRowBelow.capacity()
                                + b.columnNext.capacity())
                 + sizeof(IndexPair) * b.pairs.capacity();
    }
    return bytes;
}

} // namespace dem
