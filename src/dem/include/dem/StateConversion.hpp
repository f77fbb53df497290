// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Conversion of a state file of an older version to the current version of its engine, for
// the engines read their current version only (the policy: StateFile.cpp, SlabState.cpp).
// The command dpmConvertState runs it.

#include <cstdint>
#include <string>

namespace dem {

/// The command that converts an older state (named in the engines' refusal).
inline constexpr const char* stateConverter = "dpmConvertState";

/// The current versions, written by save() and the only ones load() reads.
inline constexpr std::uint32_t discStateVersion = 9;
inline constexpr std::uint32_t slabStateVersion = 7;
/// The oldest versions the converter reads.
inline constexpr std::uint32_t oldestDiscStateVersion = 2;
inline constexpr std::uint32_t oldestSlabStateVersion = 1;
/// The first versions that carry a checksum (and a run record).
inline constexpr std::uint32_t firstSealedDiscStateVersion = 6;
inline constexpr std::uint32_t firstSealedSlabStateVersion = 4;

/// What convertState did.
struct StateConversion {
    int dimension = 2;               ///< the engine: 2 (discs in a plane), 3 (slab spheres)
    std::uint32_t fromVersion = 0;   ///< the file's version
    std::uint32_t toVersion = 0;     ///< the version written (fromVersion if current already)
    std::string notes;               ///< what the older file did not carry, one line each
};

/// The command line that converts `path` in place, for messages.
std::string convertCommand(const std::string& path);

/// Reads the state at `in` (2D versions 2-8, slab versions 1-6) and writes it at `out` in
/// the current version of its engine: the same particles, contacts and counters, with what
/// the older version did not carry set as its load did (a bed recipe without a settle
/// friction, settled with the contacts' own; 2D before 8 and slab before 6: without placed
/// particles; 2D before 6 and slab before 4: no run record; no bed recipe, the adaptive skin's clock at the file's step; 2D version 2:
/// the neighbour list rebuilt on the first step; slab versions 1-2: the skin 0.1 d_min)
/// and the settings key's contact entries as the earlier versions ran: the contact law of
/// the run record's contactLaw line (else linear), tangentialDampingRatio 1, no rolling
/// friction, no moduli. Written beside `out` and renamed, so
/// `out` may be `in`. A file of the current version is left as it is and nothing is
/// written. Throws dem::Error naming the file for one that is not a DEM state, of an unknown
/// version, damaged or not writable.
StateConversion convertState(const std::string& in, const std::string& out);

} // namespace dem
