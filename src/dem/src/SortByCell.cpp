// System's renumbering of the particles by search cell (the list build itself is
// EngineBase's).

#include "dem/System.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace dem {

void System::sortByCell()
{
    const std::size_t n = p_.size();
    if (n == 0) return;
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

    // Pair history under the new numbers, kept as i < j. The stored tangential displacement
    // is symmetric in i and j (swapping them flips both nHat and the relative velocity, so
    // vRel . tHat is unchanged): no sign to change.
    for (std::size_t k = 0; k < pairs_.size(); ++k) {
        int i = newIndex[pairs_.i[k]];
        int j = newIndex[pairs_.j[k]];
        if (i > j) std::swap(i, j);
        pairs_.i[k] = i;
        pairs_.j[k] = j;
    }

    // Wall history: regroup by the new particle numbers.
    if (wallContacts_.start.size() == n + 1) {
        WallList next;
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

} // namespace dem
