// Point scenes whose metrics are known: lattices, jittered lattices and Poisson patterns.
#pragma once

#include <cstdint>
#include <vector>

#include "libshapeproc/core/random.hpp"
#include "libshapeproc/geometry/scene.hpp"

namespace shapeproc::testing {

inline geometry::Scene point_scene(const std::vector<geometry::Vec3>& points, double width,
                                   double height) {
  geometry::Scene scene;
  scene.window = geometry::Box3(geometry::Vec3(0, 0, 0), geometry::Vec3(width, height, 0));
  scene.categories.push_back({"default"});
  scene.shapes.push_back(geometry::Shape{geometry::PointShape{}, "point"});
  for (const geometry::Vec3& p : points) scene.elements.push_back({0, 0, p});
  return scene;
}

inline geometry::Scene lattice(double spacing, int columns, int rows) {
  std::vector<geometry::Vec3> points;
  for (int y = 0; y < rows; ++y)
    for (int x = 0; x < columns; ++x)
      points.emplace_back((x + 0.5) * spacing, (y + 0.5) * spacing, 0.0);
  return point_scene(points, columns * spacing, rows * spacing);
}

inline geometry::Scene poisson(double width, double height, int count, std::uint64_t seed) {
  core::Random random(seed);
  std::vector<geometry::Vec3> points;
  for (int i = 0; i < count; ++i)
    points.emplace_back(random.uniform(0, width), random.uniform(0, height), 0.0);
  return point_scene(points, width, height);
}

// A square lattice whose points are moved by uniform noise in [-amplitude, amplitude] per axis.
inline geometry::Scene jittered_lattice(double spacing, int columns, int rows, double amplitude,
                                        std::uint64_t seed) {
  geometry::Scene scene = lattice(spacing, columns, rows);
  core::Random random(seed);
  for (geometry::Element& e : scene.elements)
    e.position += geometry::Vec3(random.uniform(-amplitude, amplitude),
                                 random.uniform(-amplitude, amplitude), 0.0);
  return scene;
}

// A triangular (hexagonal) lattice that tiles its torus: `rows` must be even.
inline geometry::Scene triangular_lattice(double spacing, int columns, int rows) {
  const double row = spacing * 0.8660254037844386;
  std::vector<geometry::Vec3> points;
  for (int y = 0; y < rows; ++y)
    for (int x = 0; x < columns; ++x)
      points.emplace_back((x + 0.25 + 0.5 * (y % 2)) * spacing, (y + 0.5) * row, 0.0);
  return point_scene(points, columns * spacing, rows * row);
}

}  // namespace shapeproc::testing
