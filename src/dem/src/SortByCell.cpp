// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The engines' renumbering of the particles by search cell (the list build itself is
// EngineBase's).

#include "dem/EngineBase.hpp"
#include "dem/SlabSystem.hpp"
#include "dem/System.hpp"

#include <algorithm>
#include <cstddef>

namespace dem {

template <class Derived, class Traits>
void EngineBase<Derived, Traits>::sortByCell()
{
    const std::size_t n = p_.size();
    if (n == 0) return;
    fitSearchCells();
    const CellMapper& cells = search_.mapper();
    const int nCells = cells.nRows() * cells.nColumns();

    // Counting sort by cell (stable: ties keep their order): order[q] = old index of new q.
    std::vector<int> start(static_cast<std::size_t>(nCells) + 1, 0);
    std::vector<int> cellOf(n);
    for (std::size_t i = 0; i < n; ++i) {
        cellOf[i] = cells.row(p_.y[i]) * cells.nColumns() + cells.column(p_.x[i]);
        ++start[cellOf[i] + 1];
    }
    for (int c = 0; c < nCells; ++c) start[c + 1] += start[c];
    std::vector<int> order(n), newIndex(n);
    for (std::size_t i = 0; i < n; ++i) {
        const int q = start[cellOf[i]]++;
        order[q] = static_cast<int>(i);
        newIndex[i] = q;
    }

    p_.forEachArray([&](auto& a) {
        auto sorted = a;
        for (std::size_t q = 0; q < n; ++q) sorted[q] = a[order[q]];
        a = std::move(sorted);
    });

    // Pair history under the new numbers, kept as i < j; a pair whose partners swap takes
    // the history as seen from the other partner (Traits::swapped).
    for (std::size_t k = 0; k < pairs_.size(); ++k) {
        const int i = newIndex[pairs_.i[k]];
        const int j = newIndex[pairs_.j[k]];
        pairs_.i[k] = std::min(i, j);
        pairs_.j[k] = std::max(i, j);
        if (i > j) pairs_.xi[k] = Traits::swapped(pairs_.xi[k]);
    }

    // Wall history: regroup by the new particle numbers.
    if (wallContacts_.start.size() == n + 1) {
        WallListT<History> next;
        next.start.assign(n + 1, 0);
        for (std::size_t q = 0; q < n; ++q) {
            const int i = order[q];
            for (int s = wallContacts_.start[i]; s < wallContacts_.start[i + 1]; ++s) {
                next.wall.push_back(wallContacts_.wall[s]);
                next.xi.push_back(wallContacts_.xi[s]);
            }
            next.start[q + 1] = static_cast<int>(next.wall.size());
        }
        wallContacts_ = std::move(next);
    }

    // A fresh list under the new numbers (it carries the remapped history over).
    rebuildNeighbourList();
}

template void EngineBase<System, DiscTraits>::sortByCell();
template void EngineBase<SlabSystem, SphereTraits>::sortByCell();

} // namespace dem
