// 2D proxies: flattening, Douglas–Peucker, region tests, mass cubature (strips through
// Boost.Geometry).
#include <boost/geometry.hpp>
#include <boost/geometry/geometries/linestring.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <cmath>
#include <cstdlib>

#include "libshapeproc/geometry/proxy.hpp"

namespace shapeproc::geometry {

namespace bg = boost::geometry;

namespace {

using BgPoint = bg::model::d2::point_xy<double>;
using BgLine = bg::model::linestring<BgPoint>;

// Douglas–Peucker on an open or closed polyline. A closed ring is simplified as a linestring that
// returns to its start, so it stays closed; if it would collapse below a triangle it is kept.
// Of points equally far from a chord (a circle's samples are, up to rounding), the first is
// kept: the choice must not hang on rounding, so that copies of one drawing placed anywhere get
// the same proxy.
std::vector<Vec2> simplify(const std::vector<Vec2>& points, bool closed, double tolerance) {
  if (points.size() <= 2 || tolerance <= 0.0) return points;
  std::vector<Vec2> line = points;
  if (closed) line.push_back(points.front());
  const double tie = 1e-9 * tolerance;
  std::vector<char> keep(line.size(), 0);
  keep.front() = keep.back() = 1;
  std::vector<std::pair<std::size_t, std::size_t>> spans{{0, line.size() - 1}};
  while (!spans.empty()) {
    const auto [first, last] = spans.back();
    spans.pop_back();
    if (last <= first + 1) continue;
    const Vec2 a = line[first], chord = line[last] - a;
    const double length2 = chord.squaredNorm();
    double farthest = -1.0;
    std::size_t at = first;
    for (std::size_t i = first + 1; i < last; ++i) {
      const Vec2 d = line[i] - a;
      const double t = length2 > 0 ? std::clamp(d.dot(chord) / length2, 0.0, 1.0) : 0.0;
      const double distance = (d - t * chord).norm();
      if (distance > farthest + tie) {
        farthest = distance;
        at = i;
      }
    }
    if (farthest <= tolerance) continue;
    keep[at] = 1;
    spans.push_back({at, last});
    spans.push_back({first, at});
  }
  std::vector<Vec2> result;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (keep[i]) result.push_back(line[i]);
  }
  if (closed) {
    if (result.size() > 1 && result.back() == result.front()) result.pop_back();
    if (result.size() < 3) return points;
  } else if (result.size() < 2) {
    return points;
  }
  return result;
}

using BgPolygon = bg::model::polygon<BgPoint>;
using BgMultiPolygon = bg::model::multi_polygon<BgPolygon>;

std::vector<Vec2> ring_points(const bg::model::ring<BgPoint>& ring) {
  std::vector<Vec2> points;
  for (const BgPoint& p : ring) points.emplace_back(p.x(), p.y());
  if (points.size() > 1 && points.back() == points.front()) points.pop_back();
  return points;
}

// Strips of the given half-width around a polyline (closed polylines give annuli).
BgMultiPolygon strip_around(const Proxy2::Polyline& polyline, double half_width) {
  BgLine line;
  for (const Vec2& p : polyline.points) line.emplace_back(p.x(), p.y());
  if (polyline.closed && !polyline.points.empty())
    line.emplace_back(polyline.points.front().x(), polyline.points.front().y());
  BgMultiPolygon result;
  if (line.size() < 2) {
    const Vec2 p = polyline.points.empty() ? Vec2::Zero() : polyline.points.front();
    line.clear();
    line.emplace_back(p.x() - half_width, p.y());
    line.emplace_back(p.x() + half_width, p.y());
  }
  bg::buffer(line, result, bg::strategy::buffer::distance_symmetric<double>(half_width),
             bg::strategy::buffer::side_straight(), bg::strategy::buffer::join_miter(),
             bg::strategy::buffer::end_flat(), bg::strategy::buffer::point_circle(8));
  return result;
}

bool in_strip(const std::vector<std::vector<Vec2>>& rings, const Vec2& p) {
  int winding = 0;
  for (const auto& ring : rings) winding += winding_number(ring, p) != 0 ? 1 : 0;
  return winding % 2 == 1;
}

// The boundary of the mass: every edge of a filled ring or strip ring that has mass on exactly
// one side, with its normal towards the empty side. Edges inside the mass (shared by two rings,
// overlapping strips) drop out.
void build_mass(Proxy2& proxy, const std::vector<double>& strip_half_widths, double diagonal,
                const ProxyOptions&) {
  for (std::size_t k = 0; k < proxy.polylines.size(); ++k) {
    if (strip_half_widths[k] <= 0.0) continue;
    for (const BgPolygon& polygon : strip_around(proxy.polylines[k], strip_half_widths[k])) {
      std::vector<std::vector<Vec2>> rings{ring_points(polygon.outer())};
      for (const auto& inner : polygon.inners()) rings.push_back(ring_points(inner));
      proxy.strips.push_back(std::move(rings));
    }
  }
  const double epsilon = std::max(1e-9, 1e-7 * diagonal);
  auto consider = [&](const Vec2& a, const Vec2& b) {
    const Vec2 edge = b - a;
    const double length = edge.norm();
    if (length == 0.0) return;
    const Vec2 left(-edge.y() / length, edge.x() / length);
    const Vec2 mid = 0.5 * (a + b);
    const bool mass_left = proxy.in_mass(mid + epsilon * left);
    const bool mass_right = proxy.in_mass(mid - epsilon * left);
    if (mass_left != mass_right) proxy.mass.add_edge(a, b, mass_left ? Vec2(-left) : left);
  };
  for (const auto& region : proxy.regions) {
    for (int ring : region.rings) {
      const auto& points = proxy.polylines[ring].points;
      for (std::size_t i = 0; i < points.size(); ++i)
        consider(points[i], points[(i + 1) % points.size()]);
    }
  }
  for (const auto& strip : proxy.strips) {
    for (const auto& ring : strip) {
      for (std::size_t i = 0; i < ring.size(); ++i) consider(ring[i], ring[(i + 1) % ring.size()]);
    }
  }
  proxy.mass.finish();
  if (proxy.mass.point)
    proxy.mass.centroid = proxy.box.isEmpty() ? Vec2::Zero() : Vec2(proxy.box.center());
}

}  // namespace

bool Proxy2::in_mass(const Vec2& p) const {
  if (inside(p)) return true;
  for (const auto& strip : strips) {
    if (in_strip(strip, p)) return true;
  }
  return false;
}

MassModel2 sample_mass(const Proxy2& proxy, double cell, const Vec2& lattice, int subsamples) {
  std::vector<Vec2> points;
  std::vector<double> weights;
  Box2 box = proxy.box;
  for (const auto& strip : proxy.strips)
    for (const auto& ring : strip)
      for (const Vec2& p : ring) box.extend(p);
  if (box.isEmpty() || cell <= 0) return make_mass_model(std::vector<Vec2>{Vec2::Zero()}, {1.0});
  // Cells [lattice + cell * (i, j), lattice + cell * (i + 1, j + 1)] covering the box.
  const Vec2 first((box.min() - lattice).array() / cell);
  const Vec2 origin = lattice + cell * Vec2(std::floor(first.x()), std::floor(first.y()));
  const int nx = 1 + static_cast<int>(std::ceil((box.max().x() - origin.x()) / cell));
  const int ny = 1 + static_cast<int>(std::ceil((box.max().y() - origin.y()) / cell));
  const int k = std::max(1, subsamples);
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j) {
      Vec2 sum = Vec2::Zero();
      int covered = 0;
      for (int a = 0; a < k; ++a) {
        for (int b = 0; b < k; ++b) {
          const Vec2 p = origin + cell * Vec2(i + (a + 0.5) / k, j + (b + 0.5) / k);
          if (proxy.in_mass(p)) {
            sum += p;
            ++covered;
          }
        }
      }
      if (covered > 0) {
        points.push_back(k == 1 ? sum : Vec2(sum / covered));
        weights.push_back(cell * cell * covered / (k * k));
      }
    }
  }
  if (points.empty()) return make_mass_model(std::vector<Vec2>{proxy.mass.centroid}, {1.0});
  return make_mass_model(std::move(points), std::move(weights));
}

bool Proxy2::inside(const Vec2& p) const {
  if (regions.empty() || !box.contains(p)) return false;
  // Each ring's winding number, from the segments that reach the point's height only (the
  // others add nothing): the same sum as winding_number's, found through the segment tree.
  thread_local std::vector<int> winding_of;
  winding_of.assign(polylines.size(), 0);
  thread_local std::vector<int> stack;
  stack.assign(1, 0);
  while (!stack.empty()) {
    const BoxTree<2>::Node& node = segment_tree.nodes[static_cast<std::size_t>(stack.back())];
    stack.pop_back();
    if (p.y() < node.box.min().y() || p.y() > node.box.max().y()) continue;
    if (node.count == 0) {
      stack.push_back(node.first);
      stack.push_back(node.first + 1);
      continue;
    }
    for (int k = node.first; k < node.first + node.count; ++k) {
      const auto s = static_cast<std::size_t>(segment_tree.order[static_cast<std::size_t>(k)]);
      winding_of[static_cast<std::size_t>(segment_polyline[s])] +=
          winding_crossing(segment_start[s], segment_end[s], p);
    }
  }
  for (const Region& region : regions) {
    int winding = 0;
    for (int ring : region.rings) winding += winding_of[static_cast<std::size_t>(ring)];
    if (region.rule == FillRule::nonzero ? winding != 0 : (winding % 2) != 0) return true;
  }
  return false;
}

Proxy2 make_proxy2(const Shape& shape, const ProxyOptions& options) {
  Proxy2 proxy;
  std::vector<Vec2> curve_points;  // mass of unfilled outlines
  if (std::holds_alternative<PointShape>(shape.geometry)) {
    proxy.polylines.push_back({{Vec2::Zero()}, false});
    proxy.segment_start.push_back(Vec2::Zero());
    proxy.segment_end.push_back(Vec2::Zero());
    proxy.box = Box2(Vec2::Zero(), Vec2::Zero());
    proxy.segment_tree = BoxTree<2>::build({proxy.box});
    proxy.mass.finish();  // a unit point mass
    return proxy;
  }
  const PlanarShape& planar = std::get<PlanarShape>(shape.geometry);
  const Box3 shape_box = bounding_box(shape);
  const double diagonal = shape_box.isEmpty() ? 0.0 : shape_box.diagonal().norm();
  const double tolerance = options.tolerance * diagonal;
  std::vector<double> strip_half_widths;  // per polyline; 0 for rings of filled regions
  for (const Drawable2& part : planar.parts) {
    Proxy2::Region region;
    region.rule = part.fill_rule;
    double half_width = options.curve_half_width * diagonal;
    if (const auto stroke = part.style.find("stroke-width"); stroke != part.style.end()) {
      const double width = std::atof(stroke->second.c_str());
      if (width > 0 && std::isfinite(width)) half_width = 0.5 * width;
    }
    for (const Path2& path : part.paths) {
      proxy.source_segments += path.segments.size();
      std::vector<Vec2> flat = flatten(path, std::max(tolerance / 4, diagonal * 1e-9));
      Proxy2::Polyline polyline{simplify(flat, path.closed, tolerance),
                                path.closed && flat.size() >= 3};
      const bool ring = part.filled() && polyline.closed;
      if (ring) region.rings.push_back(static_cast<int>(proxy.polylines.size()));
      strip_half_widths.push_back(ring ? 0.0 : half_width);
      proxy.polylines.push_back(std::move(polyline));
    }
    if (!region.rings.empty()) proxy.regions.push_back(std::move(region));
  }
  for (std::size_t k = 0; k < proxy.polylines.size(); ++k) {
    const Proxy2::Polyline& polyline = proxy.polylines[k];
    const std::size_t n = polyline.points.size();
    const std::size_t count = polyline.closed ? n : (n >= 2 ? n - 1 : n);
    for (std::size_t i = 0; i < count; ++i) {
      proxy.segment_start.push_back(polyline.points[i]);
      proxy.segment_end.push_back(polyline.points[(i + 1) % n]);
      proxy.segment_polyline.push_back(static_cast<int>(k));
    }
  }
  std::vector<Box2> boxes;
  for (std::size_t i = 0; i < proxy.segment_start.size(); ++i) {
    boxes.push_back(Box2(proxy.segment_start[i]).extend(proxy.segment_end[i]));
    proxy.box.extend(boxes.back());
  }
  proxy.segment_tree = BoxTree<2>::build(boxes);

  build_mass(proxy, strip_half_widths, diagonal, options);
  return proxy;
}

Shape proxy_as_shape(const Proxy2& proxy) {
  Drawable2 drawable;
  drawable.style = {{"fill", "none"}, {"stroke", "#d53f8c"}, {"stroke-width", "0.5"}};
  for (const Proxy2::Polyline& polyline : proxy.polylines) {
    Path2 path;
    const std::size_t n = polyline.points.size();
    for (std::size_t i = 0; i + 1 < n; ++i)
      path.segments.push_back(Segment2::line(polyline.points[i], polyline.points[i + 1]));
    if (polyline.closed && n >= 2) {
      path.segments.push_back(Segment2::line(polyline.points.back(), polyline.points.front()));
      path.closed = true;
    }
    if (!path.segments.empty()) drawable.paths.push_back(std::move(path));
  }
  return Shape{PlanarShape{{drawable}}, "proxy"};
}

}  // namespace shapeproc::geometry
