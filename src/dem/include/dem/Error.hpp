// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The one exception type of the DEM library.

#include <stdexcept>
#include <string>

namespace dem {

/// Raised for a bad setting, a bad state file or a particle that leaves the box.
/// The message names the setting, its value and the allowed range.
class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Compact decimal text of a value (6 significant digits), for error messages.
std::string formatValue(double value);

} // namespace dem

namespace dem {

/// A state file written by the other engine (a slab state read in 2D, or the reverse).
class ForeignStateError : public Error {
public:
    ForeignStateError(const std::string& what, int fileDimension)
        : Error(what), fileDimension_(fileDimension) {}
    /// The engine of the file: 2 (discs in a plane) or 3 (spheres in a slab).
    int fileDimension() const { return fileDimension_; }

private:
    int fileDimension_;
};

} // namespace dem
