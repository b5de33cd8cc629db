#include "libshapeproc/geometry/tile_repeat.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shapeproc::geometry {

Scene repeat_tile(const Scene& tile, int times) {
  Scene out = tile;
  if (times <= 1) return out;
  out.elements.clear();
  const Vec3 sizes = tile.window.sizes();
  const int depth = tile.dimension == 3 ? times : 1;
  for (int k = 0; k < depth; ++k) {
    for (int j = 0; j < times; ++j) {
      for (int i = 0; i < times; ++i) {
        const Vec3 shift(i * sizes.x(), j * sizes.y(), k * sizes.z());
        for (Element e : tile.elements) {
          e.position += shift;
          out.elements.push_back(e);
        }
      }
    }
  }
  Vec3 max = tile.window.min() + times * sizes;
  if (tile.dimension == 2) max.z() = tile.window.max().z();
  out.window = Box3(tile.window.min(), max);
  return out;
}

std::vector<Element> tile_over(const Scene& tile, const Box3& region) {
  std::vector<Element> out;
  const Vec3 sizes = tile.window.sizes();
  const int axes = tile.dimension;
  if (tile.elements.empty() || region.isEmpty()) return out;
  for (int a = 0; a < axes; ++a)
    if (!(sizes[a] > 0)) return out;
  // Half-open along each axis: on a torus the region's two faces are one place, and a copy on
  // each would be the same element twice.
  const auto inside = [&](const Vec3& p) {
    for (int a = 0; a < axes; ++a)
      if (p[a] < region.min()[a] || p[a] >= region.max()[a]) return false;
    return true;
  };
  // Whole windows k along each axis with the shifted window meeting the region.
  Eigen::Vector3i first = Eigen::Vector3i::Zero(), last = Eigen::Vector3i::Zero();
  for (int a = 0; a < axes; ++a) {
    first[a] = static_cast<int>(std::floor((region.min()[a] - tile.window.max()[a]) / sizes[a]));
    last[a] = static_cast<int>(std::ceil((region.max()[a] - tile.window.min()[a]) / sizes[a]));
  }
  for (int k = first.z(); k <= last.z(); ++k) {
    for (int j = first.y(); j <= last.y(); ++j) {
      for (int i = first.x(); i <= last.x(); ++i) {
        const Vec3 shift(i * sizes.x(), j * sizes.y(), axes == 3 ? k * sizes.z() : 0.0);
        for (Element e : tile.elements) {
          e.position += shift;
          if (inside(e.position)) out.push_back(e);
        }
      }
    }
  }
  return out;
}

Scene repeat_to_reach(const Scene& tile, double reach) {
  double side = std::numeric_limits<double>::infinity();
  for (int a = 0; a < tile.dimension; ++a) side = std::min(side, tile.window.sizes()[a]);
  if (!(side > 0) || side >= reach) return tile;
  return repeat_tile(tile, static_cast<int>(std::ceil(reach / side)));
}

int repeats_to_hold(const Scene& tile, double range, int at_least) {
  double extent = 0.0;  // the largest distance from a reference position to its outline
  for (const Shape& shape : tile.shapes)
    extent = std::max(extent, 0.5 * bounding_box(shape).sizes().norm());
  double side = std::numeric_limits<double>::infinity();
  for (int a = 0; a < tile.dimension; ++a) side = std::min(side, tile.window.sizes()[a]);
  if (!(side > 0) || !std::isfinite(range)) return at_least;
  const double needed = 2.0 * (range + 2.0 * extent);
  return std::max(at_least, static_cast<int>(std::ceil(needed / side - 1e-9)));
}

int tile_repeats(std::size_t elements) {
  if (elements >= 8) return 1;
  return elements <= 1 ? 4 : 3;
}

}  // namespace shapeproc::geometry
