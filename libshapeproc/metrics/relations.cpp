#include "libshapeproc/metrics/relations.hpp"

#include <algorithm>

#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/geometry/neighbour_grid.hpp"

namespace shapeproc::metrics {

namespace {

// Whether every vertex of `inner` (at `offset` from `outer`) lies in `outer`'s filled region.
bool wholly_inside(const geometry::Proxy2& inner, const geometry::Proxy2& outer,
                   const geometry::Vec2& offset) {
  if (inner.polylines.empty()) return false;
  for (const auto& polyline : inner.polylines)
    for (const geometry::Vec2& p : polyline.points)
      if (!outer.inside(p + offset)) return false;
  return true;
}

}  // namespace

Relation relation(const geometry::PairMeasurer& measurer, int a, int b,
                  const geometry::Vec3& offset) {
  const double d = measurer.distance(a, b, offset);
  if (d > 0) return Relation::apart;
  if (d == 0) return Relation::touching;
  const auto& proxies = measurer.proxies2();
  const geometry::Proxy2& pa = proxies[static_cast<std::size_t>(a)];
  const geometry::Proxy2& pb = proxies[static_cast<std::size_t>(b)];
  const geometry::Vec2 t = offset.head<2>();
  if (wholly_inside(pa, pb, -t)) return Relation::inside;
  if (wholly_inside(pb, pa, t)) return Relation::contains;
  return Relation::overlapping;
}

const char* to_string(Relation relation) {
  switch (relation) {
    case Relation::apart:
      return "apart";
    case Relation::touching:
      return "touching";
    case Relation::overlapping:
      return "overlapping";
    case Relation::inside:
      return "inside";
    case Relation::contains:
      return "contains";
  }
  return "?";
}

CategoryRelations category_relations(const geometry::Scene& scene,
                                     const geometry::PairMeasurer& measurer) {
  CategoryRelations out;
  if (scene.dimension != 2 || measurer.proxies2().empty() || scene.categories.size() < 2)
    return out;
  const std::size_t n = scene.elements.size();
  const std::size_t categories = scene.categories.size();
  std::vector<char> nested(n, 0), overlapping(n, 0);
  double reach = 0.0;
  for (std::size_t s = 0; s < scene.shapes.size(); ++s)
    reach = std::max(reach, measurer.radius(static_cast<int>(s)));
  const geometry::Vec3 period =
      measurer.options().periodic ? geometry::Vec3(scene.window.sizes()) : geometry::Vec3::Zero();
  geometry::NeighbourGrid grid(scene.window, scene.dimension, std::max(2 * reach, 1e-12),
                               measurer.options().periodic);
  for (std::size_t i = 0; i < n; ++i) grid.insert(static_cast<int>(i), scene.elements[i].position);
  for (std::size_t i = 0; i < n; ++i) {
    const geometry::Element& a = scene.elements[i];
    grid.for_each_candidate_within(a.position, 2 * reach, [&](int j) {
      if (static_cast<std::size_t>(j) <= i) return;
      const geometry::Element& b = scene.elements[static_cast<std::size_t>(j)];
      if (a.category == b.category) return;
      const geometry::Vec3 offset = geometry::minimum_image(b.position - a.position, period);
      if (offset.norm() > measurer.radius(a.shape) + measurer.radius(b.shape)) return;
      const Relation r = relation(measurer, a.shape, b.shape, offset);
      if (r == Relation::inside) {
        nested[i] = 1;
      } else if (r == Relation::contains) {
        nested[static_cast<std::size_t>(j)] = 1;
      } else if (r == Relation::overlapping) {
        overlapping[i] = overlapping[static_cast<std::size_t>(j)] = 1;
      }
    });
  }
  std::vector<double> count(categories, 0.0);
  out.nested.assign(categories, 0.0);
  out.overlapping.assign(categories, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const auto c = static_cast<std::size_t>(scene.elements[i].category);
    count[c] += 1;
    out.nested[c] += nested[i];
    out.overlapping[c] += overlapping[i] && !nested[i];
  }
  for (std::size_t c = 0; c < categories; ++c) {
    if (count[c] == 0) continue;
    out.nested[c] /= count[c];
    out.overlapping[c] /= count[c];
  }
  return out;
}

}  // namespace shapeproc::metrics
