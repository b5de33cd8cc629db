// Argument checks on entry to library functions, with one message format
// ("FUNCTION: NAME must be ..., got VALUE"); each throws core::ArgumentError.
#pragma once

#include <string>

#include "libshapeproc/core/error.hpp"

namespace shapeproc::core {

// Throws ArgumentError(function, message) unless `condition` holds.
inline void check(bool condition, const char* function, const std::string& message) {
  if (!condition) throw ArgumentError(function, message);
}

// The number as the checks print it (shortest round-trip form).
std::string describe(double value);

// NAME must be > 0 (and finite).
void check_positive(const char* function, const char* name, double value);
// NAME must be >= 0 (and finite).
void check_non_negative(const char* function, const char* name, double value);
// NAME must lie in [low, high] (`high_open`: [low, high)).
void check_in_range(const char* function, const char* name, double value, double low, double high,
                    bool high_open = false);

}  // namespace shapeproc::core
