// Mathematical constants, defined once.
#pragma once

namespace shapeproc::core {

inline constexpr double kPi = 3.14159265358979323846;

}  // namespace shapeproc::core
