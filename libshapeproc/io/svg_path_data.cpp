#include "libshapeproc/io/svg_path_data.hpp"

#include "libshapeproc/core/format.hpp"

namespace shapeproc::io {

std::string svg_path_data(const geometry::Path2& path) {
  std::string d;
  auto point = [&](const geometry::Vec2& p) {
    d += core::format_number(p.x());
    d += ' ';
    d += core::format_number(p.y());
  };
  d += 'M';
  point(path.start_point());
  for (const geometry::Segment2& s : path.segments) {
    if (s.cubic) {
      d += 'C';
      point(s.control1);
      d += ' ';
      point(s.control2);
      d += ' ';
    } else {
      d += 'L';
    }
    point(s.end);
  }
  if (path.closed) d += 'Z';
  return d;
}

std::string svg_path_data(const std::vector<geometry::Path2>& paths) {
  std::string d;
  for (const geometry::Path2& path : paths) {
    if (!d.empty()) d += ' ';
    d += svg_path_data(path);
  }
  return d;
}

}  // namespace shapeproc::io
