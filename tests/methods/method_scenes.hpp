// Small scenes for the comparison methods' tests (lattices and scatters of rectangles), and
// what their tests ask of the outputs.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "libshapeproc/core/random.hpp"
#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/synthesis/synthesizer.hpp"
#include "tests/test_support.hpp"

namespace shapeproc::testing {

// A filled axis-aligned rectangle w x h centred at the origin.
inline geometry::Shape rectangle(double w, double h) {
  geometry::Path2 path;
  const geometry::Vec2 a(-w / 2, -h / 2), b(w / 2, -h / 2), c(w / 2, h / 2), d(-w / 2, h / 2);
  path.segments = {geometry::Segment2::line(a, b), geometry::Segment2::line(b, c),
                   geometry::Segment2::line(c, d), geometry::Segment2::line(d, a)};
  path.closed = true;
  geometry::Drawable2 drawable;
  drawable.paths = {path};
  drawable.style["fill"] = "#000000";
  geometry::Shape shape;
  shape.geometry = geometry::PlanarShape{{drawable}};
  return shape;
}

// An n x n square lattice of w x h rectangles with spacing a, filling the window [0, n a]^2 (a
// seamless tile: its copies continue the lattice).
inline geometry::Scene rectangle_lattice(int n, double a, double w, double h) {
  geometry::Scene scene;
  scene.window = geometry::Box3(geometry::Vec3(0, 0, 0), geometry::Vec3(n * a, n * a, 0));
  scene.categories = {{"a"}};
  scene.shapes = {rectangle(w, h)};
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      scene.elements.push_back({0, 0, geometry::Vec3((i + 0.5) * a, (j + 0.5) * a, 0)});
  return scene;
}

// A hexagonal lattice of spacing a, `columns` x `rows` (rows even), of w x h rectangles: a
// seamless tile of [0, columns a] x [0, rows a √3/2].
inline geometry::Scene hexagonal_lattice(int columns, int rows, double a, double w, double h) {
  const double row = a * std::sqrt(3.0) / 2.0;
  geometry::Scene scene;
  scene.window =
      geometry::Box3(geometry::Vec3(0, 0, 0), geometry::Vec3(columns * a, rows * row, 0));
  scene.categories = {{"a"}};
  scene.shapes = {rectangle(w, h)};
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i)
      scene.elements.push_back(
          {0, 0, geometry::Vec3((i + 0.25 + 0.5 * (j % 2)) * a, (j + 0.5) * row, 0)});
  return scene;
}

// `count` squares of side s at uniform random places of [0, size]^2, none closer than `gap`.
inline geometry::Scene rectangle_scatter(int count, double size, double s, double gap,
                                         std::uint64_t seed) {
  geometry::Scene scene;
  scene.window = geometry::Box3(geometry::Vec3(0, 0, 0), geometry::Vec3(size, size, 0));
  scene.categories = {{"a"}};
  scene.shapes = {rectangle(s, s)};
  core::Random random(seed);
  while (static_cast<int>(scene.elements.size()) < count) {
    const geometry::Vec3 p(random.uniform(0, size), random.uniform(0, size), 0);
    bool free = true;
    for (const auto& e : scene.elements) free = free && (e.position - p).norm() >= gap;
    if (free) scene.elements.push_back({0, 0, p});
  }
  return scene;
}

// `count` horizontal bars 30 x 4 at random places of a 200 x 200 torus, none overlapping.
inline geometry::Scene bar_scatter(int count, std::uint64_t seed) {
  geometry::Scene scene;
  scene.window = geometry::Box3(geometry::Vec3(0, 0, 0), geometry::Vec3(200, 200, 0));
  scene.categories = {{"a"}};
  scene.shapes = {rectangle(30.0, 4.0)};
  const auto torus = geometry::Domain::from_sizes({200, 200}, geometry::Boundary::torus);
  core::Random random(seed);
  while (static_cast<int>(scene.elements.size()) < count) {
    const geometry::Vec3 p(random.uniform(0, 200), random.uniform(0, 200), 0);
    bool free = true;
    for (const auto& e : scene.elements) {
      const geometry::Vec3 d = torus.minimum_image(e.position - p);
      free = free && !(std::abs(d.x()) < 31.0 && std::abs(d.y()) < 5.0);
    }
    if (free) scene.elements.push_back({0, 0, p});
  }
  return scene;
}

inline int overlapping_bars(const geometry::Scene& scene, const geometry::Domain& domain) {
  int pairs = 0;
  for (std::size_t i = 0; i < scene.elements.size(); ++i)
    for (std::size_t j = i + 1; j < scene.elements.size(); ++j) {
      const geometry::Vec3 d =
          domain.minimum_image(scene.elements[j].position - scene.elements[i].position);
      pairs += std::abs(d.x()) < 30.0 - 1e-9 && std::abs(d.y()) < 4.0 - 1e-9;
    }
  return pairs;
}

// Hero Patterns' bubbles tile (17 discs, data/third-party), read as the seamless tile it is.
inline geometry::Scene bubbles_tile() {
  io::ReaderOptions seamless;
  seamless.tile = true;
  return io::read_scene(data_path("third-party/hero-patterns/bubbles.svg"), seamless);
}

// One chain of `method` from `seed`.
inline synthesis::SynthesisResult run(const synthesis::Synthesizer& method, std::uint64_t seed) {
  core::Random random(seed);
  return method.synthesize(random, synthesis::ChainControl{});
}

// Every element's distance to its nearest other (minimum image on a torus).
inline std::vector<double> nearest_distances(const geometry::Scene& scene,
                                             const geometry::Domain& domain) {
  std::vector<double> out;
  for (std::size_t i = 0; i < scene.elements.size(); ++i) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < scene.elements.size(); ++j)
      if (j != i)
        best = std::min(
            best,
            domain.minimum_image(scene.elements[j].position - scene.elements[i].position).norm());
    out.push_back(best);
  }
  return out;
}

}  // namespace shapeproc::testing
