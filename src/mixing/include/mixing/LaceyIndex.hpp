// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
/// \file LaceyIndex.hpp
/// \brief Mixing and segregation measures of a binary 2D particle bed: the
///        Lacey mixing index (Norouzi et al. 2012, eqs 8-11; docs/model.md,
///        "Mixing") and vertical/horizontal segregation indices.
///
/// Plain C++17, no OpenFOAM: the laceyIndex function object and the unit
/// tests call the same functions with plain arrays (one entry per particle).
///
/// Conventions shared by every function here:
/// - A particle belongs to the sampled region if its centre lies in the
///   closed rectangle [xMin, xMax] x [yMin, yMax]; particles outside are
///   ignored by every measure.
/// - Exactly two size classes. Class indices are 0 and 1 into
///   `classDiameters`; the class with the smaller diameter is "small" (the
///   paper's flotsam, fraction p), whichever index it has.
/// - Equivalent particles: a small particle counts 1, a large one
///   (d_large/d_small)^3 (4.63 for the paper's 2.5/1.5 mm). With one solid
///   density, equivalent-particle fractions are mass (= volume) fractions.
/// - Invalid settings or inputs throw std::invalid_argument with a message
///   that names the entry and the allowed values. A well-posed input whose
///   measure is undefined (e.g. one class absent from the region) gives NaN
///   for that measure, so that a monitor writing every step never stops.

#include <cstddef>
#include <vector>

namespace mixing
{

/// Axis-aligned rectangle in the plane of the bed (m).
struct Region
{
    double xMin = 0;
    double xMax = 0;
    double yMin = 0;
    double yMax = 0;

    /// Bounding box of the points (x[i], y[i]), i < n. Throws if n == 0.
    static Region boundingBox(std::size_t n, const double* x, const double* y);
};

/// Which number of particles the random-mixture variance SR2 = p q / N uses.
enum class VarianceBasis
{
    /// The paper's N: total number of equivalent particles in the sampled
    /// region (the whole bed by default). Default.
    wholeBed,
    /// Lacey's n: mean number of equivalent particles per occupied sampling
    /// cell, n = (sum over occupied cells of k_i) / (number of occupied cells).
    perSample
};

/// Name of a basis as used in dictionaries and output headers
/// ("wholeBed", "perSample").
const char* toString(VarianceBasis basis);

/// Basis from its name; throws std::invalid_argument naming the allowed
/// values for any other string.
VarianceBasis varianceBasisFromString(const char* name);

/// Settings of the Lacey index.
struct LaceySettings
{
    /// Edge of the square sampling cells (m); the paper's 5 mm. Must be > 0.
    double cellSize = 5e-3;

    /// Sampled region. The grid of cells starts at (xMin, yMin); the last
    /// row and column are cut by xMax, yMax when the size is not a multiple
    /// of cellSize. When useRegion is false the region is the bounding box of
    /// all particle centres (the function object passes the bed's bounds).
    bool useRegion = false;
    Region region;

    /// Random-mixture variance basis; see VarianceBasis.
    VarianceBasis basis = VarianceBasis::wholeBed;
};

/// Lacey index and the quantities it is made of.
struct LaceyResult
{
    double M = 0;       ///< (S02 - S2)/(S02 - SR2); ~1 mixed, 0 segregated
    double S2 = 0;      ///< actual variance: sum k_i (X_i - p)^2 / sum k_i
    double S02 = 0;     ///< fully segregated variance p q
    double SR2 = 0;     ///< random-mixture variance p q / N
    std::size_t nCells = 0;  ///< sampling cells holding at least one particle
    double p = 0;       ///< mass fraction of small particles in the region
    double N = 0;       ///< the N of SR2 (equivalent particles; see basis)
    VarianceBasis basis = VarianceBasis::wholeBed;  ///< basis N follows
    double weightLarge = 0;  ///< equivalent particles per large one
    std::size_t nSmall = 0;  ///< small particles in the region
    std::size_t nLarge = 0;  ///< large particles in the region
};

/// Lacey mixing index of a binary bed.
///
/// In sampling cell i with nS_i small and nL_i large particles (centres in
/// the cell): k_i = nS_i + w nL_i, w = (d_large/d_small)^3, X_i = nS_i/k_i.
/// p = sum nS_i / sum k_i, q = 1 - p, S2 = sum k_i (X_i - p)^2 / sum k_i over
/// occupied cells, S02 = p q, SR2 = p q / N, M = (S02 - S2)/(S02 - SR2).
/// M, S2 are NaN when the region holds no particles; M is NaN when one class
/// is absent (S02 = 0) or N <= 1.
///
/// \param n               number of particles
/// \param x, y            particle centres (m), n entries each
/// \param classIndex      0 or 1 per particle, into classDiameters
/// \param classDiameters  the two class diameters (m), different and > 0
/// \param settings        cell size, region, variance basis
/// \throws std::invalid_argument for a class count other than two, equal or
///         non-positive diameters, a class index other than 0 or 1, a
///         non-positive cell size or an empty region
LaceyResult laceyIndex(std::size_t n, const double* x, const double* y,
                       const int* classIndex,
                       const std::vector<double>& classDiameters,
                       const LaceySettings& settings = {});

/// Lacey index with classes taken from the particle diameters (see
/// classifyByDiameter; there must be exactly two distinct diameters).
LaceyResult laceyIndex(std::size_t n, const double* x, const double* y,
                       const double* diameter,
                       const LaceySettings& settings = {});

/// Size classes found in a list of diameters.
struct SizeClasses
{
    std::vector<double> diameters;  ///< distinct diameters, ascending
    std::vector<int> classIndex;    ///< per particle, into diameters
};

/// Groups diameters that agree within a relative tolerance into classes,
/// numbered by ascending diameter (so 0 is the smallest). Any number of
/// classes is returned; laceyIndex and segregationIndices check for two.
/// \throws std::invalid_argument for a non-positive diameter or relTol < 0
SizeClasses classifyByDiameter(std::size_t n, const double* diameter,
                               double relTol = 1e-6);

/// Segregation indices that tell vertical from horizontal segregation.
///
/// Heights h are measured from the region's floor yMin (the distributor when
/// the region is the bed); distances r = |x - xc| from the region's centre
/// line xc = (xMin + xMax)/2. Per class the plain mean (all particles of a
/// class weigh the same); for all particles together the volume-weighted
/// (d^3) mean, hAll and rAll. Then
///
///   vertical   = (hSmall - hLarge) / hAll
///   horizontal = (rSmall - rLarge) / rAll
///
/// Why these normalisations: for a bed of uniform solids fraction filling
/// heights [0, H] and widths [xc - W/2, xc + W/2], hAll = H/2 and rAll = W/4
/// are the differences that complete segregation gives, whatever the
/// proportions of the classes:
/// - small layer on top of large layer: hLarge = H_L/2, hSmall = H_L + H_S/2,
///   difference (H_L + H_S)/2 = H/2 -> vertical = +1;
/// - large core of width W_c, small in the two wall bands: rLarge = W_c/4,
///   rSmall = (W_c + W)/4, difference W/4 -> horizontal = +1.
/// Values: 0 well mixed (in that direction); +1 complete segregation with the
/// small particles on top (vertical) or at the walls (horizontal), as the
/// paper finds at 1 bar and at 64 bar; negative values the reverse. The
/// estimates H/2 = hAll and W/4 = rAll come from the particles, so the
/// indices need no bed height and stay meaningful when the bed expands.
struct SegregationResult
{
    double hSmall = 0;      ///< mean height of small particles (m)
    double hLarge = 0;      ///< mean height of large particles (m)
    double hAll = 0;        ///< volume-weighted mean height of all (m)
    double rSmall = 0;      ///< mean |x - xc| of small particles (m)
    double rLarge = 0;      ///< mean |x - xc| of large particles (m)
    double rAll = 0;        ///< volume-weighted mean |x - xc| of all (m)
    double vertical = 0;    ///< (hSmall - hLarge)/hAll
    double horizontal = 0;  ///< (rSmall - rLarge)/rAll
    std::size_t nSmall = 0; ///< small particles in the region
    std::size_t nLarge = 0; ///< large particles in the region
};

/// Segregation indices of a binary bed (see SegregationResult). Class means
/// are NaN for an absent class, and then the indices too.
/// \param region  floor, centre line and the particles that count; when
///                null, the bounding box of all particle centres
/// \throws std::invalid_argument as laceyIndex, for the classes and region
SegregationResult segregationIndices(std::size_t n, const double* x,
                                     const double* y, const int* classIndex,
                                     const std::vector<double>& classDiameters,
                                     const Region* region = nullptr);

/// Segregation indices with classes taken from the particle diameters.
SegregationResult segregationIndices(std::size_t n, const double* x,
                                     const double* y, const double* diameter,
                                     const Region* region = nullptr);

} // namespace mixing
