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
    : mapper_(xMin, xMax, yMin, yMax, minCellSize),
      headsThisRow_(mapper_.nColumns(), -1),
      headsRowBelow_(mapper_.nColumns(), -1)
{
}

void NbsSearch::findPairs(const double* x, const double* y, const double* r, std::size_t n,
                          double margin, std::vector<IndexPair>& pairs)
{
    pairs.clear();
    columnNext_.resize(n);
    mapper_.linkRows(y, n);

    const int nColumns = mapper_.nColumns();
    auto test = [&](int i, int j) {
        const double dx = x[j] - x[i];
        const double dy = y[j] - y[i];
        const double reach = r[i] + r[j] + margin;
        if (dx * dx + dy * dy < reach * reach) {
            pairs.push_back(i < j ? IndexPair{i, j} : IndexPair{j, i});
        }
    };
    auto testList = [&](int i, int head) {
        for (int j = head; j >= 0; j = columnNext_[j]) test(i, j);
    };

    // Half stencil: own cell (later entries only), east, and the three cells of the row
    // below (south-west, south, south-east): every neighbouring cell pair is visited once.
    int linkedBelow = -1;   // row whose column lists are in headsRowBelow_, -1 if none
    for (int row = 0; row < mapper_.nRows(); ++row) {
        if (mapper_.rowHead(row) < 0) continue;
        if (linkedBelow != row - 1 && linkedBelow >= 0) {
            mapper_.unlinkColumns(linkedBelow, x, headsRowBelow_);
            linkedBelow = -1;
        }
        mapper_.linkColumns(row, x, headsThisRow_, columnNext_);
        const bool haveBelow = linkedBelow == row - 1;

        for (int i = mapper_.rowHead(row); i >= 0; i = mapper_.rowNext(i)) {
            const int c = mapper_.column(x[i]);
            testList(i, columnNext_[i]);
            if (c + 1 < nColumns) testList(i, headsThisRow_[c + 1]);
            if (haveBelow) {
                if (c > 0) testList(i, headsRowBelow_[c - 1]);
                testList(i, headsRowBelow_[c]);
                if (c + 1 < nColumns) testList(i, headsRowBelow_[c + 1]);
            }
        }

        if (linkedBelow >= 0) mapper_.unlinkColumns(linkedBelow, x, headsRowBelow_);
        std::swap(headsThisRow_, headsRowBelow_);
        linkedBelow = row;
    }
    if (linkedBelow >= 0) mapper_.unlinkColumns(linkedBelow, x, headsRowBelow_);
}

std::size_t NbsSearch::memoryBytes() const
{
    return sizeof(int) * (headsThisRow_.capacity() + headsRowBelow_.capacity()
                          + 2 * columnNext_.capacity()
                          + static_cast<std::size_t>(mapper_.nRows()));
}

} // namespace dem
