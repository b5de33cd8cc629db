#include "libshapeproc/io/csv_reader.hpp"

#include <map>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/io/points_scene.hpp"
#include "libshapeproc/io/text.hpp"

namespace shapeproc::io {

namespace {

// A disc's radius may be at most this many times the window's longest side.
constexpr double kLargestRadius = 10.0;

}  // namespace

bool split_csv_line(std::string_view line, std::vector<std::string>& fields) {
  fields.clear();
  std::string field;
  bool quoted = false, was_quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        field += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        field += c;
      }
    } else if (c == '"' && trim(field).empty() && !was_quoted) {
      field.clear();
      quoted = was_quoted = true;
    } else if (was_quoted && (c == ' ' || c == '\t')) {
      continue;  // blanks after a closing quote
    } else if (c == ',') {
      fields.push_back(was_quoted ? field : std::string(trim(field)));
      field.clear();
      was_quoted = false;
    } else {
      field += c;
    }
  }
  if (quoted) return false;
  fields.push_back(was_quoted ? field : std::string(trim(field)));
  return true;
}

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos && trim(text) == text) return text;
  std::string out = "\"";
  for (char c : text) out += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

geometry::Scene parse_csv_points(std::string_view text, const std::string& file_name,
                                 const ReaderOptions& options) {
  if (trim(text).empty()) throw core::InputError(file_name, 0, "the file is empty");
  std::vector<std::string_view> lines;
  for (std::size_t start = 0; start <= text.size();) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    lines.push_back(line);
    start = end + 1;
  }
  std::vector<std::string> fields;
  if (!split_csv_line(lines.front(), fields))
    throw core::InputError(file_name, 1, "bad quoting in the header");
  std::map<std::string, std::size_t> column;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    const std::string name = to_lower(fields[i]);
    if (!column.emplace(name, i).second)
      throw core::InputError(file_name, 1, "column '" + name + "' appears twice");
  }
  if (!column.count("x") || !column.count("y")) {
    throw core::InputError(file_name, 1,
                           "the header must name columns x and y (and optionally z, category)");
  }
  const int dimension = column.count("z") ? 3 : 2;
  const auto radius_column = column.find("radius");
  const bool discs = radius_column != column.end();
  if (discs && dimension == 3)
    throw core::InputError(file_name, 1, "a radius column makes discs, which are 2D: drop z");
  if (!options.window) {
    throw core::InputError(file_name, 0,
                           std::string("a CSV point pattern needs {window} xmin,xmax,ymin,ymax") +
                               (dimension == 3 ? ",zmin,zmax" : ""));
  }
  if (options.window->dimension != dimension) {
    throw core::InputError(file_name, 0,
                           "the points are " + std::to_string(dimension) + "D but {window} is " +
                               std::to_string(options.window->dimension) + "D");
  }
  geometry::Scene scene;
  scene.dimension = dimension;
  scene.window = options.window->box;
  scene.units = "1";
  if (!discs) scene.shapes.push_back(geometry::Shape{geometry::PointShape{}, "point"});
  std::map<double, int> shape_of_radius;  // discs: one shape per distinct radius
  const std::size_t width = fields.size();
  const char* axes[3] = {"x", "y", "z"};
  for (std::size_t n = 1; n < lines.size(); ++n) {
    const int line_number = static_cast<int>(n + 1);
    if (trim(lines[n]).empty()) continue;
    if (!split_csv_line(lines[n], fields))
      throw core::InputError(file_name, line_number, "bad quoting");
    if (fields.size() != width) {
      throw core::InputError(
          file_name, line_number,
          "expected " + std::to_string(width) + " fields, got " + std::to_string(fields.size()));
    }
    geometry::Element element;
    element.shape = 0;
    for (int axis = 0; axis < dimension; ++axis) {
      const std::string& value = fields[column.at(axes[axis])];
      const auto number = parse_number(value);
      if (!number) {
        throw core::InputError(file_name, line_number,
                               std::string("column ") + axes[axis] +
                                   ": expected a finite number, got '" + value + "'");
      }
      element.position[axis] = *number;
    }
    const auto category = column.find("category");
    const std::string category_name =
        category == column.end() ? "default" : fields[category->second];
    if (category_name.empty()) throw core::InputError(file_name, line_number, "empty category");
    element.category = scene.category_index(category_name);
    if (discs) {
      const std::string& value = fields[radius_column->second];
      const auto r = parse_number(value);
      if (!r || !(*r > 0.0)) {
        throw core::InputError(file_name, line_number,
                               "column radius: expected a positive number, got '" + value + "'");
      }
      if (*r > kLargestRadius * scene.window.sizes().maxCoeff()) {
        throw core::InputError(file_name, line_number,
                               "column radius: " + value + " is larger than " +
                                   std::to_string(static_cast<int>(kLargestRadius)) +
                                   " times the window");
      }
      const auto [found, added] =
          shape_of_radius.emplace(*r, static_cast<int>(scene.shapes.size()));
      if (added) scene.shapes.push_back(disc_shape(*r));
      element.shape = found->second;
    }
    const geometry::Vec3& p = element.position;
    const geometry::Box3& w = scene.window;
    if ((p.array() < w.min().array()).any() || (p.array() > w.max().array()).any()) {
      throw core::InputError(file_name, line_number, "the point lies outside {window}");
    }
    scene.elements.push_back(element);
  }
  if (scene.elements.empty())
    throw core::InputError(file_name, 0, "no points: the file has a header only");
  return scene;
}

geometry::Scene read_csv_points(const std::filesystem::path& file, const ReaderOptions& options) {
  const std::string text = read_text_file(file);
  return parse_csv_points(text, file.string(), options);
}

}  // namespace shapeproc::io
