#include "libshapeproc/geometry/pair_measurements.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "libshapeproc/core/constants.hpp"
#include "libshapeproc/geometry/overlap_depth.hpp"
#include "libshapeproc/geometry/path.hpp"
#include "libshapeproc/geometry/segment_distance.hpp"
#include "libshapeproc/geometry/triangle_distance.hpp"
#include "tests/geometry/measurement_fixtures.hpp"

namespace shapeproc::geometry {
namespace {

using namespace fixtures;

MeasurementOptions fine() {
  MeasurementOptions options;
  options.proxy.tolerance = 1e-4;
  return options;
}

// Proxies that keep every segment: the proxy is the polygon itself.
MeasurementOptions exact() {
  MeasurementOptions options;
  options.proxy.tolerance = 0.0;
  return options;
}

double measured(const std::vector<Shape>& shapes, const std::vector<Vec2>& positions,
                const MeasurementOptions& options = fine()) {
  const Scene scene = scene_of(shapes, positions);
  const PairMeasurer measurer(scene, options);
  return measurer.measure(scene.elements[0], scene.elements[1]).distance;
}

double angle_between(const Vec3& a, const Vec3& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * 180 / core::kPi;
}

TEST(ShapeDistance, BoxesWithKnownGaps) {
  const Shape square = planar({rectangle(0, 0, 2, 2)});
  EXPECT_DOUBLE_EQ(measured({square, square}, {{0, 0}, {5, 0}}), 3.0);
  EXPECT_DOUBLE_EQ(measured({square, square}, {{0, 0}, {5, 6}}), 5.0);    // corner to corner 3-4-5
  EXPECT_DOUBLE_EQ(measured({square, square}, {{0, 0}, {2, 2}}), 0.0);    // touching at a corner
  EXPECT_DOUBLE_EQ(measured({square, square}, {{0, 0}, {2, 0.5}}), 0.0);  // sharing an edge
  // Overlapping: minus the depth of the deepest corner inside the other square.
  EXPECT_DOUBLE_EQ(measured({square, square}, {{0, 0}, {1, 0.5}}), -0.5);
}

TEST(ShapeDistance, DiscsAreCentreDistanceMinusRadii) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.5, 3.0), angle(0, 2 * core::kPi);
  for (int trial = 0; trial < 40; ++trial) {
    const double r1 = u(rng), r2 = u(rng), gap = u(rng) - 0.5, a = angle(rng);
    const double c = r1 + r2 + gap;
    const double d = measured({disc(r1), disc(r2)}, {{0, 0}, {c * std::cos(a), c * std::sin(a)}});
    // Proxies are inscribed polygons: never closer than the true shapes, within the tolerance.
    const double tolerance = 1e-4 * 2 * std::sqrt(2) * (r1 + r2) + 1e-3 * (r1 + r2);
    EXPECT_NEAR(d, std::max(gap, 0.0), tolerance) << r1 << " " << r2 << " " << gap;
  }
}

TEST(ShapeDistance, FilledRegionsHoldWhatIsInsideThem) {
  const Shape dot = disc(0.5);
  // A dot inside a filled disc overlaps it: minus the depth of its deepest point (7.5).
  EXPECT_NEAR(measured({disc(10), dot}, {{0, 0}, {3, 0}}), -7.5, 1e-2);
  // A dot in a ring's hole (nonzero winding with a reversed hole) is apart from the ring.
  EXPECT_NEAR(measured({ring(10, 6), dot}, {{0, 0}, {1, 0}}), 6 - 1.5, 1e-2);
  // The same ring drawn with even-odd and both circles the same way round.
  const Shape evenodd = planar(
      {ellipse_path(Vec2::Zero(), 10, 10), ellipse_path(Vec2::Zero(), 6, 6)}, FillRule::evenodd);
  EXPECT_NEAR(measured({evenodd, dot}, {{0, 0}, {1, 0}}), 4.5, 1e-2);
  EXPECT_NEAR(measured({evenodd, dot}, {{0, 0}, {8, 0}}), -1.98, 2e-2);  // in the ring's body
  // An unfilled circle is a curve: a dot inside is apart from it.
  const Shape outline = planar({ellipse_path(Vec2::Zero(), 10, 10)}, FillRule::nonzero, false);
  EXPECT_NEAR(measured({outline, dot}, {{0, 0}, {3, 0}}), 10 - 3.5, 1e-2);
  // Open curves crossing each other.
  const Shape stroke = planar({polygon({{-5, 0}, {5, 0}}, false)});
  // Open curves crossing each other overlap, by a depth the vertices do not show.
  const double crossing =
      measured({stroke, planar({polygon({{0, -5}, {0, 5}}, false)})}, {{0, 0}, {1, 0}});
  EXPECT_LT(crossing, 0.0);
  EXPECT_GT(crossing, -1e-6);
  // Touching at an end is not overlapping.
  EXPECT_DOUBLE_EQ(measured({stroke, planar({polygon({{0, 0}, {0, 5}}, false)})}, {{0, 0}, {5, 0}}),
                   0.0);
  EXPECT_DOUBLE_EQ(measured({stroke, stroke}, {{0, 0}, {0, 2}}), 2.0);
  // Nested elongated and interlocking shapes: an L inside another L's notch.
  const Shape ell = planar({polygon({{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 4}, {0, 4}})});
  EXPECT_NEAR(measured({ell, ell}, {{0, 0}, {1.5, 1.5}}), 0.5, 1e-12);
}

TEST(ShapeDistance, InsideThroughTheSegmentTreeIsTheWindingNumber) {  // NOLINT
  // 24 random star polygons of 5 to 34 corners, probed on a grid and at their vertices' heights.
  const auto [shapes, positions] = scatter_polygons(4, 24, 5, 30, 2.0, -6, 6);
  const PairMeasurer measurer(scene_of(shapes, positions), exact());
  int inside = 0;
  for (const Proxy2& proxy : measurer.proxies2()) {
    const auto& ring = proxy.polylines[0].points;
    std::vector<Vec2> probes;
    for (int gx = -40; gx <= 40; ++gx)
      for (int gy = -40; gy <= 40; ++gy) probes.emplace_back(0.1 * gx, 0.1 * gy);
    for (const Vec2& v : ring) probes.emplace_back(v.x() - 0.05, v.y());  // at a vertex's height
    for (const Vec2& p : probes) {
      const bool expected = winding_number(ring, p) != 0;
      EXPECT_EQ(proxy.inside(p), expected) << p.transpose();
      inside += expected ? 1 : 0;
    }
  }
  EXPECT_GT(inside, 100);  // the probes do reach inside
}

TEST(ShapeDistance, BvhAgreesWithBruteForceOnRandomShapes) {  // NOLINT
  const auto [shapes, positions] = scatter_polygons(9, 24, 5, 30, 2.0, -6, 6);
  const Scene scene = scene_of(shapes, positions);
  const PairMeasurer measurer(scene, exact());
  for (std::size_t i = 0; i < scene.elements.size(); ++i) {
    for (std::size_t j = 0; j < scene.elements.size(); ++j) {
      if (i == j) continue;
      const auto& pa = measurer.proxies2()[scene.elements[i].shape];
      const auto& pb = measurer.proxies2()[scene.elements[j].shape];
      const Vec2 t = (scene.elements[j].position - scene.elements[i].position).head<2>();
      double brute = INFINITY;
      for (std::size_t s = 0; s < pa.segment_count(); ++s)
        for (std::size_t k = 0; k < pb.segment_count(); ++k)
          brute = std::min(
              brute, segment_segment_distance(pa.segment_start[s], pa.segment_end[s],
                                              pb.segment_start[k] + t, pb.segment_end[k] + t));
      // Star-shaped polygons around their centres: one inside the other iff a vertex is inside.
      if (pa.inside(pb.polylines[0].points[0] + t) || pb.inside(pa.polylines[0].points[0] - t))
        brute = 0.0;
      const double d = measurer.measure(scene.elements[i], scene.elements[j]).distance;
      if (brute == 0.0) {  // overlapping (random polygons do not touch exactly)
        EXPECT_LT(d, 0.0) << i << " " << j;
        EXPECT_DOUBLE_EQ(d, -overlap_depth(pa, pb, t)) << i << " " << j;
        // Asked only whether they overlap: the first vertex inside, positive, at most the depth.
        const double any = overlap_depth(pa, pb, t, true);
        EXPECT_GT(any, 0.0) << i << " " << j;
        EXPECT_LE(any, -d) << i << " " << j;
      } else {
        EXPECT_NEAR(d, brute, 1e-12) << i << " " << j;
      }
      // Symmetric, and the cut-off form agrees below the cut-off.
      EXPECT_DOUBLE_EQ(d, measurer.measure(scene.elements[j], scene.elements[i]).distance);
      const double cut = measurer.measure(scene.elements[i], scene.elements[j], 1.0).distance;
      EXPECT_DOUBLE_EQ(cut, std::min(d, 1.0));
    }
  }
}

// With breakpoints the distance may be any value of the interval that holds the exact one.
TEST(ShapeDistance, BreakpointsDecideTheIntervalOfTheExactDistance) {  // NOLINT
  auto [shapes, positions] = scatter_polygons(21, 24, 5, 30, 2.0, -6, 6);
  shapes.push_back(ring(3, 2));  // holds small shapes in its hole, or in its body
  positions.emplace_back(0.0, 0.0);
  shapes.push_back(disc(0.3));
  positions.emplace_back(0.2, 0.1);
  shapes.push_back(disc(0.2));
  positions.emplace_back(2.5, 0.0);
  for (const bool periodic : {false, true}) {
    const Box3 window(Vec3(-7, -7, 0), Vec3(7, 7, 0));
    const Scene scene = scene_of(shapes, positions, window);
    MeasurementOptions options;
    options.proxy.tolerance = 0.0;
    options.periodic = periodic;
    const PairMeasurer measurer(scene, options);
    for (const std::vector<double>& breakpoints :
         {std::vector<double>{0.0, 0.5, 1.0, 3.0}, std::vector<double>{0.2, 0.25, 2.0},
          std::vector<double>{1.5}}) {
      const double cutoff = breakpoints.back();
      auto interval = [&](double d) {
        return std::upper_bound(breakpoints.begin(), breakpoints.end(), d) - breakpoints.begin();
      };
      int inside_interval = 0;
      for (std::size_t i = 0; i < scene.elements.size(); ++i) {
        for (std::size_t j = 0; j < scene.elements.size(); ++j) {
          if (i == j) continue;
          const Measurement exact =
              measurer.measure_distance(scene.elements[i], scene.elements[j], cutoff);
          const Measurement coarse =
              measurer.measure_distance(scene.elements[i], scene.elements[j], cutoff, &breakpoints);
          EXPECT_EQ(interval(coarse.distance), interval(exact.distance))
              << i << " " << j << " " << exact.distance;
          EXPECT_LE(coarse.distance, cutoff);
          if (coarse.distance != exact.distance) ++inside_interval;
        }
      }
      // The interval form does stop early (otherwise it would return the exact distances).
      EXPECT_GT(inside_interval, 0);
    }
  }
}

// Discs, rings and points, whose outlines lie between two circles about their reference
// positions: apart, those circles alone often decide the interval (rings: the dots of rings,
// most pairs of a sparse scatter), and the interval must still be the exact distance's.
TEST(ShapeDistance, CirclesAboutTheReferencePositionsDecideTheInterval) {  // NOLINT
  std::vector<Shape> shapes;
  std::vector<Vec2> positions;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> radius(0.2, 1.2), position(-9, 9);
  for (int k = 0; k < 40; ++k) {
    const double r = radius(rng);
    shapes.push_back(k % 3 == 0   ? ring(r, 0.4 * r)
                     : k % 3 == 1 ? disc(r)
                                  : Shape{PointShape{}, "point"});
    positions.emplace_back(position(rng), position(rng));
  }
  const std::vector<double> breakpoints{0.0, 0.4, 0.45, 1.0, 2.5, 2.6, 4.0};
  const auto interval = [&](double d) {
    return std::upper_bound(breakpoints.begin(), breakpoints.end(), d) - breakpoints.begin();
  };
  for (const bool periodic : {false, true}) {
    const Scene scene = scene_of(shapes, positions, Box3(Vec3(-10, -10, 0), Vec3(10, 10, 0)));
    MeasurementOptions options;
    options.periodic = periodic;
    const PairMeasurer measurer(scene, options);
    int decided = 0;
    for (std::size_t i = 0; i < scene.elements.size(); ++i) {
      for (std::size_t j = 0; j < scene.elements.size(); ++j) {
        if (i == j) continue;
        const double exact =
            measurer.measure_distance(scene.elements[i], scene.elements[j], 4.0).distance;
        const double coarse =
            measurer.measure_distance(scene.elements[i], scene.elements[j], 4.0, &breakpoints)
                .distance;
        EXPECT_EQ(interval(coarse), interval(exact)) << i << " " << j << " " << exact;
        if (exact < 4.0 && coarse != exact) ++decided;
      }
    }
    EXPECT_GT(decided, 0);
  }
}

TEST(ShapeDistance, VariantsForComparison) {
  const Shape square = planar({rectangle(-1, -1, 1, 1)});
  MeasurementOptions centroid = fine();
  centroid.distance = DistanceKind::centroid;
  EXPECT_DOUBLE_EQ(measured({square, square}, {{0, 0}, {3, 4}}, centroid), 5.0);
  MeasurementOptions hausdorff = fine();
  hausdorff.distance = DistanceKind::hausdorff;
  // Translated copies: every outline point is 5 from the other outline; a wider rectangle around
  // the square reaches 1 beyond it.
  EXPECT_NEAR(measured({square, square}, {{0, 0}, {5, 0}}, hausdorff), 5.0, 1e-9);
  EXPECT_NEAR(measured({square, planar({rectangle(-2, -1, 2, 1)})}, {{0, 0}, {0, 0}}, hausdorff),
              1.0, 1e-9);
}

TEST(Periodic, MinimumImageAcrossTheWindowEdge) {
  const Box3 window(Vec3(0, 0, 0), Vec3(100, 50, 0));
  const Scene scene = scene_of({disc(2), disc(3)}, {{3, 25}, {96, 25}}, window);
  MeasurementOptions open = fine(), torus = fine();
  torus.periodic = true;
  const Measurement far = PairMeasurer(scene, open).measure(scene.elements[0], scene.elements[1]);
  const Measurement near = PairMeasurer(scene, torus).measure(scene.elements[0], scene.elements[1]);
  EXPECT_NEAR(far.distance, 93 - 5, 1e-2);
  EXPECT_NEAR(near.distance, 7 - 5, 1e-2);
  EXPECT_NEAR(near.direction.x(), -1.0, 1e-6);  // the nearest image is to the left
  EXPECT_EQ(near.offset, Vec3(-7, 0, 0));
  // Corners: the diagonal image.
  const Scene corners = scene_of({disc(1), disc(1)}, {{2, 2}, {98, 48}}, window);
  EXPECT_NEAR(
      PairMeasurer(corners, torus).measure(corners.elements[0], corners.elements[1]).distance,
      std::hypot(4.0, 4.0) - 2, 1e-2);
}

TEST(Gravitation, ExactlyAntisymmetricAndTranslationInvariant) {
  const auto [shapes, positions] = scatter_polygons(21, 10, 7, 1, 2.5, 0, 20);
  const Scene scene = scene_of(shapes, positions);
  const PairMeasurer measurer(scene, MeasurementOptions{});
  std::vector<Vec2> moved = positions;
  for (Vec2& p : moved) p += Vec2(123.25, -47.5);
  const Scene translated = scene_of(shapes, moved);
  const PairMeasurer moved_measurer(translated, MeasurementOptions{});
  for (int i = 0; i < 10; ++i) {
    for (int j = 0; j < 10; ++j) {
      if (i == j) continue;
      const Measurement ab = measurer.measure(scene.elements[i], scene.elements[j]);
      const Measurement ba = measurer.measure(scene.elements[j], scene.elements[i]);
      EXPECT_EQ(ba.direction, -ab.direction);  // bit for bit
      EXPECT_EQ(ab.axis, ba.axis);
      const Measurement moved_ab =
          moved_measurer.measure(translated.elements[i], translated.elements[j]);
      // Equal up to rounding in the shapes' local coordinates.
      EXPECT_LT(angle_between(ab.direction, moved_ab.direction), 1e-6);
      EXPECT_NEAR(ab.distance, moved_ab.distance, 1e-9);
    }
  }
}

// The exact boundary integral against a dense brute-force double sum over cell-centre samples of
// the same proxies' masses, on one lattice for both shapes (so that samples of an overlap
// coincide and their contributions cancel: pairs closer than 1e-9 cell are skipped).
Vec2 dense_force(const Proxy2& a, const Proxy2& b, const Vec2& offset) {
  const double cell = std::max(a.box.sizes().maxCoeff(), b.box.sizes().maxCoeff()) / 160;
  const Vec2 lattice(std::fmod(offset.x(), cell), std::fmod(offset.y(), cell));
  const MassModel2 ma = sample_mass(a, cell, Vec2::Zero(), 1),
                   mb = sample_mass(b, cell, -lattice, 1);
  Vec2 total = Vec2::Zero();
  for (std::size_t i = 0; i < ma.points.size(); ++i) {
    for (std::size_t j = 0; j < mb.points.size(); ++j) {
      const Vec2 r = mb.points[j] + offset - ma.points[i];
      const double r2 = r.squaredNorm();
      if (r2 <= 1e-18 * cell * cell) continue;
      total += (ma.weights[i] * mb.weights[j] / (r2 * std::sqrt(r2))) * r;
    }
  }
  return total;
}

void expect_near_brute_force(const std::vector<Shape>& shapes, const std::vector<Vec2>& positions,
                             const char* what) {
  const Scene scene = scene_of(shapes, positions);
  const PairMeasurer measurer(scene, MeasurementOptions{});
  const Vec3 offset = scene.elements[1].position - scene.elements[0].position;
  const Vec2 exact = dense_force(measurer.proxies2()[0], measurer.proxies2()[1], offset.head<2>());
  const Vec3 ours = measurer.direction(0, 1, offset);
  EXPECT_LT(angle_between(ours, Vec3(exact.x(), exact.y(), 0)), 1.0) << what;
}

TEST(Gravitation, WithinOneDegreeOfDenseBruteForce) {
  const Shape ell = planar({polygon({{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 4}, {0, 4}})});
  const Shape bar = planar({rectangle(-5, -0.5, 5, 0.5)});
  const Shape square = planar({rectangle(-1, -1, 1, 1)});
  const Shape crescent = planar({polygon({{-4, 0}, {-2, 2}, {2, 2}, {4, 0}, {2, 1}, {-2, 1}})});
  expect_near_brute_force({ell, ell}, {{0, 0}, {1.5, 1.5}}, "interlocking L shapes");
  expect_near_brute_force({bar, square}, {{0, 0}, {4, 1.5}}, "square touching a bar's end");
  expect_near_brute_force({square, square}, {{0, 0}, {2, 2}}, "squares touching at a corner");
  expect_near_brute_force({crescent, crescent}, {{0, 0}, {0, 1}},
                          "nested crescents touching along an edge");
  expect_near_brute_force({crescent, crescent}, {{0, 0}, {0, 1.1}},
                          "nested crescents, a gap of 0.1");
  expect_near_brute_force({crescent, crescent}, {{0, 0}, {0.5, 1.1}}, "crescents overlapping");
  expect_near_brute_force({bar, planar({polygon({{-3, 0}, {3, 0}}, false)})}, {{0, 0}, {1, 0.75}},
                          "an open curve (its strip) beside a bar");
  expect_near_brute_force({bar, bar}, {{0, 0}, {3, 8}}, "parallel bars, slanted");
  expect_near_brute_force({ring(5, 3), disc(1)}, {{0, 0}, {1, 0.5}},
                          "dot off-centre in a ring's hole");
}

// certain_axis promises the axis of every offset within the slack: check it on random shapes,
// offsets and slacks against the direction measured at points of the slack's disc (and count
// that the multipole bound decides beyond the boxes' cone).
TEST(Gravitation, CertainAxisHoldsOverItsDisc) {
  std::mt19937 rng(7);
  std::vector<Shape> shapes;
  std::vector<Vec2> positions;
  for (int k = 0; k < 6; ++k) {
    shapes.push_back(random_polygon(rng, 5 + k, 2.0 + 0.5 * k));
    positions.push_back({12.0 * k, 0.0});
  }
  shapes.push_back(planar({rectangle(-4, -0.5, 4, 0.5)}));
  positions.push_back({100, 0});
  const Scene scene = scene_of(shapes, positions);
  const PairMeasurer measurer(scene, MeasurementOptions{});
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int decided = 0, beyond_boxes = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const int a = static_cast<int>(rng() % shapes.size()),
              b = static_cast<int>(rng() % shapes.size());
    const double angle = 2 * core::kPi * unit(rng), distance = 8.0 + 40.0 * unit(rng),
                 slack = 4.0 * unit(rng);
    const Vec3 offset(distance * std::cos(angle), distance * std::sin(angle), 0.0);
    const int axis = measurer.certain_axis(a, b, offset, slack);
    if (axis < 0) continue;
    ++decided;
    if (measurer.axis_from_boxes(a, b, offset, slack) < 0) ++beyond_boxes;
    for (int k = 0; k < 24; ++k) {
      const double r = slack * std::sqrt(unit(rng)), t = 2 * core::kPi * unit(rng);
      const Vec3 o = offset + Vec3(r * std::cos(t), r * std::sin(t), 0.0);
      ASSERT_EQ(measurer.bins().axis_of(measurer.direction(a, b, o)), axis)
          << a << " " << b << " " << trial;
    }
    // The disc's rim, where the angle strays most.
    for (int k = 0; k < 16; ++k) {
      const Vec3 o =
          offset + slack * Vec3(std::cos(k * core::kPi / 8), std::sin(k * core::kPi / 8), 0.0);
      ASSERT_EQ(measurer.bins().axis_of(measurer.direction(a, b, o)), axis)
          << a << " " << b << " " << trial;
    }
  }
  EXPECT_GT(decided, 1000);
  EXPECT_GT(beyond_boxes, 300);
}

TEST(Gravitation, DiffersFromCentroidsForElongatedShapes) {
  // Paper Fig. 3: two long bars side by side, offset along their length: the centroid direction
  // is slanted, the gravitation direction is closer to perpendicular.
  const Shape bar = planar({rectangle(-5, -0.5, 5, 0.5)});
  const Scene scene = scene_of({bar, bar}, {{0, 0}, {6, 2}});
  const PairMeasurer measurer(scene, MeasurementOptions{});
  const Vec3 o = measurer.measure(scene.elements[0], scene.elements[1]).direction;
  const double slant_gravitation = std::abs(std::atan2(o.x(), o.y()));
  const double slant_centroid = std::atan2(6.0, 2.0);
  EXPECT_LT(slant_gravitation, slant_centroid - 0.2);
}

TEST(Measurements3D, MeshDistancesAndContainment) {
  const TriangleMesh cube = box_mesh(Vec3(-1, -1, -1), Vec3(1, 1, 1));
  const TriangleMesh small = box_mesh(Vec3(-0.2, -0.2, -0.2), Vec3(0.2, 0.2, 0.2));
  const TriangleMesh sphere = uv_sphere(1.0, 24, 12);
  const Scene scene =
      scene_of_meshes({cube, cube, small, sphere, sphere},
                      {{0, 0, 0}, {5, 0, 0}, {0.3, 0.1, 0}, {0, 10, 0}, {3, 13, 1}});
  MeasurementOptions options;
  options.directions = 12;
  options.proxy.tolerance = 1e-3;
  const PairMeasurer measurer(scene, options);
  const auto& e = scene.elements;
  EXPECT_NEAR(measurer.measure(e[0], e[1]).distance, 3.0, 1e-12);
  // A small cube inside the big one overlaps it: minus its deepest corner's depth.
  EXPECT_LT(measurer.measure(e[0], e[2]).distance, 0.0);
  const double spheres = std::sqrt(9.0 + 9.0 + 1.0) - 2.0;
  EXPECT_NEAR(measurer.measure(e[3], e[4]).distance, spheres, 0.05);  // polyhedral spheres
  EXPECT_GE(measurer.measure(e[3], e[4]).distance, spheres - 1e-9);
  const Measurement ab = measurer.measure(e[0], e[1]);
  EXPECT_EQ(measurer.measure(e[1], e[0]).direction, -ab.direction);
  EXPECT_NEAR(ab.direction.x(), 1.0, 1e-9);
  EXPECT_TRUE(measurer.proxies3()[3].closed);
}

// Meshes at random offsets, some touching or crossing: with breakpoints, the 3D distance is a
// value of the interval that holds the exact one, and the search does stop early.
TEST(Measurements3D, BreakpointsDecideTheIntervalOfTheExactDistance) {  // NOLINT
  const TriangleMesh cube = box_mesh(Vec3(-0.6, -0.4, -0.5), Vec3(0.6, 0.4, 0.5));
  const TriangleMesh sphere = uv_sphere(0.7, 12, 8);
  std::vector<TriangleMesh> meshes;
  std::vector<Vec3> positions;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> position(-2.5, 2.5);
  for (int k = 0; k < 16; ++k) {
    meshes.push_back(k % 2 == 0 ? cube : sphere);
    positions.emplace_back(position(rng), position(rng), position(rng));
  }
  const Scene scene = scene_of_meshes(meshes, positions);
  MeasurementOptions options;
  options.directions = 12;
  const PairMeasurer measurer(scene, options);
  for (const std::vector<double>& breakpoints :
       {std::vector<double>{0.0, 0.3, 0.9, 2.0}, std::vector<double>{0.5, 1.5}}) {
    const double cutoff = breakpoints.back();
    const auto interval = [&](double d) {
      return std::upper_bound(breakpoints.begin(), breakpoints.end(), d) - breakpoints.begin();
    };
    int decided = 0, touching = 0;
    for (std::size_t i = 0; i < scene.elements.size(); ++i) {
      for (std::size_t j = 0; j < scene.elements.size(); ++j) {
        if (i == j) continue;
        const double exact =
            measurer.measure_distance(scene.elements[i], scene.elements[j], cutoff).distance;
        const double coarse =
            measurer.measure_distance(scene.elements[i], scene.elements[j], cutoff, &breakpoints)
                .distance;
        EXPECT_EQ(interval(coarse), interval(exact)) << i << " " << j << " " << exact;
        if (coarse != exact) ++decided;
        if (exact <= 0.0) ++touching;
      }
    }
    EXPECT_GT(decided, 0);
    EXPECT_GT(touching, 0);  // the scatter holds meeting pairs, which the first marks separate
  }
}

// The surface integral's near and far triangle pairs together: the force between two closed
// meshes agrees in direction with a fine volume cubature of the same solids (the 3D
// counterpart of the 2D reference), whether they nearly touch or stand apart.
TEST(Measurements3D, SolidGravitationMatchesVolumeCubature) {  // NOLINT
  const TriangleMesh sphere = uv_sphere(1.0, 16, 10);
  const TriangleMesh slab = box_mesh(Vec3(-1.5, -0.5, -0.3), Vec3(1.5, 0.5, 0.3));
  const Scene scene =
      scene_of_meshes({slab, sphere, sphere}, {{0, 0, 0}, {0.9, 0.4, 1.4}, {3.5, 2.0, -1.0}});
  MeasurementOptions options;
  options.directions = 12;
  const PairMeasurer measurer(scene, options);
  ASSERT_TRUE(measurer.proxies3()[0].closed && measurer.proxies3()[1].closed);
  for (const int other : {1, 2}) {
    const Vec3 offset = scene.elements[static_cast<std::size_t>(other)].position;
    const Vec3 reference = gravitation_force_direct(
        sample_mass(measurer.proxies3()[0], 0.08),
        sample_mass(measurer.proxies3()[static_cast<std::size_t>(other)], 0.08), offset);
    EXPECT_LT(angle_between(measurer.direction(0, other, offset), reference), 1.0) << other;
  }
}

TEST(Measurements3D, GravitationNearDenseBruteForce) {
  const TriangleMesh slab = box_mesh(Vec3(-3, -1, -0.5), Vec3(3, 1, 0.5));
  const TriangleMesh cube = box_mesh(Vec3(-1, -1, -1), Vec3(1, 1, 1));
  const Scene scene = scene_of_meshes({slab, cube}, {{0, 0, 0}, {3.5, 0.5, 1.6}});
  MeasurementOptions options;
  options.directions = 12;
  const PairMeasurer measurer(scene, options);
  const Vec3 offset = scene.elements[1].position - scene.elements[0].position;
  const double cell = 0.1;
  const Vec3 exact = gravitation_force_direct(sample_mass(measurer.proxies3()[0], cell),
                                              sample_mass(measurer.proxies3()[1], cell), offset);
  EXPECT_LT(angle_between(measurer.direction(0, 1, offset), exact), 1.0);
}

TEST(Proxies, SimplificationKeepsClosedRingsAndHoles) {
  const Shape r = ring(10, 6);
  ProxyOptions options;
  options.tolerance = 0.005;
  const Proxy2 proxy = make_proxy2(r, options);
  ASSERT_EQ(proxy.polylines.size(), 2u);
  EXPECT_TRUE(proxy.polylines[0].closed);
  EXPECT_TRUE(proxy.polylines[1].closed);
  EXPECT_FALSE(proxy.inside(Vec2(0, 0)));  // the hole
  EXPECT_TRUE(proxy.inside(Vec2(8, 0)));
  // Every proxy vertex within tolerance of the true circles.
  const double bound = options.tolerance * std::hypot(20.0, 20.0);
  for (const auto& polyline : proxy.polylines) {
    for (const Vec2& p : polyline.points) {
      EXPECT_LT(std::min(std::abs(p.norm() - 10), std::abs(p.norm() - 6)), bound);
    }
  }
  // Coarser tolerance, fewer segments.
  options.tolerance = 0.05;
  EXPECT_LT(make_proxy2(r, options).segment_count(), proxy.segment_count());
}

TEST(Proxies, DecimationIsErrorBoundedAndKeepsMeshesClosed) {
  const Shape sphere{MeshShape{uv_sphere(1.0, 48, 24)}, ""};
  const auto& mesh = std::get<MeshShape>(sphere.geometry).mesh;
  const double diagonal = bounding_box(mesh).diagonal().norm();
  std::size_t previous = mesh.triangles.size() + 1;
  for (const double tolerance : {0.002, 0.01, 0.03}) {
    ProxyOptions options;
    options.tolerance = tolerance;
    const Proxy3 proxy = make_proxy3(sphere, options);
    EXPECT_TRUE(proxy.closed);
    EXPECT_LT(proxy.triangles.size(), previous);
    previous = proxy.triangles.size();
    double worst = 0.0;
    for (const Vec3& v : mesh.vertices) {
      double nearest = INFINITY;
      for (const auto& t : proxy.triangles) {
        nearest =
            std::min(nearest, point_triangle_distance(v, proxy.vertices[t[0]], proxy.vertices[t[1]],
                                                      proxy.vertices[t[2]]));
      }
      worst = std::max(worst, nearest);
    }
    EXPECT_LE(worst, tolerance * diagonal * 1.001) << tolerance;
  }
}

}  // namespace
}  // namespace shapeproc::geometry

namespace shapeproc::geometry {
namespace {

TEST(AxisFromBoxes, AgreesWithTheDirectionWheneverItDecides) {
  const auto [shapes, positions] = fixtures::scatter_polygons(77, 30, 9, 1, 2.0, 0, 40);
  const Scene scene = fixtures::scene_of(shapes, positions);
  for (const DirectionKind kind : {DirectionKind::gravitation, DirectionKind::centroid}) {
    MeasurementOptions options;
    options.direction = kind;
    const PairMeasurer measurer(scene, options);
    int decided = 0;
    for (int i = 0; i < 30; ++i) {
      for (int j = 0; j < 30; ++j) {
        if (i == j) continue;
        const Vec3 offset = scene.elements[j].position - scene.elements[i].position;
        const int axis = measurer.axis_from_boxes(i, j, offset);
        if (axis < 0) continue;
        ++decided;
        EXPECT_EQ(axis, measurer.bins().axis_of(measurer.direction(i, j, offset)));
      }
    }
    EXPECT_GT(decided, 300);  // most of the 870 ordered pairs are decided by their boxes
  }
}

}  // namespace
}  // namespace shapeproc::geometry
