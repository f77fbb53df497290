// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Older state files from a current one (OlderStateFiles.hpp): the current layout walked
// (StateFile::write, SlabSystem::save), then each version's changes undone.

#include "OlderStateFiles.hpp"

#include "StateIntegrity.hpp"

#include <cstring>

namespace dem::test {

namespace {

void resign(std::string& b)
{
    put(b, b.size() - 24, fnv1a64(b.data(), b.size() - 24));
}

/// The settings key at `at` of a current state in the earlier versions' layout: without the
/// contact law, tangential damping ratio, rolling friction, the walls' moduli (6 values)
/// and each class's moduli (2 per class) that sit before its last entry.
std::string previousKey(const std::string& b, std::size_t at)
{
    const auto n = get<std::uint64_t>(b, at);
    const auto classes = static_cast<std::uint64_t>(get<double>(b, at + 8));
    const std::uint64_t added = 6 + 2 * classes;
    std::string key = b.substr(at, 8 + 8 * n);
    key.erase(8 + 8 * (n - 1 - added), 8 * added);
    put(key, 0, n - added);
    return key;
}

/// The key at `at` of `b` put in the earlier layout in `old`.
void shortenKey(std::string& old, const std::string& b, std::size_t at)
{
    old.replace(at, 8 + 8 * get<std::uint64_t>(b, at), previousKey(b, at));
}

} // namespace

std::string olderDisc(const std::string& b, std::uint32_t version, std::string& expected)
{
    const Layout l(b, 2);
    std::string old = b;
    expected = b;
    if (version == 2) {
        // Pair forces (3 doubles), a per-particle start (n + 1) and entries (2 per pair) in
        // place of the groups; the converter makes the list invalid and drops the groups.
        std::string index;
        auto array = [&](std::uint64_t n, std::size_t element) {
            index.append(reinterpret_cast<const char*>(&n), 8);
            index.append(n * element, '\x5a');
        };
        array(l.pairCount, 24);
        array(l.particles + 1, 4);
        array(2 * l.pairCount, 4);
        old.replace(l.groupStart, l.groupStartEnd - l.groupStart, index);
        expected.replace(l.groupStart, l.groupStartEnd - l.groupStart, std::string(8, '\0'));
        expected[l.listValid] = 0;
    }
    if (version <= 5) old.erase(old.size() - 24, 8);   // checksum
    if (version <= 4) {
        old.erase(l.lastBuild, 8);
        put(expected, l.lastBuild, get<std::int64_t>(b, l.step));
    }
    if (version <= 3) {
        old.erase(l.recipe, l.recipeEnd - l.recipe);
        expected.replace(l.recipe, l.recipeEnd - l.recipe, std::string(1, '\0'));
    } else if (b[l.recipe]) {
        old.erase(l.settleFriction, l.recipeEnd - l.settleFriction);   // none before 9
        if (version <= 7) old.erase(l.placed, l.settleFriction - l.placed);   // none before 8
    }
    if (version <= 6) shortenKey(old, b, l.key);
    if (version <= 5) {
        old.erase(l.record, 8 + get<std::uint64_t>(b, l.record));
        expected.replace(l.record, 8 + get<std::uint64_t>(b, l.record), std::string(8, '\0'));
    }
    put(old, 16, version);
    if (version >= 6) resign(old);
    resign(expected);
    return old;
}

std::string olderSlab(const std::string& b, std::uint32_t version, std::string& expected,
                      double dMin)
{
    const Layout l(b, 3);
    std::string old = b;
    expected = b;
    if (version <= 3) old.erase(old.size() - 24, 8);   // checksum
    if (version <= 2) {
        old.erase(l.skin, 16);
        put(expected, l.skin, 0.1 * dMin);
        put(expected, l.lastBuild, get<std::int64_t>(b, l.step));
    }
    if (version <= 1) {
        old.erase(l.recipe, l.recipeEnd - l.recipe);
        expected.replace(l.recipe, l.recipeEnd - l.recipe, std::string(1, '\0'));
    } else if (b[l.recipe]) {
        old.erase(l.settleFriction, l.recipeEnd - l.settleFriction);   // none before 7
        if (version <= 5) old.erase(l.placed, l.settleFriction - l.placed);   // none before 6
    }
    if (version <= 4) shortenKey(old, b, l.key);
    if (version <= 3) {
        old.erase(l.record, 8 + get<std::uint64_t>(b, l.record));
        expected.replace(l.record, 8 + get<std::uint64_t>(b, l.record), std::string(8, '\0'));
    }
    put(old, 16, version);
    if (version >= 4) resign(old);
    resign(expected);
    return old;
}

} // namespace dem::test
