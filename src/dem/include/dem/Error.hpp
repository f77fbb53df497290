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
