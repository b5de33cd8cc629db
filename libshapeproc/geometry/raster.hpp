// A grey-level picture stretched over a box: the data of domain masks and intensity maps.
#pragma once

#include <vector>

#include "libshapeproc/geometry/types.hpp"

namespace shapeproc::geometry {

// Grey levels in [0, 1], row-major, row 0 at the top (SVG's y axis points down, and so do
// scenes read from SVG).
struct Raster {
  int width = 0, height = 0;
  std::vector<float> values;

  float at(int x, int y) const {
    return values[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                  static_cast<std::size_t>(x)];
  }
  // The value of the pixel holding `p`, with the raster stretched over `box` (x right, y down);
  // 0 outside the box.
  float sample(const Box3& box, const Vec2& p) const;
};

}  // namespace shapeproc::geometry
