#include "libshapeproc/geometry/overlap_depth.hpp"

#include <algorithm>
#include <cmath>

#include "libshapeproc/geometry/box_tree.hpp"
#include "libshapeproc/geometry/pair_measurements.hpp"
#include "libshapeproc/geometry/segment_distance.hpp"
#include "libshapeproc/geometry/triangle_distance.hpp"

namespace shapeproc::geometry {

namespace {

constexpr double kCrossingDepth = 1e-9;  // of the shapes' size, for outlines crossing as an X

// Twice the signed area of (a, b, c), zero within `tolerance` of its scale.
int orientation(const Vec2& a, const Vec2& b, const Vec2& c, double tolerance) {
  const double cross = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
  const double scale = (b - a).norm() * (c - a).norm();
  if (std::abs(cross) <= tolerance * scale) return 0;
  return cross > 0 ? 1 : -1;
}

// Whether two outlines cross properly somewhere: segments meeting at a point inside both, at an
// angle (meeting at an end point, or running together, is touching).
bool outlines_cross(const Proxy2& a, const Proxy2& b, const Vec2& t) {
  constexpr double kTolerance = 1e-12;
  for (std::size_t i = 0; i < a.segment_start.size(); ++i) {
    const Vec2 &a0 = a.segment_start[i], &a1 = a.segment_end[i];
    const Box2 box_a = Box2(a0, a0).extend(a1);
    for (std::size_t j = 0; j < b.segment_start.size(); ++j) {
      const Vec2 b0 = b.segment_start[j] + t, b1 = b.segment_end[j] + t;
      if (!box_a.intersects(Box2(b0, b0).extend(b1))) continue;
      const int o1 = orientation(a0, a1, b0, kTolerance), o2 = orientation(a0, a1, b1, kTolerance);
      const int o3 = orientation(b0, b1, a0, kTolerance), o4 = orientation(b0, b1, a1, kTolerance);
      if (o1 * o2 < 0 && o3 * o4 < 0) return true;
    }
  }
  return false;
}

}  // namespace

double point_to_outline(const Proxy2& proxy, const Vec2& p) {
  BoxTree<2> single = BoxTree<2>::build({Box2(p, p)});
  return closest_pair_distance<2>(
      single, proxy.segment_tree, Vec2::Zero(), PairMeasurer::kNoCutoff, [&](int, int j) {
        return point_segment_distance(p, proxy.segment_start[j], proxy.segment_end[j]);
      });
}

double point_to_surface(const Proxy3& proxy, const Vec3& p) {
  if (proxy.point) return (p - proxy.vertices[0]).norm();
  BoxTree<3> single = BoxTree<3>::build({Box3(p, p)});
  return closest_pair_distance<3>(
      single, proxy.triangle_tree, Vec3::Zero(), PairMeasurer::kNoCutoff, [&](int, int j) {
        const auto& t = proxy.triangles[j];
        return point_triangle_distance(p, proxy.vertices[t[0]], proxy.vertices[t[1]],
                                       proxy.vertices[t[2]]);
      });
}

double overlap_depth(const Proxy2& a, const Proxy2& b, const Vec2& offset, bool any) {
  if (!a.box.intersects(b.box.translated(offset))) return 0.0;
  double depth = 0.0;
  for (const auto& polyline : b.polylines) {
    for (const Vec2& p : polyline.points) {
      if (a.inside(p + offset)) depth = std::max(depth, point_to_outline(a, p + offset));
      if (any && depth > 0.0) return depth;
    }
  }
  for (const auto& polyline : a.polylines) {
    for (const Vec2& p : polyline.points) {
      if (b.inside(p - offset)) depth = std::max(depth, point_to_outline(b, p - offset));
      if (any && depth > 0.0) return depth;
    }
  }
  if (depth > 0.0) return depth;
  if (outlines_cross(a, b, offset)) {
    return kCrossingDepth * std::max(a.box.diagonal().norm(), b.box.diagonal().norm());
  }
  return 0.0;
}

double overlap_depth(const Proxy3& a, const Proxy3& b, const Vec3& offset, bool any) {
  if (!a.box.intersects(b.box.translated(offset))) return 0.0;
  double depth = 0.0;
  if (a.closed) {
    for (const Vec3& p : b.vertices) {
      if (a.inside(p + offset)) depth = std::max(depth, point_to_surface(a, p + offset));
      if (any && depth > 0.0) return depth;
    }
  }
  if (b.closed) {
    for (const Vec3& p : a.vertices) {
      if (b.inside(p - offset)) depth = std::max(depth, point_to_surface(b, p - offset));
      if (any && depth > 0.0) return depth;
    }
  }
  return depth;
}

}  // namespace shapeproc::geometry
