#include "libshapeproc/geometry/stroke_ink.hpp"

#include <algorithm>
#include <boost/geometry.hpp>
#include <cmath>
#include <cstdlib>
#include <string>

#include "libshapeproc/core/constants.hpp"

namespace shapeproc::geometry {

namespace {

namespace bg = boost::geometry;
using Point = bg::model::d2::point_xy<double>;
using Ring = bg::model::ring<Point>;
using Polygon = bg::model::polygon<Point>;
using MultiPolygon = bg::model::multi_polygon<Polygon>;
using Line = bg::model::linestring<Point>;

std::string style_value(const Drawable2& drawable, const char* key, const char* fallback) {
  const auto it = drawable.style.find(key);
  return it == drawable.style.end() ? fallback : it->second;
}

double stroke_width(const Drawable2& drawable) {
  const double width = std::atof(style_value(drawable, "stroke-width", "1").c_str());
  return std::isfinite(width) ? width : 0.0;
}

// Points per full circle so that the chords stay within `tolerance` of a circle of radius r.
int circle_points(double radius, double tolerance) {
  if (!(radius > tolerance)) return 8;
  const double step = 2 * std::acos(1 - tolerance / radius);
  return std::clamp(static_cast<int>(std::ceil(2 * core::kPi / step)), 8, 360);
}

// The buffer of `geometry` by `distance` with the stroke's join and end strategies.
template <typename Geometry>
MultiPolygon buffered(const Geometry& geometry, double distance, const Drawable2& drawable,
                      int points) {
  const bg::strategy::buffer::distance_symmetric<double> by(distance);
  const bg::strategy::buffer::side_straight side;
  const bg::strategy::buffer::point_circle circle(points);
  const std::string join = style_value(drawable, "stroke-linejoin", "miter");
  const std::string cap = style_value(drawable, "stroke-linecap", "butt");
  const double limit =
      std::max(1.0, std::atof(style_value(drawable, "stroke-miterlimit", "4").c_str()));
  MultiPolygon out;
  const auto with_end = [&](const auto& join_strategy) {
    if (cap == "round") {
      bg::buffer(geometry, out, by, side, join_strategy, bg::strategy::buffer::end_round(points),
                 circle);
    } else {
      bg::buffer(geometry, out, by, side, join_strategy, bg::strategy::buffer::end_flat(), circle);
    }
  };
  if (join == "round") {
    with_end(bg::strategy::buffer::join_round(points));
  } else {
    // Boost's mitre join bevels corners past the limit (SVG's bevel join is a limit of 1).
    with_end(bg::strategy::buffer::join_miter(join == "bevel" ? 1.0 : limit));
  }
  return out;
}

Drawable2 as_drawable(const MultiPolygon& ink, const Drawable2& stroked_drawable) {
  Drawable2 out;
  out.fill_rule = FillRule::evenodd;
  out.style = stroked_drawable.style;
  out.style["fill"] = style_value(stroked_drawable, "stroke", "none");
  if (const auto it = stroked_drawable.style.find("stroke-opacity");
      it != stroked_drawable.style.end()) {
    out.style["fill-opacity"] = it->second;
  } else {
    out.style.erase("fill-opacity");
  }
  for (const char* key : {"stroke-width", "stroke-linecap", "stroke-linejoin", "stroke-miterlimit",
                          "stroke-opacity", "stroke-dasharray"})
    out.style.erase(key);
  out.style["stroke"] = "none";
  const auto add_ring = [&](const Ring& ring) {
    if (ring.size() < 4) return;
    Path2 path;
    path.closed = true;
    for (std::size_t i = 0; i + 1 < ring.size(); ++i) {
      path.segments.push_back(
          Segment2::line(Vec2(bg::get<0>(ring[i]), bg::get<1>(ring[i])),
                         Vec2(bg::get<0>(ring[i + 1]), bg::get<1>(ring[i + 1]))));
    }
    out.paths.push_back(std::move(path));
  };
  for (const Polygon& polygon : ink) {
    add_ring(polygon.outer());
    for (const Ring& hole : polygon.inners()) add_ring(hole);
  }
  return out;
}

}  // namespace

bool stroked(const Drawable2& drawable) {
  const std::string stroke = style_value(drawable, "stroke", "none");
  return stroke != "none" && stroke_width(drawable) > 0;
}

std::optional<Drawable2> stroke_ink(const Drawable2& drawable, double tolerance) {
  if (!stroked(drawable)) return std::nullopt;
  const double half = 0.5 * stroke_width(drawable);
  const int points = circle_points(half, tolerance);
  const bool square = style_value(drawable, "stroke-linecap", "butt") == "square";
  MultiPolygon ink;
  for (const Path2& path : drawable.paths) {
    if (path.segments.empty()) continue;
    std::vector<Vec2> flat = flatten(path, tolerance);
    if (flat.size() < 2) continue;
    MultiPolygon piece;
    if (path.closed && flat.size() >= 3) {
      Polygon polygon;
      for (const Vec2& p : flat) bg::append(polygon.outer(), Point(p.x(), p.y()));
      bg::append(polygon.outer(), Point(flat.front().x(), flat.front().y()));
      bg::correct(polygon);
      const MultiPolygon outer = buffered(polygon, half, drawable, points);
      const MultiPolygon inner = buffered(polygon, -half, drawable, points);
      bg::difference(outer, inner, piece);
    } else {
      if (square) {  // a flat cap half a width beyond each end
        const Vec2 start = flat[0] - flat[1], end = flat.back() - flat[flat.size() - 2];
        if (start.norm() > 0) flat.front() += half * start.normalized();
        if (end.norm() > 0) flat.back() += half * end.normalized();
      }
      Line line;
      for (const Vec2& p : flat) bg::append(line, Point(p.x(), p.y()));
      piece = buffered(line, half, drawable, points);
    }
    MultiPolygon joined;
    bg::union_(ink, piece, joined);
    ink = std::move(joined);
  }
  if (ink.empty()) return std::nullopt;
  return as_drawable(ink, drawable);
}

}  // namespace shapeproc::geometry
