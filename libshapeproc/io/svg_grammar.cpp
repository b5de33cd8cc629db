#include "libshapeproc/io/svg_grammar.hpp"

#include <algorithm>
#include <boost/range/iterator_range.hpp>
#include <cmath>
#include <cstdio>
#include <svgpp/svgpp.hpp>

#include "libshapeproc/geometry/arc.hpp"

namespace shapeproc::io::svg {

using geometry::Path2;
using geometry::Segment2;
using geometry::Vec2;

namespace {

// Absolute coordinates only, every shorthand expanded, quadratics as cubics; arcs are converted
// here (geometry/arc) so that the degenerate cases of F.6.2 are handled and end points are exact.
struct NormalPathPolicy {
  static const bool absolute_coordinates_only = true;
  static const bool no_ortho_line_to = true;
  static const bool no_quadratic_bezier_shorthand = true;
  static const bool no_cubic_bezier_shorthand = true;
  static const bool quadratic_bezier_as_cubic = true;
  static const bool arc_as_cubic_bezier = false;
};

class PathCollector {
 public:
  explicit PathCollector(std::size_t max_segments) : max_segments_(max_segments) {}

  void path_move_to(double x, double y, svgpp::tag::coordinate::absolute) {
    finish_subpath();
    point_ = subpath_start_ = checked(x, y);
  }
  void path_line_to(double x, double y, svgpp::tag::coordinate::absolute) {
    const Vec2 to = checked(x, y);
    current_.segments.push_back(Segment2::line(point_, to));
    point_ = to;
    check_budget();
  }
  void path_cubic_bezier_to(double x1, double y1, double x2, double y2, double x, double y,
                            svgpp::tag::coordinate::absolute) {
    const Vec2 to = checked(x, y);
    current_.segments.push_back(Segment2::bezier(point_, checked(x1, y1), checked(x2, y2), to));
    point_ = to;
    check_budget();
  }
  void path_quadratic_bezier_to(double x1, double y1, double x, double y,
                                svgpp::tag::coordinate::absolute) {
    // Degree elevation: C1 = P0 + 2/3 (Q - P0), C2 = P3 + 2/3 (Q - P3).
    const Vec2 q = checked(x1, y1), to = checked(x, y);
    current_.segments.push_back(
        Segment2::bezier(point_, point_ + 2.0 / 3.0 * (q - point_), to + 2.0 / 3.0 * (q - to), to));
    point_ = to;
    check_budget();
  }
  void path_elliptical_arc_to(double rx, double ry, double x_axis_rotation, bool large_arc_flag,
                              bool sweep_flag, double x, double y,
                              svgpp::tag::coordinate::absolute) {
    const Vec2 to = checked(x, y);
    const Vec2 radii = checked(rx, ry);
    if (!std::isfinite(x_axis_rotation)) throw GrammarError("arc rotation is not a finite number");
    geometry::append_elliptical_arc(current_, point_, radii.x(), radii.y(), x_axis_rotation,
                                    large_arc_flag, sweep_flag, to);
    point_ = to;
    check_budget();
  }
  void path_close_subpath() {
    // Relative coordinates often miss the start by rounding error: snap instead of adding a
    // closing line of length ~1e-15.
    if (!current_.segments.empty() && point_ != subpath_start_ &&
        (point_ - subpath_start_).norm() <= 1e-9 * std::max(1.0, subpath_start_.norm())) {
      current_.segments.back().end = subpath_start_;
      if (!current_.segments.back().cubic) current_.segments.back().control2 = subpath_start_;
      point_ = subpath_start_;
    }
    if (!current_.segments.empty() || point_ != subpath_start_) {
      if (point_ != subpath_start_) {
        current_.segments.push_back(Segment2::line(point_, subpath_start_));
      }
      current_.closed = true;
    }
    finish_subpath();
    point_ = subpath_start_;
  }
  void path_exit() { finish_subpath(); }

  std::vector<Path2> take() {
    finish_subpath();
    return std::move(paths_);
  }

 private:
  static Vec2 checked(double x, double y) {
    if (!std::isfinite(x) || !std::isfinite(y)) {
      throw GrammarError("coordinate is not a finite number");
    }
    return Vec2(x, y);
  }
  void check_budget() const {
    if (finished_segments_ + current_.segments.size() > max_segments_) {
      throw GrammarError("more than " + std::to_string(max_segments_) + " segments");
    }
  }
  void finish_subpath() {
    finished_segments_ += current_.segments.size();
    if (!current_.segments.empty()) paths_.push_back(std::move(current_));
    current_ = Path2();
  }

  std::vector<Path2> paths_;
  Path2 current_;
  Vec2 point_ = Vec2::Zero();
  Vec2 subpath_start_ = Vec2::Zero();
  std::size_t max_segments_, finished_segments_ = 0;
};

class TransformCollector {
 public:
  void transform_matrix(const boost::array<double, 6>& m) {
    for (double v : m) {
      if (!std::isfinite(v)) throw GrammarError("transform has a non-finite number");
    }
    geometry::Affine2 next = geometry::Affine2::Identity();
    next.matrix() << m[0], m[2], m[4], m[1], m[3], m[5], 0, 0, 1;
    map_ = map_ * next;
  }
  geometry::Affine2 map() const { return map_; }

 private:
  geometry::Affine2 map_ = geometry::Affine2::Identity();
};

class ColorCollector {
 public:
  template <class Tag>
  void set(Tag, int color) {
    color_ = color;
  }
  std::optional<int> color() const { return color_; }

 private:
  std::optional<int> color_;
};

}  // namespace

std::vector<Path2> parse_path_data(std::string_view data, std::size_t max_segments) {
  PathCollector collector(max_segments);
  try {
    svgpp::value_parser<svgpp::tag::type::path_data, svgpp::path_policy<NormalPathPolicy>>::parse(
        svgpp::tag::attribute::d(), collector,
        boost::make_iterator_range(data.data(), data.data() + data.size()),
        svgpp::tag::source::attribute());
  } catch (const svgpp::exception_base&) {
    throw GrammarError("cannot parse path data");
  }
  return collector.take();
}

geometry::Affine2 parse_transform(std::string_view text) {
  TransformCollector collector;
  try {
    svgpp::value_parser<svgpp::tag::type::transform_list>::parse(
        svgpp::tag::attribute::transform(), collector,
        boost::make_iterator_range(text.data(), text.data() + text.size()),
        svgpp::tag::source::attribute());
  } catch (const svgpp::exception_base&) {
    throw GrammarError("cannot parse transform list");
  }
  return collector.map();
}

std::optional<std::string> normalise_color(std::string_view text) {
  ColorCollector collector;
  try {
    svgpp::value_parser<svgpp::tag::type::color>::parse(
        svgpp::tag::attribute::color(), collector,
        boost::make_iterator_range(text.data(), text.data() + text.size()),
        svgpp::tag::source::attribute());
  } catch (const svgpp::exception_base&) {
    return std::nullopt;
  }
  if (!collector.color()) return std::nullopt;
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, "#%06x",
                static_cast<unsigned>(*collector.color()) & 0xffffffu);
  return std::string(buffer);
}

}  // namespace shapeproc::io::svg
