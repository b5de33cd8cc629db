#include "libshapeproc/fit/quadrature_cell.hpp"

#include <algorithm>
#include <cmath>

#include "libshapeproc/core/constants.hpp"
#include "libshapeproc/fit/detail/quadrature_cell_internal.hpp"

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

namespace {

// Splits of a 2D cell where a level set curves more tightly than chords can follow (a band
// narrower than the cell about a near neighbour): each halves the cell's side.
constexpr int kTightSplits = 3;

// Parts of the 2^dimension halves of the cell, as fractions of the whole; `integrate` gives a
// sub-cell's (its dummy moved to the sub-cell's centre).
template <typename Integrate>
std::vector<CellPart> split_cell(int dimension, const geometry::Element& dummy, const Vec3& size,
                                 Integrate&& integrate) {
  std::vector<CellPart> parts;
  const int children = 1 << dimension;
  for (int child = 0; child < children; ++child) {
    geometry::Element sub = dummy;
    for (int axis = 0; axis < dimension; ++axis) {
      sub.position[axis] += ((child >> axis) & 1 ? 0.25 : -0.25) * size[axis];
    }
    for (CellPart& part : integrate(sub)) {
      part.fraction /= children;
      parts.push_back(std::move(part));
    }
  }
  return parts;
}

std::vector<CellPart> integrate_plane(const CellContext& context, const geometry::Element& dummy,
                                      const Vec3& size, bool* uniform, CornerCache* cache,
                                      int splits) {
  bool too_curved = false;
  std::vector<CellPart> parts =
      integrate_cell_plane(context, dummy, size, uniform, &too_curved, cache);
  if (!too_curved || splits <= 0) return parts;
  return split_cell(2, dummy, size, [&](const geometry::Element& sub) {
    return integrate_plane(context, sub, 0.5 * size, nullptr, cache, splits - 1);
  });
}

}  // namespace

std::vector<CellPart> integrate_cell(const CellContext& context, const geometry::Element& dummy,
                                     const Vec3& size, bool* uniform, CornerCache* cache) {
  if (context.dimension == 2)
    return integrate_plane(context, dummy, size, uniform, cache, kTightSplits);
  return integrate_cell_ball(context, dummy, size, uniform);
}

std::vector<CellPart> integrate_cell_adaptive(const CellContext& context,
                                              const geometry::Element& dummy, const Vec3& size,
                                              int depth, CornerCache* cache) {
  bool uniform = true;
  std::vector<CellPart> parts = integrate_cell(context, dummy, size, &uniform, cache);
  if (uniform || depth <= 0) return parts;
  return split_cell(context.dimension, dummy, size, [&](const geometry::Element& sub) {
    return integrate_cell_adaptive(context, sub, 0.5 * size, depth - 1, cache);
  });
}

}  // namespace shapeproc::fit
