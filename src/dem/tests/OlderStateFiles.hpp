// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Older state files made from a current one by each version's layout changes
// (StateConversion.cpp lists them), for the tests of the converter.
#pragma once

#include "dem/Particles.hpp"
#include "dem/SlabSystem.hpp"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

namespace dem::test {

/// The value of type T at byte `at` of `b`, and its writing.
template <class T> T get(const std::string& b, std::size_t at)
{
    T v;
    std::memcpy(&v, &b[at], sizeof(T));
    return v;
}

template <class T> void put(std::string& b, std::size_t at, T v) { std::memcpy(&b[at], &v, sizeof(T)); }

/// The offsets of a current state's fields, walked from its layout (StateFile::write,
/// SlabSystem::save).
struct Layout {
    std::size_t record, key, recipe, placed = 0, settleFriction = 0, recipeEnd, step, lastBuild,
        skin = 0, listValid = 0;
    std::size_t groupStart, groupStartEnd, pairs, checksum;
    std::uint64_t particles = 0, pairCount = 0;

    Layout(const std::string& b, int dimension)
    {
        auto array = [&](std::size_t at, std::size_t element) {
            return at + 8 + element * get<std::uint64_t>(b, at);
        };
        record = 20;
        key = array(record, 1);
        recipe = array(key, 8);
        recipeEnd = recipe + 1;
        if (b[recipe]) {
            placed = array(recipe + 1, 4) + 32 + 8 + 8 + 8;
            settleFriction = array(placed, 8);
            recipeEnd = array(settleFriction, 8);
        }
        step = recipeEnd;   // step count, list builds
        std::size_t at;
        if (dimension == 2) {
            lastBuild = step + 16;
            listValid = lastBuild + 8;
            at = listValid + 1 + 1 + 8 + 8;   // flags, contacts, largest overlap
        } else {
            skin = step + 16;
            lastBuild = skin + 8;
            at = array(lastBuild + 8, 8);     // the walls
        }
        particles = get<std::uint64_t>(b, at);
        auto walk = [&](auto& arrays) {
            arrays.forEachArray([&](auto& a) { at = array(at, sizeof(a[0])); });
        };
        if (dimension == 2) {
            Particles p;
            walk(p);
        } else {
            SlabParticles p;
            walk(p);
            at += 1;   // ready
        }
        pairs = at;
        pairCount = get<std::uint64_t>(b, at);
        const std::size_t history = dimension == 2 ? 8 : 24;
        at = array(array(array(array(at, 4), 4), 4), history);
        groupStart = at;
        groupStartEnd = array(at, 4);
        checksum = b.size() - 16 - 8;
    }
};

/// A current 2D state `b` in the layout of `version`, and in `expected` the current layout
/// of what the converter makes of it.
std::string olderDisc(const std::string& b, std::uint32_t version, std::string& expected);

/// The same for a slab state; `dMin` the smallest diameter (the skin of versions before 3).
std::string olderSlab(const std::string& b, std::uint32_t version, std::string& expected,
                      double dMin);

} // namespace dem::test
