// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The search grid: a uniform grid of cells over the box (NbsSearch sorts the particles by
// its cells; System::sortByCell numbers them in its order).

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace dem {

/// Grid of cells at least minCellSize wide, numbered row by row.
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

    /// Cell of (x, y), row by row: row(y) nColumns() + column(x).
    int cell(double x, double y) const { return row(y) * nColumns_ + column(x); }

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
};

} // namespace dem
