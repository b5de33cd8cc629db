#include "libshapeproc/io/reader_options.hpp"

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/io/text.hpp"

namespace shapeproc::io {

CategoryRule CategoryRule::parse(const std::string& text) {
  CategoryRule rule;
  if (text == "none") {
    rule.kind = Kind::none;
  } else if (text == "fill") {
    rule.kind = Kind::fill;
  } else if (text == "stroke") {
    rule.kind = Kind::stroke;
  } else if (text == "class") {
    rule.kind = Kind::class_name;
  } else if (text == "layer") {
    rule.kind = Kind::layer;
  } else if (text.rfind("attr:", 0) == 0 && text.size() > 5) {
    rule.kind = Kind::attribute;
    rule.attribute = text.substr(5);
  } else {
    throw core::UsageError(
        "{category_by}: expected none, fill, stroke, class, layer or attr:NAME, got '" + text +
        "'");
  }
  return rule;
}

std::string CategoryRule::to_string() const {
  switch (kind) {
    case Kind::none:
      return "none";
    case Kind::fill:
      return "fill";
    case Kind::stroke:
      return "stroke";
    case Kind::class_name:
      return "class";
    case Kind::layer:
      return "layer";
    case Kind::attribute:
      return "attr:" + attribute;
  }
  return "none";
}

WindowOption WindowOption::parse(const std::string& text) {
  const auto values = parse_number_list(text);
  if (!values || (values->size() != 4 && values->size() != 6)) {
    throw core::UsageError("{window}: expected xmin,xmax,ymin,ymax[,zmin,zmax], got '" + text +
                           "'");
  }
  const auto& v = *values;
  WindowOption window;
  window.dimension = v.size() == 6 ? 3 : 2;
  const double zmin = window.dimension == 3 ? v[4] : 0.0;
  const double zmax = window.dimension == 3 ? v[5] : 0.0;
  const char* axes = "xyz";
  for (int axis = 0; axis < window.dimension; ++axis) {
    if (!(v[2 * axis] < v[2 * axis + 1])) {
      throw core::UsageError(std::string("{window}: ") + axes[axis] + "min must be below " +
                             axes[axis] + "max, got '" + text + "'");
    }
  }
  window.box = geometry::Box3(geometry::Vec3(v[0], v[2], zmin), geometry::Vec3(v[1], v[3], zmax));
  return window;
}

}  // namespace shapeproc::io
