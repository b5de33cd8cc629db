// Shapes with known measurements, shared by the measurement tests.
#pragma once

#include <cmath>
#include <random>

#include "libshapeproc/geometry/arc.hpp"
#include "libshapeproc/geometry/scene.hpp"

namespace shapeproc::geometry::fixtures {

inline Path2 polygon(const std::vector<Vec2>& corners, bool closed = true) {
  Path2 path;
  for (std::size_t i = 0; i + 1 < corners.size(); ++i)
    path.segments.push_back(Segment2::line(corners[i], corners[i + 1]));
  if (closed) path.segments.push_back(Segment2::line(corners.back(), corners.front()));
  path.closed = closed;
  return path;
}

inline Path2 rectangle(double x0, double y0, double x1, double y1, bool reversed = false) {
  std::vector<Vec2> c = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  if (reversed) std::reverse(c.begin(), c.end());
  return polygon(c);
}

inline Shape planar(std::vector<Path2> paths, FillRule rule = FillRule::nonzero,
                    bool filled = true) {
  Drawable2 d;
  d.paths = std::move(paths);
  d.fill_rule = rule;
  if (!filled) d.style["fill"] = "none";
  return Shape{PlanarShape{{d}}, ""};
}

inline Shape disc(double r) { return planar({ellipse_path(Vec2::Zero(), r, r)}); }

// A ring of outer radius r and inner radius h, hole drawn the other way round (nonzero).
inline Shape ring(double r, double h) {
  Path2 hole = ellipse_path(Vec2::Zero(), h, h);
  // reverse the hole
  Path2 reversed;
  for (auto it = hole.segments.rbegin(); it != hole.segments.rend(); ++it) {
    reversed.segments.push_back(Segment2::bezier(it->end, it->control2, it->control1, it->start));
  }
  reversed.closed = true;
  return planar({ellipse_path(Vec2::Zero(), r, r), reversed});
}

// Random star-shaped polygon around the origin (simple, closed).
inline Shape random_polygon(std::mt19937& rng, int corners, double radius) {
  std::uniform_real_distribution<double> scale(0.4, 1.0);
  std::vector<Vec2> points;
  for (int k = 0; k < corners; ++k) {
    const double angle = 2 * 3.14159265358979323846 * k / corners;
    const double r = radius * scale(rng);
    points.emplace_back(r * std::cos(angle), r * std::sin(angle));
  }
  return planar({polygon(points)});
}

// `count` random polygons (the i-th with min_corners + i % corner_span corners) at positions
// uniform in [low, high]^2, all from one generator seeded with `seed`.
struct ScatteredPolygons {
  std::vector<Shape> shapes;
  std::vector<Vec2> positions;
};
inline ScatteredPolygons scatter_polygons(unsigned seed, int count, int min_corners,
                                          int corner_span, double radius, double low, double high) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> position(low, high);
  ScatteredPolygons out;
  for (int i = 0; i < count; ++i) {
    out.shapes.push_back(random_polygon(rng, min_corners + i % corner_span, radius));
    out.positions.emplace_back(position(rng), position(rng));
  }
  return out;
}

// A scene of 2D shapes placed at the given positions (shapes given in local coordinates).
inline Scene scene_of(const std::vector<Shape>& shapes, const std::vector<Vec2>& positions,
                      Box3 window = Box3(Vec3(-1000, -1000, 0), Vec3(1000, 1000, 0))) {
  Scene scene;
  scene.window = window;
  scene.categories.push_back({"default"});
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    Shape placed = shapes[i];
    translate(placed, Vec3(positions[i].x(), positions[i].y(), 0));
    add_element(scene, placed, 0);
  }
  return scene;
}

// Closed UV sphere with `slices` x `stacks` (2 * slices * (stacks - 1) triangles).
inline TriangleMesh uv_sphere(double r, int slices, int stacks) {
  TriangleMesh m;
  const double pi = 3.14159265358979323846;
  m.vertices.emplace_back(0, 0, r);
  for (int i = 1; i < stacks; ++i) {
    const double theta = pi * i / stacks;
    for (int j = 0; j < slices; ++j) {
      const double phi = 2 * pi * j / slices;
      m.vertices.emplace_back(r * std::sin(theta) * std::cos(phi),
                              r * std::sin(theta) * std::sin(phi), r * std::cos(theta));
    }
  }
  m.vertices.emplace_back(0, 0, -r);
  const int south = static_cast<int>(m.vertices.size()) - 1;
  auto at = [&](int ring, int j) { return 1 + ring * slices + (j % slices); };
  for (int j = 0; j < slices; ++j) m.triangles.push_back({0, at(0, j), at(0, j + 1)});
  for (int i = 0; i + 1 < stacks - 1; ++i)
    for (int j = 0; j < slices; ++j) {
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  for (int j = 0; j < slices; ++j)
    m.triangles.push_back({south, at(stacks - 2, j + 1), at(stacks - 2, j)});
  return m;
}

inline TriangleMesh box_mesh(const Vec3& lo, const Vec3& hi) {
  TriangleMesh m;
  for (int i = 0; i < 8; ++i)
    m.vertices.emplace_back(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(),
                            i & 4 ? hi.z() : lo.z());
  m.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                 {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return m;
}

inline Scene scene_of_meshes(const std::vector<TriangleMesh>& meshes,
                             const std::vector<Vec3>& positions,
                             Box3 window = Box3(Vec3(-100, -100, -100), Vec3(100, 100, 100))) {
  Scene scene;
  scene.dimension = 3;
  scene.window = window;
  scene.categories.push_back({"default"});
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    Shape shape{MeshShape{meshes[i]}, ""};
    translate(shape, positions[i]);
    add_element(scene, shape, 0);
  }
  return scene;
}

}  // namespace shapeproc::geometry::fixtures
