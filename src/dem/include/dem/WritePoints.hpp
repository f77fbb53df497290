// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Named moments of the state writers (Simulation::save, both engines), where a caller may
// stop or kill the process to see what a kill at that moment leaves on disk (the
// coupling's fault tests). No hook is installed by default; the writers then only test
// a pointer.
//
//   "stateWrite.part"    <path>.tmp holds the header and the particle arrays, flushed;
//                        the contact lists, the checksum and the end marker are not
//                        written yet
//   "stateWrite.rename"  <path>.tmp is complete and closed, not yet renamed to <path>

namespace dem {

/// Called at each write point with its name; it may stop or end the process.
using WritePointHook = void (*)(const char* point);

/// Installs `hook` for every state writer of the process (nullptr: none); returns the
/// hook it replaces.
WritePointHook setWritePointHook(WritePointHook hook);

/// Runs the installed hook, if any, at `point` (the writers' side).
void atWritePoint(const char* point);

} // namespace dem
