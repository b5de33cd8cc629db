#include "libshapeproc/core/check.hpp"

#include <cmath>
#include <cstdio>

#include "libshapeproc/core/format.hpp"

namespace shapeproc::core {

std::string describe(double value) { return format_number(value); }

void check_positive(const char* function, const char* name, double value) {
  check(std::isfinite(value) && value > 0, function,
        std::string(name) + " must be positive, got " + describe(value));
}

void check_non_negative(const char* function, const char* name, double value) {
  check(std::isfinite(value) && value >= 0, function,
        std::string(name) + " must be >= 0, got " + describe(value));
}

void check_in_range(const char* function, const char* name, double value, double low, double high,
                    bool high_open) {
  const bool inside = value >= low && (high_open ? value < high : value <= high);
  check(inside, function,
        std::string(name) + " must be in [" + describe(low) + ", " + describe(high) +
            (high_open ? ")" : "]") + ", got " + describe(value));
}

}  // namespace shapeproc::core
