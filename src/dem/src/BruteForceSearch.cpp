// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "dem/NbsSearch.hpp"

namespace dem {

void bruteForcePairs(const double* x, const double* y, const double* r, std::size_t n,
                     double margin, std::vector<IndexPair>& pairs)
{
    pairs.clear();
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = i + 1; j < n; ++j) {
            const double dx = x[j] - x[i];
            const double dy = y[j] - y[i];
            const double reach = r[i] + r[j] + margin;
            if (dx * dx + dy * dy < reach * reach) {
                pairs.push_back({static_cast<int>(i), static_cast<int>(j)});
            }
        }
    }
}

void bruteForcePairs(const double* x, const double* y, const double* z, const double* r,
                     std::size_t n, double margin, std::vector<IndexPair>& pairs)
{
    pairs.clear();
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = i + 1; j < n; ++j) {
            const double dx = x[j] - x[i];
            const double dy = y[j] - y[i];
            const double dz = z[j] - z[i];
            const double reach = r[i] + r[j] + margin;
            if (dx * dx + dy * dy + dz * dz < reach * reach) {
                pairs.push_back({static_cast<int>(i), static_cast<int>(j)});
            }
        }
    }
}

} // namespace dem
