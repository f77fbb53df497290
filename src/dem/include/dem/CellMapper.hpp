#pragma once
// The NBS cell mapper: a uniform grid over the box and the per-row / per-column linked
// lists of Munjiza & Andrews (1998). It only maps; NbsSearch walks what it builds.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace dem {

/// Grid of cells at least minCellSize wide, and head/next linked lists of particles by row
/// and, for one row at a time, by column. Memory is O(N + rows + columns), not O(cells).
class CellMapper {
public:
    /// Grid over [xMin, xMax] x [yMin, yMax] with cells no smaller than minCellSize (m).
    CellMapper(double xMin, double xMax, double yMin, double yMax, double minCellSize);

    int nColumns() const { return nColumns_; }
    int nRows() const { return nRows_; }
    double cellWidth() const { return cellWidth_; }
    double cellHeight() const { return cellHeight_; }

    /// Column of x, clamped to the grid (a particle may poke through a wall by its overlap).
    int column(double x) const { return clampIndex((x - xMin_) * invWidth_, nColumns_); }
    /// Row of y, clamped to the grid.
    int row(double y) const { return clampIndex((y - yMin_) * invHeight_, nRows_); }

    /// Links particles 0..n-1 into per-row lists (rowHead/next), reusing the arrays.
    void linkRows(const double* y, std::size_t n);
    /// First particle of a row list, or -1.
    int rowHead(int r) const { return rowHead_[r]; }
    /// Next particle in the same row list, or -1.
    int rowNext(int i) const { return rowNext_[i]; }

    /// Links the particles of row r into per-column lists of `heads` (length nColumns(),
    /// all -1 on entry); the next-links go into columnNext (length >= n).
    void linkColumns(int r, const double* x, std::vector<int>& heads,
                     std::vector<int>& columnNext) const;
    /// Sets back to -1 the heads that linkColumns(r, ...) set.
    void unlinkColumns(int r, const double* x, std::vector<int>& heads) const;

private:
    static int clampIndex(double s, int n)
    {
        // Compare in floating point first so that NaN or huge values cannot overflow int.
        if (!(s > 0.0)) return 0;
        if (s >= n) return n - 1;
        return static_cast<int>(s);
    }

    double xMin_, yMin_;
    int nColumns_, nRows_;
    double cellWidth_, cellHeight_, invWidth_, invHeight_;
    std::vector<int> rowHead_;
    std::vector<int> rowNext_;
};

} // namespace dem
