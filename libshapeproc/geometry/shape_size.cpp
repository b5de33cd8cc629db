#include "libshapeproc/geometry/shape_size.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <variant>
#include <vector>

#include "libshapeproc/geometry/path.hpp"

namespace shapeproc::geometry {

ShapeSize shape_size(const Shape& shape) {
  std::vector<Vec3> points;
  double area = 0.0;
  std::visit(
      [&](const auto& g) {
        using T = std::decay_t<decltype(g)>;
        if constexpr (std::is_same_v<T, PlanarShape>) {
          const double tolerance = 1e-3 * bounding_box(shape).sizes().norm();
          for (const Drawable2& d : g.parts)
            for (const Path2& path : d.paths) {
              const std::vector<Vec2> line = flatten(path, tolerance);
              for (const Vec2& p : line) points.emplace_back(p.x(), p.y(), 0.0);
              if (d.filled()) area += signed_area(line);
            }
        } else if constexpr (std::is_same_v<T, MeshShape>) {
          points = g.mesh.vertices;
        }
      },
      shape.geometry);
  ShapeSize s;
  s.area = std::abs(area);
  if (points.empty()) return s;
  Vec3 centroid = Vec3::Zero();
  for (const Vec3& p : points) centroid += p;
  centroid /= static_cast<double>(points.size());
  for (const Vec3& p : points) s.radius = std::max(s.radius, (p - centroid).norm());
  return s;
}

double size_distance(const ShapeSize& a, const ShapeSize& b) {
  const double tiny = 1e-12;
  return std::abs(std::log((a.radius + tiny) / (b.radius + tiny))) +
         std::abs(std::log((a.area + tiny) / (b.area + tiny)));
}

}  // namespace shapeproc::geometry
