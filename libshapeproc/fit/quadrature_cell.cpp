#include "libshapeproc/fit/quadrature_cell.hpp"

#include <algorithm>
#include <cmath>

#include "libshapeproc/core/constants.hpp"
#include "libshapeproc/fit/quadrature_cell_internal.hpp"

namespace shapeproc::fit {

using geometry::Vec3;

double cell_radius(int dimension, double measure) {
  return dimension == 2 ? std::sqrt(measure / core::kPi)
                        : std::cbrt(3.0 * measure / (4.0 * core::kPi));
}

double cut_fraction(int dimension, double cell_measure, double x) {
  const double r = cell_radius(dimension, cell_measure);
  if (x >= r) return 0.0;
  x = std::max(0.0, x);
  if (dimension == 2) {
    return (r * r * std::acos(x / r) - x * std::sqrt(r * r - x * x)) / (core::kPi * r * r);
  }
  return (r - x) * (r - x) * (2 * r + x) / (4.0 * r * r * r);  // cap volume / ball volume
}

std::vector<CellPart> integrate_cell(const CellContext& context, const geometry::Element& dummy,
                                     const Vec3& size, bool* uniform, CornerCache* cache) {
  if (context.dimension == 2) return integrate_cell_plane(context, dummy, size, uniform, cache);
  return integrate_cell_ball(context, dummy, size, uniform);
}

std::vector<CellPart> integrate_cell_adaptive(const CellContext& context,
                                              const geometry::Element& dummy, const Vec3& size,
                                              int depth, CornerCache* cache) {
  bool uniform = true;
  std::vector<CellPart> parts = integrate_cell(context, dummy, size, &uniform, cache);
  if (uniform || depth <= 0) return parts;
  parts.clear();
  const int children = context.dimension == 2 ? 4 : 8;
  const double share = 1.0 / children;
  for (int child = 0; child < children; ++child) {
    geometry::Element sub = dummy;
    for (int axis = 0; axis < context.dimension; ++axis) {
      sub.position[axis] += ((child >> axis) & 1 ? 0.25 : -0.25) * size[axis];
    }
    for (CellPart& part : integrate_cell_adaptive(context, sub, 0.5 * size, depth - 1, cache)) {
      part.fraction *= share;
      parts.push_back(std::move(part));
    }
  }
  return parts;
}

}  // namespace shapeproc::fit
