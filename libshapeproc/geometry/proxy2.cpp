// 2D proxies: flattening, Douglas–Peucker through Boost.Geometry, region tests, mass cubature.
#include <cmath>

#include <boost/geometry.hpp>
#include <boost/geometry/geometries/linestring.hpp>
#include <boost/geometry/geometries/point_xy.hpp>

#include "libshapeproc/geometry/proxy.hpp"

namespace shapeproc::geometry {

namespace bg = boost::geometry;

namespace {

using BgPoint = bg::model::d2::point_xy<double>;
using BgLine = bg::model::linestring<BgPoint>;

// Douglas–Peucker on an open or closed polyline. A closed ring is simplified as a linestring that
// returns to its start, so it stays closed; if it would collapse below a triangle it is kept.
std::vector<Vec2> simplify(const std::vector<Vec2>& points, bool closed, double tolerance) {
  if (points.size() <= 2 || tolerance <= 0.0) return points;
  BgLine line;
  for (const Vec2& p : points) line.emplace_back(p.x(), p.y());
  if (closed) line.emplace_back(points.front().x(), points.front().y());
  BgLine simple;
  bg::simplify(line, simple, tolerance);
  std::vector<Vec2> result;
  for (const BgPoint& p : simple) result.emplace_back(p.x(), p.y());
  if (closed) {
    if (result.size() > 1 && result.back() == result.front()) result.pop_back();
    if (result.size() < 3) return points;
  } else if (result.size() < 2) {
    return points;
  }
  return result;
}

}  // namespace

bool Proxy2::inside(const Vec2& p) const {
  if (regions.empty() || !box.contains(p)) return false;
  for (const Region& region : regions) {
    int winding = 0;
    for (int ring : region.rings) winding += winding_number(polylines[ring].points, p);
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
    proxy.mass = make_mass_model(std::vector<Vec2>{Vec2::Zero()}, {1.0});
    return proxy;
  }
  const PlanarShape& planar = std::get<PlanarShape>(shape.geometry);
  const Box3 shape_box = bounding_box(shape);
  const double diagonal = shape_box.isEmpty() ? 0.0 : shape_box.diagonal().norm();
  const double tolerance = options.tolerance * diagonal;
  for (const Drawable2& part : planar.parts) {
    Proxy2::Region region;
    region.rule = part.fill_rule;
    for (const Path2& path : part.paths) {
      proxy.source_segments += path.segments.size();
      std::vector<Vec2> flat = flatten(path, std::max(tolerance / 4, diagonal * 1e-9));
      Proxy2::Polyline polyline{simplify(flat, path.closed, tolerance), path.closed && flat.size() >= 3};
      if (part.filled() && polyline.closed) region.rings.push_back(static_cast<int>(proxy.polylines.size()));
      proxy.polylines.push_back(std::move(polyline));
    }
    if (!region.rings.empty()) proxy.regions.push_back(std::move(region));
  }
  for (const Proxy2::Polyline& polyline : proxy.polylines) {
    const std::size_t n = polyline.points.size();
    const std::size_t count = polyline.closed ? n : (n >= 2 ? n - 1 : n);
    for (std::size_t i = 0; i < count; ++i) {
      proxy.segment_start.push_back(polyline.points[i]);
      proxy.segment_end.push_back(polyline.points[(i + 1) % n]);
    }
  }
  std::vector<Box2> boxes;
  for (std::size_t i = 0; i < proxy.segment_start.size(); ++i) {
    boxes.push_back(Box2(proxy.segment_start[i]).extend(proxy.segment_end[i]));
    proxy.box.extend(boxes.back());
  }
  proxy.segment_tree = BoxTree<2>::build(boxes);

  // Mass: midpoint rule on a square grid over the filled regions; outlines that bound no filled
  // region (open curves, fill:none) count as strips one cell wide.
  const double longest = proxy.box.isEmpty() ? 0.0 : proxy.box.sizes().maxCoeff();
  std::vector<Vec2> points;
  std::vector<double> weights;
  if (longest > 0.0) {
    const double h = longest / options.mass_resolution_2d;
    if (!proxy.regions.empty()) {
      const int nx = std::max(1, static_cast<int>(std::ceil(proxy.box.sizes().x() / h)));
      const int ny = std::max(1, static_cast<int>(std::ceil(proxy.box.sizes().y() / h)));
      const Vec2 origin = proxy.box.center() - 0.5 * h * Vec2(nx, ny);
      for (int i = 0; i < nx; ++i) {
        for (int j = 0; j < ny; ++j) {
          const Vec2 p = origin + h * Vec2(i + 0.5, j + 0.5);
          if (proxy.inside(p)) {
            points.push_back(p);
            weights.push_back(h * h);
          }
        }
      }
    }
    std::vector<bool> in_region(proxy.polylines.size(), false);
    for (const auto& region : proxy.regions)
      for (int ring : region.rings) in_region[ring] = true;
    const bool no_area = points.empty();  // filled regions thinner than a cell count as outlines
    for (std::size_t k = 0; k < proxy.polylines.size(); ++k) {
      if (in_region[k] && !no_area) continue;
      const auto& polyline = proxy.polylines[k];
      const std::size_t n = polyline.points.size();
      const std::size_t count = polyline.closed ? n : n - 1;
      for (std::size_t i = 0; i < count; ++i) {
        const Vec2 a = polyline.points[i], b = polyline.points[(i + 1) % n];
        const double length = (b - a).norm();
        const int pieces = std::max(1, static_cast<int>(std::ceil(length / h)));
        for (int s = 0; s < pieces; ++s) {
          points.push_back(a + (s + 0.5) / pieces * (b - a));
          weights.push_back(length / pieces * h);
        }
      }
    }
  }
  if (points.empty()) {  // a degenerate shape: its box centre
    points.push_back(proxy.box.isEmpty() ? Vec2::Zero() : Vec2(proxy.box.center()));
    weights.push_back(1.0);
  }
  proxy.mass = make_mass_model(std::move(points), std::move(weights));
  return proxy;
}

Shape proxy_as_shape(const Proxy2& proxy) {
  Drawable2 drawable;
  drawable.style = {{"fill", "none"}, {"stroke", "#d53f8c"}, {"stroke-width", "0.5"}};
  for (const Proxy2::Polyline& polyline : proxy.polylines) {
    Path2 path;
    const std::size_t n = polyline.points.size();
    for (std::size_t i = 0; i + 1 < n; ++i) path.segments.push_back(Segment2::line(polyline.points[i], polyline.points[i + 1]));
    if (polyline.closed && n >= 2) {
      path.segments.push_back(Segment2::line(polyline.points.back(), polyline.points.front()));
      path.closed = true;
    }
    if (!path.segments.empty()) drawable.paths.push_back(std::move(path));
  }
  return Shape{PlanarShape{{drawable}}, "proxy"};
}

}  // namespace shapeproc::geometry
