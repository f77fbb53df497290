// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a state file must satisfy before its particles are used: the checksum and the end
// marker of its bytes, the engine it was written by, and particles that a step can take
// (finite, inside the box, no pair nearly on top of each other). Shared by the 2D engine's
// and the slab's state files.

#include <cstdint>
#include <string>
#include <vector>

namespace dem {

struct Box;

/// 64-bit FNV-1a over `n` bytes, continued from `hash`.
std::uint64_t fnv1a64(const char* data, std::size_t n,
                      std::uint64_t hash = 0xcbf29ce484222325ULL);

/// The whole file; throws naming the file and the OS reason if it cannot be read.
std::string readStateBytes(const std::string& path, const std::string& kind);

/// Throws unless `bytes` ends with its checksum and the end marker `magic`, the checksum
/// being the FNV-1a of everything before it. Names the damage: bytes after the marker,
/// a file cut short, or contents that changed since it was written.
void verifyChecksum(const std::string& bytes, const char (&magic)[16], const std::string& what);

/// Throws naming the damage if the version field after the magic of `bytes` is not
/// `current` but was: the checksum matches the file with `current` in its place (a bit flip
/// of the field), or the claimed earlier version carries a checksum (from `firstSealed` on)
/// that does not match. Else returns, for the caller's version message.
void refuseDamagedVersion(const std::string& bytes, std::uint32_t current,
                          std::uint32_t firstSealed, const char (&magic)[16], const std::string& what);

/// The two engines' magics, for naming a state of the other engine.
extern const char discStateMagic[16];
extern const char slabStateMagic[16];

/// If `bytes` is a state of the other engine than `dimension` (2: discs, 3: slab spheres),
/// throws naming it and the fix; else returns.
void refuseForeignEngine(const std::string& bytes, int dimension, const std::string& path);

/// Particle arrays to check on load (z, vz null in 2D; depth 0).
struct LoadedParticles {
    std::size_t n;
    const double *x, *y, *z;
    const double *vx, *vy, *vz;
    const double* radius;
};

/// Pairs whose centres are closer than this fraction of the sum of their radii are refused
/// on load: at such overlaps the linear spring throws them apart at an unphysical speed,
/// and coincident centres have no contact normal (a settled bed overlaps by ~0.1 %).
constexpr double closestApproachFraction = 0.5;

/// Throws naming the file, the particle and the fault unless every position and velocity is
/// finite, every centre inside the box (and the slab's depth), and no two centres closer
/// than closestApproachFraction of their radii's sum.
void checkLoadedParticles(const LoadedParticles& p, const Box& box, double depth,
                          const std::string& what);

} // namespace dem
