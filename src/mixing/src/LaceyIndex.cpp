// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "mixing/LaceyIndex.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace mixing
{

namespace
{

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

[[noreturn]] void invalid(const std::string& message)
{
    throw std::invalid_argument("mixing: " + message);
}

/// The two classes in a checked form: which index is small, and the
/// equivalent-particle weight of each index.
struct BinaryClasses
{
    int small = 0;
    double weight[2] = {1, 1};  ///< equivalent particles per particle
    double volume[2] = {1, 1};  ///< relative volume d^3 per particle
};

BinaryClasses checkClasses(const std::vector<double>& classDiameters)
{
    if (classDiameters.size() != 2)
    {
        invalid("classDiameters: " + std::to_string(classDiameters.size())
              + " size classes given; allowed: exactly 2 (small and large)");
    }
    const double d0 = classDiameters[0];
    const double d1 = classDiameters[1];
    if (!(d0 > 0) || !(d1 > 0))
    {
        invalid("classDiameters: (" + std::to_string(d0) + ", "
              + std::to_string(d1) + "); allowed: two diameters > 0");
    }
    if (d0 == d1)
    {
        invalid("classDiameters: both " + std::to_string(d0)
              + "; allowed: two different diameters");
    }
    BinaryClasses c;
    c.small = d0 < d1 ? 0 : 1;
    const double dSmall = std::min(d0, d1);
    const double dLarge = std::max(d0, d1);
    c.weight[c.small] = 1;
    c.weight[1 - c.small] = std::pow(dLarge/dSmall, 3);
    c.volume[0] = std::pow(d0/dSmall, 3);
    c.volume[1] = std::pow(d1/dSmall, 3);
    return c;
}

void checkArrays(std::size_t n, const double* x, const double* y,
                 const void* third, const char* thirdName)
{
    if (n > 0 && (!x || !y || !third))
    {
        invalid(std::string("null array among x, y, ") + thirdName
              + " for " + std::to_string(n) + " particles; allowed: arrays of n entries");
    }
}

int checkedClass(const int* classIndex, std::size_t i)
{
    const int c = classIndex[i];
    if (c != 0 && c != 1)
    {
        invalid("classIndex[" + std::to_string(i) + "] = " + std::to_string(c)
              + "; allowed: 0 or 1 (index into classDiameters)");
    }
    return c;
}

Region checkedRegion(const Region& r)
{
    if (!(r.xMax >= r.xMin) || !(r.yMax >= r.yMin))
    {
        invalid("region: (" + std::to_string(r.xMin) + " " + std::to_string(r.yMin)
              + ") (" + std::to_string(r.xMax) + " " + std::to_string(r.yMax)
              + "); allowed: xMin <= xMax and yMin <= yMax");
    }
    return r;
}

bool inside(const Region& r, double x, double y)
{
    return x >= r.xMin && x <= r.xMax && y >= r.yMin && y <= r.yMax;
}

} // namespace


Region Region::boundingBox(std::size_t n, const double* x, const double* y)
{
    if (n == 0)
    {
        invalid("region: no particles to take a bounding box of; "
                "allowed: at least one particle, or give the region");
    }
    checkArrays(n, x, y, x, "x");
    Region r{x[0], x[0], y[0], y[0]};
    for (std::size_t i = 1; i < n; ++i)
    {
        r.xMin = std::min(r.xMin, x[i]);
        r.xMax = std::max(r.xMax, x[i]);
        r.yMin = std::min(r.yMin, y[i]);
        r.yMax = std::max(r.yMax, y[i]);
    }
    return r;
}


const char* toString(VarianceBasis basis)
{
    return basis == VarianceBasis::perSample ? "perSample" : "wholeBed";
}


VarianceBasis varianceBasisFromString(const char* name)
{
    if (name && std::strcmp(name, "wholeBed") == 0)
    {
        return VarianceBasis::wholeBed;
    }
    if (name && std::strcmp(name, "perSample") == 0)
    {
        return VarianceBasis::perSample;
    }
    invalid(std::string("varianceBasis: '") + (name ? name : "")
          + "'; allowed: wholeBed (the paper's N, default) or perSample (Lacey's n)");
}


LaceyResult laceyIndex(std::size_t n, const double* x, const double* y,
                       const int* classIndex,
                       const std::vector<double>& classDiameters,
                       const LaceySettings& settings)
{
    const BinaryClasses classes = checkClasses(classDiameters);
    checkArrays(n, x, y, classIndex, "classIndex");
    const double h = settings.cellSize;
    if (!(h > 0) || !std::isfinite(h))
    {
        invalid("cellSize: " + std::to_string(h) + "; allowed: a finite size > 0 (m)");
    }

    LaceyResult res;
    res.basis = settings.basis;
    res.weightLarge = classes.weight[1 - classes.small];
    if (!settings.useRegion && n == 0)
    {
        res.M = res.S2 = res.S02 = res.SR2 = res.p = nan;
        return res;
    }
    const Region region = settings.useRegion
        ? checkedRegion(settings.region) : Region::boundingBox(n, x, y);

    // Cells numbered row by row; a particle on the upper edge goes into the
    // last row/column.
    // Cell (ix, iy) = floor of the offset over h, numbered row by row; the
    // last row and column also take centres on the region's upper edges.
    auto nCellsAlong = [h](double length) {
        return static_cast<std::size_t>(std::max(1.0, std::ceil(length/h)));
    };
    const std::size_t nx = nCellsAlong(region.xMax - region.xMin);
    const std::size_t ny = nCellsAlong(region.yMax - region.yMin);
    struct Counts { std::size_t small = 0, large = 0; };
    std::unordered_map<std::size_t, Counts> cells;
    for (std::size_t i = 0; i < n; ++i)
    {
        const int c = checkedClass(classIndex, i);
        if (!inside(region, x[i], y[i]))
        {
            continue;
        }
        const std::size_t ix =
            std::min(nx - 1, static_cast<std::size_t>((x[i] - region.xMin)/h));
        const std::size_t iy =
            std::min(ny - 1, static_cast<std::size_t>((y[i] - region.yMin)/h));
        Counts& cell = cells[iy*nx + ix];
        if (c == classes.small) { ++cell.small; ++res.nSmall; }
        else { ++cell.large; ++res.nLarge; }
    }

    res.nCells = cells.size();
    const double w = res.weightLarge;
    const double K = double(res.nSmall) + w*double(res.nLarge);
    if (res.nCells == 0)
    {
        res.M = res.S2 = res.S02 = res.SR2 = res.p = nan;
        return res;
    }
    res.p = double(res.nSmall)/K;
    double sum = 0;
    for (const auto& entry : cells)
    {
        const Counts& cell = entry.second;
        const double k = double(cell.small) + w*double(cell.large);
        const double X = double(cell.small)/k;
        sum += k*(X - res.p)*(X - res.p);
    }
    res.S2 = sum/K;
    res.S02 = res.p*(1 - res.p);
    res.N = settings.basis == VarianceBasis::wholeBed ? K : K/double(res.nCells);
    res.SR2 = res.S02/res.N;
    res.M = (res.S02 > 0 && res.N > 1) ? (res.S02 - res.S2)/(res.S02 - res.SR2) : nan;
    return res;
}


SizeClasses classifyByDiameter(std::size_t n, const double* diameter, double relTol)
{
    if (!(relTol >= 0))
    {
        invalid("relTol: " + std::to_string(relTol) + "; allowed: >= 0");
    }
    if (n > 0 && !diameter)
    {
        invalid("null diameter array; allowed: an array of n entries");
    }
    SizeClasses sc;
    std::vector<double> sorted(diameter, diameter + n);
    for (std::size_t i = 0; i < n; ++i)
    {
        if (!(diameter[i] > 0) || !std::isfinite(diameter[i]))
        {
            invalid("diameter[" + std::to_string(i) + "] = "
                  + std::to_string(diameter[i]) + "; allowed: a finite diameter > 0 (m)");
        }
    }
    std::sort(sorted.begin(), sorted.end());
    for (const double d : sorted)
    {
        if (sc.diameters.empty() || d > sc.diameters.back()*(1 + relTol))
        {
            sc.diameters.push_back(d);
        }
    }
    sc.classIndex.resize(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        // The class is the last representative not above d (1 + relTol).
        const auto it = std::upper_bound(sc.diameters.begin(), sc.diameters.end(),
                                         diameter[i]);
        sc.classIndex[i] = int(it - sc.diameters.begin()) - 1;
    }
    return sc;
}


LaceyResult laceyIndex(std::size_t n, const double* x, const double* y,
                       const double* diameter, const LaceySettings& settings)
{
    const SizeClasses sc = classifyByDiameter(n, diameter);
    return laceyIndex(n, x, y, sc.classIndex.data(), sc.diameters, settings);
}


SegregationResult segregationIndices(std::size_t n, const double* x,
                                     const double* y, const int* classIndex,
                                     const std::vector<double>& classDiameters,
                                     const Region* region)
{
    const BinaryClasses classes = checkClasses(classDiameters);
    checkArrays(n, x, y, classIndex, "classIndex");

    SegregationResult res;
    if (!region && n == 0)
    {
        res.hSmall = res.hLarge = res.hAll = res.rSmall = res.rLarge = res.rAll
            = res.vertical = res.horizontal = nan;
        return res;
    }
    const Region r = region ? checkedRegion(*region) : Region::boundingBox(n, x, y);
    const double xc = 0.5*(r.xMin + r.xMax);

    double sumH[2] = {0, 0}, sumR[2] = {0, 0};
    std::size_t count[2] = {0, 0};
    for (std::size_t i = 0; i < n; ++i)
    {
        const int c = checkedClass(classIndex, i);
        if (!inside(r, x[i], y[i]))
        {
            continue;
        }
        sumH[c] += y[i] - r.yMin;
        sumR[c] += std::abs(x[i] - xc);
        ++count[c];
    }
    const int s = classes.small;
    const int l = 1 - s;
    res.nSmall = count[s];
    res.nLarge = count[l];
    auto mean = [](double sum, std::size_t k) { return k ? sum/double(k) : nan; };
    res.hSmall = mean(sumH[s], count[s]);
    res.hLarge = mean(sumH[l], count[l]);
    res.rSmall = mean(sumR[s], count[s]);
    res.rLarge = mean(sumR[l], count[l]);
    const double V = classes.volume[0]*double(count[0]) + classes.volume[1]*double(count[1]);
    res.hAll = V > 0 ? (classes.volume[0]*sumH[0] + classes.volume[1]*sumH[1])/V : nan;
    res.rAll = V > 0 ? (classes.volume[0]*sumR[0] + classes.volume[1]*sumR[1])/V : nan;
    res.vertical = (res.hSmall - res.hLarge)/res.hAll;
    res.horizontal = (res.rSmall - res.rLarge)/res.rAll;
    return res;
}


SegregationResult segregationIndices(std::size_t n, const double* x,
                                     const double* y, const double* diameter,
                                     const Region* region)
{
    const SizeClasses sc = classifyByDiameter(n, diameter);
    return segregationIndices(n, x, y, sc.classIndex.data(), sc.diameters, region);
}

} // namespace mixing
