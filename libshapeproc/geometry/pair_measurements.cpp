#include "libshapeproc/geometry/pair_measurements.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "libshapeproc/core/check.hpp"
#include "libshapeproc/core/constants.hpp"
#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/geometry/overlap_depth.hpp"
#include "libshapeproc/geometry/path.hpp"
#include "libshapeproc/geometry/round_shape.hpp"
#include "libshapeproc/geometry/segment_distance.hpp"
#include "libshapeproc/geometry/triangle_distance.hpp"

namespace shapeproc::geometry {

namespace {

// The axis of the 2D direction sector holding every angle in [lowest, highest] (radians, an
// interval shorter than a turn), or -1 when the interval meets two sectors.
int axis_of_angles(const DirectionBins& bins, double lowest, double highest) {
  const double step = 2 * core::kPi / bins.directions();
  const long first = std::lround(lowest / step), last = std::lround(highest / step);
  if (first != last) return -1;
  const long half = bins.directions() / 2;
  return static_cast<int>(((first % half) + half) % half);
}

// Lexicographic sign of a vector: the canonical order of a pair uses it when both shapes are
// the same.
bool lexicographically_negative(const Vec3& v) {
  for (int k = 0; k < 3; ++k) {
    if (v[k] != 0.0) return v[k] < 0.0;
  }
  return false;
}

// Points along a 2D outline at most `step` apart.
std::vector<Vec2> outline_samples(const Proxy2& proxy, double step) {
  std::vector<Vec2> samples;
  for (std::size_t i = 0; i < proxy.segment_start.size(); ++i) {
    const Vec2 a = proxy.segment_start[i], b = proxy.segment_end[i];
    const int pieces = std::max(1, static_cast<int>(std::ceil((b - a).norm() / step)));
    for (int s = 0; s <= pieces; ++s)
      samples.push_back(a + (static_cast<double>(s) / pieces) * (b - a));
  }
  return samples;
}

std::vector<Vec3> surface_samples(const Proxy3& proxy, double step) {
  std::vector<Vec3> samples = proxy.vertices;
  for (const auto& t : proxy.triangles) {
    const Vec3 &a = proxy.vertices[t[0]], &b = proxy.vertices[t[1]], &c = proxy.vertices[t[2]];
    const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    const int m = std::max(1, static_cast<int>(std::ceil(longest / step)));
    for (int i = 0; i <= m; ++i)
      for (int j = 0; i + j <= m; ++j) samples.push_back(a + (i * (b - a) + j * (c - a)) / m);
  }
  return samples;
}

}  // namespace

PairMeasurer::PairMeasurer(const Scene& scene, const MeasurementOptions& options)
    : dimension_(scene.dimension), options_(options), bins_(scene.dimension, options.directions) {
  core::check_non_negative("measure", "the proxy tolerance", options.proxy.tolerance);
  core::check_in_range("measure", "the gravitation theta", options.gravitation_theta, 0.0, 1.0,
                       true);
  if (options.periodic) {
    period_ = scene.window.sizes();
    if (dimension_ == 2) period_.z() = 0.0;
  }
  std::vector<std::size_t> source(scene.shapes.size(), 0), simplified(scene.shapes.size(), 0),
      mass(scene.shapes.size(), 0);
  for (std::size_t s = 0; s < scene.shapes.size(); ++s) {
    const Shape& shape = scene.shapes[s];
    if (dimension_ == 2) {
      proxies2_.push_back(make_proxy2(shape, options.proxy));
      const Proxy2& p = proxies2_.back();
      // A round shape's outer circle holds its mass too: a curve's strip reaches beyond it.
      double round = round_radius(shape).value_or(-1.0);
      if (round >= 0)
        for (const Vec2& v : p.mass.start) round = std::max(round, v.norm());
      round_.push_back(round);
      double out = 0.0, in = -1.0;
      for (const Vec2& v : p.segment_start) out = std::max(out, v.norm());
      for (const Vec2& v : p.segment_end) out = std::max(out, v.norm());
      for (const Proxy2::Polyline& polyline : p.polylines) {
        if (!polyline.closed || winding_number(polyline.points, Vec2::Zero()) == 0) continue;
        double nearest = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < polyline.points.size(); ++i) {
          nearest = std::min(
              nearest, point_segment_distance(Vec2::Zero(), polyline.points[i],
                                              polyline.points[(i + 1) % polyline.points.size()]));
        }
        in = std::max(in, nearest);
      }
      if (std::holds_alternative<PointShape>(shape.geometry)) in = 0.0;
      outline_out_.push_back(out);
      outline_in_.push_back(in);
      source[s] = p.source_segments;
      simplified[s] = std::holds_alternative<PointShape>(shape.geometry) ? 0 : p.segment_count();
      mass[s] = p.mass.start.size();
      // Farthest corner of the box from the reference position (the origin).
      double r = 0.0;
      for (int corner = 0; corner < 4; ++corner)
        r = std::max(r, p.box.corner(static_cast<Box2::CornerType>(corner)).norm());
      radii_.push_back(r);
    } else {
      proxies3_.push_back(make_proxy3(shape, options.proxy));
      const Proxy3& p = proxies3_.back();
      source[s] = p.source_triangles;
      simplified[s] = p.triangles.size();
      mass[s] = p.closed ? p.solid.triangles.size() : p.mass.points.size();
      // Farthest corner of the box from the reference position (the origin).
      double r = 0.0;
      for (int corner = 0; corner < 8; ++corner)
        r = std::max(r, p.box.corner(static_cast<Box3::CornerType>(corner)).norm());
      radii_.push_back(r);
    }
  }
  // One table of 325 complex numbers per pair of shapes (a ≤ b): up to 64 shapes (10 MB).
  constexpr std::size_t kMaximumExpansionShapes = 64;
  if (dimension_ == 2 && options_.direction == DirectionKind::gravitation &&
      scene.shapes.size() <= kMaximumExpansionShapes) {
    const std::size_t n = scene.shapes.size();
    expansions_ = std::make_shared<ExpansionCache>();
    expansions_->tables.resize(n * n);
    expansions_->once = std::make_unique<std::once_flag[]>(n * n);
  }
  mass_size_.assign(mass.begin(), mass.end());
  constexpr std::size_t kMaximumTableShapes = 1024;  // 4 MB of per-pair query counts
  if (options_.direction == DirectionKind::gravitation && bins_.directions() > 1 &&
      scene.shapes.size() <= kMaximumTableShapes) {
    forces_ =
        std::make_shared<ForceTable>(dimension_, bins_, scene.shapes.size() * scene.shapes.size());
    // Shapes with the same proxy share their grids: the first of them stands for the others.
    table_shape_.resize(scene.shapes.size());
    for (std::size_t s = 0; s < scene.shapes.size(); ++s) {
      table_shape_[s] = static_cast<int>(s);
      for (std::size_t t = 0; t < s; ++t) {
        if (table_shape_[t] == static_cast<int>(t) &&
            same_proxy(static_cast<int>(t), static_cast<int>(s))) {
          table_shape_[s] = static_cast<int>(t);
          break;
        }
      }
    }
  }
  if (!scene.elements.empty()) {
    for (const Element& e : scene.elements) {
      statistics_.source_per_element += static_cast<double>(source.at(e.shape));
      statistics_.proxy_per_element += static_cast<double>(simplified.at(e.shape));
      statistics_.mass_per_element += static_cast<double>(mass.at(e.shape));
    }
    const double n = static_cast<double>(scene.elements.size());
    statistics_.source_per_element /= n;
    statistics_.proxy_per_element /= n;
    statistics_.mass_per_element /= n;
  }
}

double PairMeasurer::outline_bracket(int a, int b, const Vec2& offset, double cutoff,
                                     const std::vector<double>& breakpoints) const {
  const std::size_t i = static_cast<std::size_t>(a), j = static_cast<std::size_t>(b);
  constexpr double kUndecided = std::numeric_limits<double>::quiet_NaN();
  if (outline_in_[i] < 0 || outline_in_[j] < 0) return kUndecided;
  const double centres = offset.norm();
  // Apart by more than rounding (contact in shape_distance): the outlines cannot meet.
  const double lo = centres - outline_out_[i] - outline_out_[j];
  if (!(lo > 1e-9 * (radii_[i] + radii_[j]))) return kUndecided;
  if (lo >= cutoff) return cutoff;
  // The ray from each reference position towards the other leaves its enclosing polyline at
  // outline_in_ or farther: two outline points at most this far apart.
  const double hi = centres - outline_in_[i] - outline_in_[j];
  if (hi >= cutoff) return kUndecided;
  const auto interval = [&](double d) {
    return std::upper_bound(breakpoints.begin(), breakpoints.end(), d) - breakpoints.begin();
  };
  return interval(lo) == interval(hi) ? lo : kUndecided;
}

namespace {

// The prune of a closest-pair search that needs only the interval between `marks` holding the
// distance: nothing below the mark under the best distance so far can move the result into
// another interval.
auto interval_floor(const std::vector<double>& marks) {
  return [&marks](double best_squared) {
    const double best = std::sqrt(best_squared);
    const auto above = std::upper_bound(marks.begin(), marks.end(), best);
    if (above == marks.begin()) return 0.0;
    const double low = *(above - 1);
    return low * low;
  };
}

// A lower bound of the squared distance between triangles (a0, a1, a2) and (b0, b1, b2): the
// squared distance from the plane of the first to the nearest corner of the second when all three
// lie strictly on one side of it, else 0 (also for a degenerate first triangle).
double plane_gap_squared(const Vec3& a0, const Vec3& a1, const Vec3& a2, const Vec3& b0,
                         const Vec3& b1, const Vec3& b2) {
  const Vec3 normal = (a1 - a0).cross(a2 - a0);
  const double area2 = normal.squaredNorm();
  if (!(area2 > 0.0)) return 0.0;
  const double h0 = normal.dot(b0 - a0), h1 = normal.dot(b1 - a0), h2 = normal.dot(b2 - a0);
  const double nearest = h0 > 0.0 && h1 > 0.0 && h2 > 0.0   ? std::min({h0, h1, h2})
                         : h0 < 0.0 && h1 < 0.0 && h2 < 0.0 ? -std::max({h0, h1, h2})
                                                            : 0.0;
  return nearest * nearest / area2;
}

}  // namespace

double PairMeasurer::shape_distance(int a, int b, const Vec3& offset, double cutoff,
                                    const std::vector<double>* breakpoints) const {
  // With no breakpoint below 0, every overlap's depth lies in one interval: the first vertex found
  // inside gives a value of it.
  const bool any_depth =
      breakpoints != nullptr && !breakpoints->empty() && breakpoints->front() >= 0;
  if (dimension_ == 2) {
    const Proxy2& pa = proxies2_[a];
    const Proxy2& pb = proxies2_[b];
    const Vec2 t = offset.head<2>();
    const Box2 moved = pb.box.translated(t);
    if (std::sqrt(pa.box.squaredExteriorDistance(moved)) >= cutoff) return cutoff;
    if (breakpoints != nullptr && !breakpoints->empty()) {
      const double bracketed = outline_bracket(a, b, t, cutoff, *breakpoints);
      if (!std::isnan(bracketed)) return bracketed;
    }
    auto segments = [&](int i, int j, double bound) {
      const Vec2 &a0 = pa.segment_start[i], &a1 = pa.segment_end[i];
      const Vec2 b0 = pb.segment_start[j] + t, b1 = pb.segment_end[j] + t;
      // The gap between the segments' boxes first: most pairs of a leaf are not nearer.
      const double gap_x = std::max({0.0, std::min(b0.x(), b1.x()) - std::max(a0.x(), a1.x()),
                                     std::min(a0.x(), a1.x()) - std::max(b0.x(), b1.x())});
      const double gap_y = std::max({0.0, std::min(b0.y(), b1.y()) - std::max(a0.y(), a1.y()),
                                     std::min(a0.y(), a1.y()) - std::max(b0.y(), b1.y())});
      const double lower = gap_x * gap_x + gap_y * gap_y;
      return lower >= bound ? kNoCutoff : segment_segment_squared_distance(a0, a1, b0, b1);
    };
    double outline;  // distance between the outlines (or a value of its interval)
    // Outlines closer than this meet (rounding of coordinates that were drawn touching).
    const double contact =
        1e-12 * (radii_[static_cast<std::size_t>(a)] + radii_[static_cast<std::size_t>(b)]);
    double first_mark = -kNoCutoff;  // the smallest breakpoint: below it, every d is one interval
    if (breakpoints == nullptr || breakpoints->empty()) {
      outline = std::sqrt(closest_pair_squared_distance<2>(pa.segment_tree, pb.segment_tree, t,
                                                           cutoff * cutoff, segments));
    } else {
      const std::vector<double>& marks = *breakpoints;
      first_mark = marks.front();
      outline = std::sqrt(closest_pair_squared_distance<2>(
          pa.segment_tree, pb.segment_tree, t, cutoff * cutoff, segments, interval_floor(marks)));
      // The search stops once the interval is known; with a breakpoint at or below 0, outlines
      // that meet (0 or below) are in another interval than a small gap: look for contact alone.
      if (first_mark <= 0.0 && contact > 0.0 && outline > contact && outline < kNoCutoff) {
        const double near = std::sqrt(closest_pair_squared_distance<2>(
            pa.segment_tree, pb.segment_tree, t, 4 * contact * contact, segments));
        if (near <= contact)
          outline = near;  // (the search returns its cut-off, 2 contact, if none)
      }
    }
    // Outlines that meet: touching (0) or overlapping (minus the overlap's depth).
    if (outline <= contact) return -overlap_depth(pa, pb, t, any_depth);
    // One shape inside the other's filled region (their outlines apart): one vertex of every
    // polyline decides. Needed only when a negative distance lies in another interval than the
    // outlines' gap, i.e. some breakpoint is at most the gap.
    if (outline >= first_mark && pa.box.intersects(moved)) {
      for (const auto& polyline : pb.polylines) {
        if (pa.inside(polyline.points.front() + t)) return -overlap_depth(pa, pb, t, any_depth);
      }
      for (const auto& polyline : pa.polylines) {
        if (pb.inside(polyline.points.front() - t)) return -overlap_depth(pa, pb, t, any_depth);
      }
    }
    return outline;
  }
  const Proxy3& pa = proxies3_[a];
  const Proxy3& pb = proxies3_[b];
  const Box3 moved = pb.box.translated(offset);
  if (std::sqrt(pa.box.squaredExteriorDistance(moved)) >= cutoff) return cutoff;
  if (pa.box.intersects(moved)) {
    if (pa.inside(pb.vertices.front() + offset) || pb.inside(pa.vertices.front() - offset))
      return -overlap_depth(pa, pb, offset, any_depth);
  }
  auto corner = [](const Proxy3& p, int t, int k) -> const Vec3& {
    return p.point ? p.vertices[0] : p.vertices[p.triangles[t][k]];
  };
  auto triangles = [&](int i, int j, double bound) {
    const Vec3 &a0 = corner(pa, i, 0), &a1 = corner(pa, i, 1), &a2 = corner(pa, i, 2);
    const Vec3 b0 = corner(pb, j, 0) + offset, b1 = corner(pb, j, 1) + offset,
               b2 = corner(pb, j, 2) + offset;
    // The gap between the triangles' boxes first: most pairs of a leaf are not nearer.
    const Vec3 gap = (b0.cwiseMin(b1).cwiseMin(b2) - a0.cwiseMax(a1).cwiseMax(a2))
                         .cwiseMax(a0.cwiseMin(a1).cwiseMin(a2) - b0.cwiseMax(b1).cwiseMax(b2))
                         .cwiseMax(0.0);
    if (gap.squaredNorm() >= bound) return kNoCutoff;
    // Then the plane of either triangle, where the other lies wholly on one side of it.
    if (plane_gap_squared(a0, a1, a2, b0, b1, b2) >= bound ||
        plane_gap_squared(b0, b1, b2, a0, a1, a2) >= bound)
      return kNoCutoff;
    const double d = triangle_triangle_distance(a0, a1, a2, b0, b1, b2);
    return d * d;
  };
  double surfaces;  // distance between the surfaces (or a value of its interval)
  if (breakpoints == nullptr || breakpoints->empty()) {
    surfaces = std::sqrt(closest_pair_squared_distance<3>(pa.triangle_tree, pb.triangle_tree,
                                                          offset, cutoff * cutoff, triangles));
  } else {
    surfaces = std::sqrt(closest_pair_squared_distance<3>(pa.triangle_tree, pb.triangle_tree,
                                                          offset, cutoff * cutoff, triangles,
                                                          interval_floor(*breakpoints)));
    // With a breakpoint at or below 0, surfaces that meet are in another interval than a small
    // gap: look for contact alone.
    const double contact =
        1e-12 * (radii_[static_cast<std::size_t>(a)] + radii_[static_cast<std::size_t>(b)]);
    if (breakpoints->front() <= 0.0 && contact > 0.0 && surfaces > 0.0 && surfaces < cutoff) {
      if (closest_pair_squared_distance<3>(pa.triangle_tree, pb.triangle_tree, offset,
                                           contact * contact, triangles) <= 0.0)
        surfaces = 0.0;
    }
  }
  return surfaces <= 0.0 ? -overlap_depth(pa, pb, offset, any_depth) : surfaces;
}

double PairMeasurer::hausdorff_distance(int a, int b, const Vec3& offset) const {
  double worst = 0.0;
  if (dimension_ == 2) {
    const Proxy2& pa = proxies2_[a];
    const Proxy2& pb = proxies2_[b];
    const Vec2 t = offset.head<2>();
    const double step =
        std::max(1e-9, 0.01 * std::max(pa.box.diagonal().norm(), pb.box.diagonal().norm()));
    for (const Vec2& p : outline_samples(pa, step))
      worst = std::max(worst, point_to_outline(pb, p - t));
    for (const Vec2& p : outline_samples(pb, step))
      worst = std::max(worst, point_to_outline(pa, p + t));
    return worst;
  }
  const Proxy3& pa = proxies3_[a];
  const Proxy3& pb = proxies3_[b];
  const double step =
      std::max(1e-9, 0.05 * std::max(pa.box.diagonal().norm(), pb.box.diagonal().norm()));
  for (const Vec3& p : surface_samples(pa, step))
    worst = std::max(worst, point_to_surface(pb, p - offset));
  for (const Vec3& p : surface_samples(pb, step))
    worst = std::max(worst, point_to_surface(pa, p + offset));
  return worst;
}

double PairMeasurer::distance(int a, int b, const Vec3& offset, double cutoff,
                              const std::vector<double>* breakpoints) const {
  // Canonical order, so that d(b, a) == d(a, b) bit for bit.
  if (a > b || (a == b && lexicographically_negative(offset)))
    return distance(b, a, -offset, cutoff, breakpoints);
  switch (options_.distance) {
    case DistanceKind::shape:
      return shape_distance(a, b, offset, cutoff, breakpoints);
    case DistanceKind::centroid:
      return std::min(cutoff, offset.norm());
    case DistanceKind::hausdorff:
      return std::min(cutoff, hausdorff_distance(a, b, offset));
  }
  return cutoff;
}

Vec3 PairMeasurer::gravitation_force_between(int a, int b, const Vec3& offset) const {
  if (dimension_ == 2) {
    Vec3 force = Vec3::Zero();
    force.head<2>() =
        gravitation_force(proxies2_[a].mass, proxies2_[b].mass, offset.head<2>(), expansion(a, b));
    return force;
  }
  const Proxy3& pa = proxies3_[a];
  const Proxy3& pb = proxies3_[b];
  if (pa.closed && pb.closed) return gravitation_force(pa.solid, pb.solid, offset);
  return gravitation_force(pa.mass, pb.mass, offset, options_.gravitation_theta);
}

double PairMeasurer::negligible_force(int a, int b, const Vec3& offset) const {
  const std::size_t i = static_cast<std::size_t>(a), j = static_cast<std::size_t>(b);
  const double scale = dimension_ == 2
                           ? proxies2_[i].mass.area * proxies2_[j].mass.area
                           : proxies3_[i].mass.total_mass() * proxies3_[j].mass.total_mass();
  return 1e-12 * scale /
         std::max(1e-300, std::pow(radii_[i] + radii_[j] + offset.norm(), dimension_ - 1));
}

bool PairMeasurer::round_apart(int a, int b, const Vec3& offset) const {
  if (dimension_ != 2) return false;
  const double ra = round_[static_cast<std::size_t>(a)], rb = round_[static_cast<std::size_t>(b)];
  return ra >= 0 && rb >= 0 && offset.norm() > ra + rb;
}

Vec3 PairMeasurer::gravitation_direction(int a, int b, const Vec3& offset) const {
  // Two round shapes whose outer circles are apart pull along the line from one centre (its
  // reference position) to the other: the centroid direction, exactly.
  if (round_apart(a, b, offset)) return offset.normalized();
  const Vec3 force = gravitation_force_between(a, b, offset);
  // A force that cancels (a dot centred in a ring) has no direction: fall back to the centroids.
  if (!(force.norm() > negligible_force(a, b, offset))) {
    return offset.norm() > 0 ? Vec3(offset.normalized()) : Vec3(Vec3::UnitX());
  }
  return force.normalized();
}

std::optional<int> PairMeasurer::table_axis(int a, int b, const Vec3& offset) const {
  if (!forces_) return std::nullopt;
  a = table_shape_[static_cast<std::size_t>(a)];
  b = table_shape_[static_cast<std::size_t>(b)];
  // A direction and its opposite share an axis.
  if (a > b || (a == b && lexicographically_negative(offset))) return table_axis(b, a, -offset);
  const std::size_t i = static_cast<std::size_t>(a), j = static_cast<std::size_t>(b);
  if (mass_size_[i] * mass_size_[j] < kForceTableCost) return std::nullopt;
  // Round shapes apart pull along the line of their centres (gravitation_direction), which the
  // table of their polygons' forces would only approximate.
  if (round_apart(a, b, offset)) return std::nullopt;
  // Regions whose circles about their centroids are well apart: the exact force is the pair's
  // multipole expansion to a low order, cheaper than the table's lookups.
  if (dimension_ == 2) {
    const MassBoundary2& ma = proxies2_[i].mass;
    const MassBoundary2& mb = proxies2_[j].mass;
    constexpr double kFarEnough = 1.6;  // the expansion converges as ((r_a + r_b)/|R|)^n
    if ((mb.centroid + offset.head<2>() - ma.centroid).norm() >
        kFarEnough * (ma.radius + mb.radius))
      return std::nullopt;
  }
  return forces_->axis(i * mass_size_.size() + j, kForceTablePitch * (radii_[i] + radii_[j]),
                       offset, negligible_force(a, b, offset), [this, a, b](const Vec3& at) {
                         return gravitation_force_between(a, b, at);
                       });
}

int PairMeasurer::axis(int a, int b, const Vec3& offset) const {
  if (options_.direction == DirectionKind::gravitation) {
    if (const std::optional<int> from_table = table_axis(a, b, offset)) return *from_table;
  }
  return bins_.axis_of(direction(a, b, offset));
}

const PairExpansion* PairMeasurer::expansion(int a, int b) const {
  if (!expansions_) return nullptr;
  const std::size_t index =
      static_cast<std::size_t>(a) * proxies2_.size() + static_cast<std::size_t>(b);
  std::call_once(expansions_->once[index], [&] {
    expansions_->tables[index] = pair_expansion(proxies2_[a].mass, proxies2_[b].mass);
  });
  return &expansions_->tables[index];
}

std::pair<double, double> PairMeasurer::distance_bounds(int a, int b, const Vec3& offset) const {
  if (options_.distance != DistanceKind::shape) {
    const double d = distance(a, b, offset);
    return {d, d};
  }
  const double norm = offset.norm();
  const Vec3 unit = norm > 0 ? Vec3(offset / norm) : Vec3(Vec3::UnitX());
  if (dimension_ == 2) {
    const Proxy2& pa = proxies2_[a];
    const Proxy2& pb = proxies2_[b];
    const Vec2 t = offset.head<2>(), u = unit.head<2>();
    const double lo = std::sqrt(pa.box.squaredExteriorDistance(pb.box.translated(t)));
    Vec2 far_a = pa.segment_start.front(), near_b = pb.segment_start.front();
    for (const Vec2& p : pa.segment_start)
      if (p.dot(u) > far_a.dot(u)) far_a = p;
    for (const Vec2& p : pb.segment_start)
      if (p.dot(u) < near_b.dot(u)) near_b = p;
    return {lo, std::max(lo, (near_b + t - far_a).norm())};
  }
  const Proxy3& pa = proxies3_[a];
  const Proxy3& pb = proxies3_[b];
  const double lo = std::sqrt(pa.box.squaredExteriorDistance(pb.box.translated(offset)));
  Vec3 far_a = pa.vertices.front(), near_b = pb.vertices.front();
  for (const Vec3& p : pa.vertices)
    if (p.dot(unit) > far_a.dot(unit)) far_a = p;
  for (const Vec3& p : pb.vertices)
    if (p.dot(unit) < near_b.dot(unit)) near_b = p;
  return {lo, std::max(lo, (near_b + offset - far_a).norm())};
}

bool PairMeasurer::same_proxy(int a, int b) const {
  if (a == b) return true;
  const auto close = [](const auto& x, const auto& y, double tolerance) {
    if (x.size() != y.size()) return false;
    for (std::size_t i = 0; i < x.size(); ++i) {
      if ((x[i] - y[i]).template lpNorm<Eigen::Infinity>() > tolerance) return false;
    }
    return true;
  };
  if (dimension_ == 2) {
    const Proxy2& pa = proxies2_[static_cast<std::size_t>(a)];
    const Proxy2& pb = proxies2_[static_cast<std::size_t>(b)];
    const double tolerance = 1e-9 * std::max(1.0, pa.box.diagonal().norm());
    if (pa.polylines.size() != pb.polylines.size() || pa.regions.size() != pb.regions.size() ||
        pa.strips.size() != pb.strips.size() || pa.mass.point != pb.mass.point) {
      return false;
    }
    for (std::size_t r = 0; r < pa.regions.size(); ++r) {
      if (pa.regions[r].rings != pb.regions[r].rings || pa.regions[r].rule != pb.regions[r].rule)
        return false;
    }
    for (std::size_t k = 0; k < pa.polylines.size(); ++k) {
      if (pa.polylines[k].closed != pb.polylines[k].closed ||
          !close(pa.polylines[k].points, pb.polylines[k].points, tolerance)) {
        return false;
      }
    }
    return close(pa.mass.start, pb.mass.start, tolerance) &&
           close(pa.mass.end, pb.mass.end, tolerance);
  }
  const Proxy3& pa = proxies3_[static_cast<std::size_t>(a)];
  const Proxy3& pb = proxies3_[static_cast<std::size_t>(b)];
  const double tolerance = 1e-9 * std::max(1.0, pa.box.diagonal().norm());
  return pa.closed == pb.closed && pa.point == pb.point && pa.triangles == pb.triangles &&
         close(pa.vertices, pb.vertices, tolerance);
}

int PairMeasurer::axis_from_boxes(int a, int b, const Vec3& offset, double slack) const {
  if (dimension_ != 2) return -1;
  if (bins_.directions() == 1) return 0;
  const Box2& box_a = proxies2_[a].box;
  const Box2& box_b = proxies2_[b].box;
  // Difference box: every y − x with x in box_a and y in box_b + offset.
  const Vec2 low = box_b.min() + offset.head<2>() - box_a.max() - Vec2::Constant(slack);
  const Vec2 high = box_b.max() + offset.head<2>() - box_a.min() + Vec2::Constant(slack);
  if (low.x() <= 0 && high.x() >= 0 && low.y() <= 0 && high.y() >= 0)
    return -1;  // holds the origin
  const Vec2 centre = 0.5 * (low + high);
  const double middle = std::atan2(centre.y(), centre.x());
  double lowest = 0.0, highest = 0.0;
  for (const Vec2& corner : {low, high, Vec2(low.x(), high.y()), Vec2(high.x(), low.y())}) {
    double delta = std::atan2(corner.y(), corner.x()) - middle;
    if (delta > core::kPi) delta -= 2 * core::kPi;
    if (delta < -core::kPi) delta += 2 * core::kPi;
    lowest = std::min(lowest, delta);
    highest = std::max(highest, delta);
  }
  return axis_of_angles(bins_, middle + lowest, middle + highest);
}

int PairMeasurer::certain_axis(int a, int b, const Vec3& offset, double slack) const {
  const int from_boxes = axis_from_boxes(a, b, offset, slack);
  if (from_boxes >= 0 || dimension_ != 2) return from_boxes;
  // Where the direction may point: about the line of centres within the angle the slack
  // subtends, and the strayed angle.
  Vec2 line;
  double stray = 0.0;
  if (options_.direction == DirectionKind::centroid) {
    line = offset.head<2>();
  } else {
    const MassBoundary2& ma = proxies2_[static_cast<std::size_t>(a)].mass;
    const MassBoundary2& mb = proxies2_[static_cast<std::size_t>(b)].mass;
    if (ma.point || mb.point) return -1;
    line = mb.centroid + offset.head<2>() - ma.centroid;
    const double nearest = line.norm() - slack;
    // Only where the force is the pair's expansion (accurate to 1e-6), see gravitation_force.
    if (!(nearest > 0) || (ma.radius + mb.radius) / nearest > 0.45) return -1;
    const PairExpansion* pair = a <= b ? expansion(a, b) : expansion(b, a);
    if (pair == nullptr) return -1;
    const double deviation = monopole_deviation(*pair, ma.radius + mb.radius, nearest) + 1e-5;
    if (deviation >= 1.0) return -1;
    stray = std::asin(deviation);
  }
  const double length = line.norm();
  if (!(length > slack)) return -1;
  const double spread = std::asin(slack / length) + stray + 1e-9;
  const double middle = std::atan2(line.y(), line.x());
  return axis_of_angles(bins_, middle - spread, middle + spread);
}

Vec3 PairMeasurer::direction(int a, int b, const Vec3& offset) const {
  // Canonical order, so that swapping the pair negates the result bit for bit.
  if (a > b || (a == b && lexicographically_negative(offset))) return -direction(b, a, -offset);
  if (options_.direction == DirectionKind::centroid) {
    return offset.norm() > 0 ? Vec3(offset.normalized()) : Vec3(Vec3::UnitX());
  }
  return gravitation_direction(a, b, offset);
}

Measurement PairMeasurer::measure(const Element& first, const Element& second,
                                  double cutoff) const {
  Measurement m = measure_distance(first, second, cutoff);
  if (m.distance >= cutoff) return m;
  m.direction = direction(first.shape, second.shape, m.offset);
  m.axis = bins_.axis_of(m.direction);
  return m;
}

Measurement PairMeasurer::measure_distance(const Element& first, const Element& second,
                                           double cutoff,
                                           const std::vector<double>* breakpoints) const {
  Measurement m;
  const Vec3 base = second.position - first.position;
  m.offset = base;
  // Every distance kind but Hausdorff is at least |offset| − r_a − r_b (0 for centroids): images
  // farther than the cut-off plus that reach are not measured.
  const double reach = options_.distance == DistanceKind::centroid ? 0.0
                       : options_.distance == DistanceKind::shape
                           ? radii_[first.shape] + radii_[second.shape]
                           : kNoCutoff;
  auto too_far = [&](const Vec3& offset, double limit) {
    const double r = limit + reach;
    return std::isfinite(r) && offset.squaredNorm() >= r * r;
  };
  if (!options_.periodic) {
    m.distance = too_far(base, cutoff)
                     ? cutoff
                     : distance(first.shape, second.shape, base, cutoff, breakpoints);
    return m;
  }
  // Minimum image: the nearest of the 3^dim translates (k = 0 first, so ties keep it).
  const int nz = dimension_ == 3 ? 1 : 0;
  std::array<Vec3, 27> images;
  int count = 0;
  for (int kx = 0; kx < 3; ++kx)
    for (int ky = 0; ky < 3; ++ky)
      for (int kz = 0; kz <= 2 * nz; ++kz) {
        const Vec3 k(kx == 2 ? -1 : kx, ky == 2 ? -1 : ky, kz == 2 ? -1 : kz);
        const Vec3 image = base + k.cwiseProduct(period_);
        if (!too_far(image, cutoff)) images[static_cast<std::size_t>(count++)] = image;
      }
  // Intervals are enough to compare images only when one image is in play.
  const std::vector<double>* coarse = count == 1 ? breakpoints : nullptr;
  m.distance = cutoff;
  bool found = false;
  for (int i = 0; i < count; ++i) {
    const Vec3& image = images[static_cast<std::size_t>(i)];
    if (too_far(image, m.distance)) continue;
    const double d = distance(first.shape, second.shape, image, m.distance, coarse);
    if (d < m.distance || (!found && d <= m.distance && d < cutoff)) {
      m.distance = d;
      m.offset = image;
      found = true;
    }
  }
  return m;
}

std::vector<PairRecord> PairMeasurer::all_pairs(const std::vector<Element>& elements,
                                                double range) const {
  std::vector<PairRecord> records;
  const std::size_t n = elements.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      const Element& a = elements[i];
      const Element& b = elements[j];
      if (std::isfinite(range) && options_.distance != DistanceKind::hausdorff) {
        // Cheap reject: d >= |offset| - r_a - r_b for every distance kind but Hausdorff.
        const Vec3 t = options_.periodic ? minimum_image(b.position - a.position, period_)
                                         : Vec3(b.position - a.position);
        const double reach =
            options_.distance == DistanceKind::centroid ? 0.0 : radii_[a.shape] + radii_[b.shape];
        if (t.norm() - reach >= range) continue;
      }
      const Measurement m = measure(a, b, range);
      if (m.distance < range || !std::isfinite(range)) {
        records.push_back({static_cast<int>(i), static_cast<int>(j), m});
      }
    }
  }
  return records;
}

}  // namespace shapeproc::geometry
