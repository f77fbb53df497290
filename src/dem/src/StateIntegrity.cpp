// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Load-time checks of state files, shared by the 2D engine and the slab.

#include "StateIntegrity.hpp"

#include "dem/Error.hpp"
#include "dem/Facade.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

namespace dem {

const char discStateMagic[16] = "dpmFoam2D-dem\n";
const char slabStateMagic[16] = "dpmFoam2D-slab\n";

std::uint64_t fnv1a64(const char* data, std::size_t n, std::uint64_t hash)
{
    for (std::size_t k = 0; k < n; ++k) {
        hash ^= static_cast<unsigned char>(data[k]);
        hash *= 0x100000001b3ULL;
    }
    return hash;
}

std::string readStateBytes(const std::string& path, const std::string& kind)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error("cannot open " + kind + " '" + path + "': " + std::strerror(errno));
    std::ostringstream all;
    all << in.rdbuf();
    if (in.bad()) throw Error("cannot read " + kind + " '" + path + "': " + std::strerror(errno));
    return all.str();
}

void verifyChecksum(const std::string& bytes, const char (&magic)[16], const std::string& what)
{
    constexpr std::size_t tail = sizeof(std::uint64_t) + sizeof(magic);
    auto checksumBefore = [&](std::size_t end) {   // end: offset of an end marker
        std::uint64_t stored = 0;
        std::memcpy(&stored, bytes.data() + end - sizeof(stored), sizeof(stored));
        return stored == fnv1a64(bytes.data(), end - sizeof(stored));
    };
    const std::size_t n = bytes.size();
    if (n >= tail + 20 && std::memcmp(bytes.data() + n - sizeof(magic), magic, sizeof(magic)) == 0) {
        if (checksumBefore(n - sizeof(magic))) return;
        throw Error(what + " is damaged: its checksum does not match its contents (changed "
                    "since it was written: a disk or copy error, or an edit)");
    }
    // No end marker last: data appended after a whole state, the marker itself damaged in a
    // file of full length, or a file cut short.
    const char* found = std::find_end(bytes.data(), bytes.data() + n, magic, magic + sizeof(magic));
    const std::size_t at = static_cast<std::size_t>(found - bytes.data());
    if (found != bytes.data() + n && at >= tail + 20 && checksumBefore(at)) {
        throw Error(what + " is damaged: " + std::to_string(n - at - sizeof(magic))
                    + " bytes follow its end (appended to it: restore the file as written)");
    }
    if (n >= tail + 20) {
        // The last 16 bytes where the marker belongs: intact contents before them, or most
        // of the marker's bytes in place, mean a whole file whose end was overwritten
        const char* last = bytes.data() + n - sizeof(magic);
        std::size_t same = 0;
        for (std::size_t k = 0; k < sizeof(magic); ++k) same += last[k] == magic[k];
        if (checksumBefore(n - sizeof(magic))) {
            throw Error(what + " is damaged: its end marker is overwritten (" 
                        + std::to_string(sizeof(magic) - same) + " of its 16 bytes differ), its "
                        "contents before it intact (their checksum matches): a disk or copy "
                        "error, or an edit");
        }
        if (2 * same >= sizeof(magic)) {
            throw Error(what + " is damaged: its end marker is overwritten ("
                        + std::to_string(sizeof(magic) - same) + " of its 16 bytes differ) and "
                        "its checksum does not match its contents: a disk or copy error, or an "
                        "edit");
        }
    }
    throw Error(what + " is damaged: it does not end with its checksum and end marker "
                "(truncated: a copy or a write cut short)");
}

void refuseDamagedVersion(const std::string& bytes, std::uint32_t current,
                          std::uint32_t firstSealed, const char (&magic)[16], const std::string& what)
{
    constexpr std::size_t at = sizeof(magic);   // the version follows the magic
    std::uint32_t claimed = 0;
    if (bytes.size() < at + sizeof(claimed)) return;
    std::memcpy(&claimed, bytes.data() + at, sizeof(claimed));
    if (claimed == current) return;
    // The file as it would read with the current version: if its checksum then matches, the
    // version field alone changed (the checksum covers it)
    const std::size_t n = bytes.size();
    constexpr std::size_t tail = sizeof(std::uint64_t) + sizeof(magic);
    if (n >= tail + at + sizeof(claimed)
        && std::memcmp(bytes.data() + n - sizeof(magic), magic, sizeof(magic)) == 0) {
        std::string restored = bytes;
        std::memcpy(&restored[at], &current, sizeof(current));
        std::uint64_t stored = 0;
        std::memcpy(&stored, bytes.data() + n - tail, sizeof(stored));
        if (stored == fnv1a64(restored.data(), n - tail)) {
            throw Error(what + " is damaged: its version field reads " + std::to_string(claimed)
                        + " where its checksum is that of a version " + std::to_string(current)
                        + " file (a disk or copy error, or an edit): restore the file as written");
        }
    }
    // A version whose layout carries a checksum: the claim holds only if the checksum does
    if (claimed >= firstSealed && claimed < current) verifyChecksum(bytes, magic, what);
}

void refuseForeignEngine(const std::string& bytes, int dimension, const std::string& path)
{
    const bool slab = bytes.size() >= sizeof(slabStateMagic)
                      && std::memcmp(bytes.data(), slabStateMagic, sizeof(slabStateMagic)) == 0;
    const bool disc = bytes.size() >= sizeof(discStateMagic)
                      && std::memcmp(bytes.data(), discStateMagic, sizeof(discStateMagic)) == 0;
    if (dimension == 2 && slab) {
        throw ForeignStateError("state file '" + path + "' is a slab state (3D spheres), "
                                "not one of 2D discs", 3);
    }
    if (dimension == 3 && disc) {
        throw ForeignStateError("state file '" + path + "' is a 2D state (discs in a plane), "
                                "not one of 3D spheres in a slab", 2);
    }
}

namespace {

std::string point(const LoadedParticles& p, std::size_t i)
{
    std::string s = "(" + formatValue(p.x[i]) + ", " + formatValue(p.y[i]);
    if (p.z) s += ", " + formatValue(p.z[i]);
    return s + ") m";
}

} // namespace

void checkLoadedParticles(const LoadedParticles& p, const Box& box, double depth,
                          const std::string& what)
{
    auto fail = [&](std::size_t i, const std::string& fault) {
        throw Error(what + ": particle " + std::to_string(i) + " " + fault);
    };
    double rMax = 0.0;
    for (std::size_t i = 0; i < p.n; ++i) {
        const bool finitePosition = std::isfinite(p.x[i]) && std::isfinite(p.y[i])
                                    && (!p.z || std::isfinite(p.z[i]));
        if (!finitePosition) fail(i, "has a position that is not a finite number: " + point(p, i));
        if (!(std::isfinite(p.vx[i]) && std::isfinite(p.vy[i]) && (!p.vz || std::isfinite(p.vz[i])))) {
            fail(i, "at " + point(p, i) + " has a velocity that is not a finite number");
        }
        if (!(p.radius[i] > 0.0) || !std::isfinite(p.radius[i])) {
            fail(i, "has a radius of " + formatValue(p.radius[i]) + " m");
        }
        const bool inside = p.x[i] >= box.xMin && p.x[i] <= box.xMax && p.y[i] >= box.yMin
                            && p.y[i] <= box.yMax && (!p.z || (p.z[i] >= 0.0 && p.z[i] <= depth));
        if (!inside) {
            std::string range = "[" + formatValue(box.xMin) + ", " + formatValue(box.xMax) + "] x ["
                                + formatValue(box.yMin) + ", " + formatValue(box.yMax) + "]";
            if (p.z) range += " x [0, " + formatValue(depth) + "]";
            fail(i, "at " + point(p, i) + " is outside the box " + range + " m");
        }
        rMax = std::max(rMax, p.radius[i]);
    }
    if (p.n < 2) return;
    // Pairs within 2 rMax of each other, by cells of that size in x-y.
    const double cell = 2.0 * rMax;
    const long nx = std::max(1L, static_cast<long>((box.xMax - box.xMin) / cell));
    const long ny = std::max(1L, static_cast<long>((box.yMax - box.yMin) / cell));
    auto column = [&](double x) { return std::clamp(static_cast<long>((x - box.xMin) / cell), 0L, nx - 1); };
    auto row = [&](double y) { return std::clamp(static_cast<long>((y - box.yMin) / cell), 0L, ny - 1); };
    std::vector<std::size_t> first(static_cast<std::size_t>(nx * ny) + 1, 0), members(p.n);
    for (std::size_t i = 0; i < p.n; ++i) ++first[static_cast<std::size_t>(row(p.y[i]) * nx + column(p.x[i])) + 1];
    for (std::size_t c = 1; c < first.size(); ++c) first[c] += first[c - 1];
    std::vector<std::size_t> fill(first.begin(), first.end() - 1);
    for (std::size_t i = 0; i < p.n; ++i) members[fill[static_cast<std::size_t>(row(p.y[i]) * nx + column(p.x[i]))]++] = i;
    for (std::size_t i = 0; i < p.n; ++i) {
        const long cx = column(p.x[i]), cy = row(p.y[i]);
        for (long y = std::max(0L, cy - 1); y <= std::min(ny - 1, cy + 1); ++y) {
            for (long x = std::max(0L, cx - 1); x <= std::min(nx - 1, cx + 1); ++x) {
                const std::size_t c = static_cast<std::size_t>(y * nx + x);
                for (std::size_t m = first[c]; m < first[c + 1]; ++m) {
                    const std::size_t j = members[m];
                    if (j <= i) continue;
                    const double dx = p.x[i] - p.x[j], dy = p.y[i] - p.y[j];
                    const double dz = p.z ? p.z[i] - p.z[j] : 0.0;
                    const double reach = closestApproachFraction * (p.radius[i] + p.radius[j]);
                    if (dx * dx + dy * dy + dz * dz < reach * reach) {
                        throw Error(what + ": particles " + std::to_string(i) + " at " + point(p, i)
                                    + " and " + std::to_string(j) + " at " + point(p, j)
                                    + " are closer than half the sum of their radii (their "
                                    "contact would throw them apart at an unphysical speed)");
                    }
                }
            }
        }
    }
}

} // namespace dem
