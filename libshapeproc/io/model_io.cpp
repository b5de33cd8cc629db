#include "libshapeproc/io/model_io.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <nlohmann/json.hpp>

#include "libshapeproc/core/atomic_file.hpp"
#include "libshapeproc/core/error.hpp"
#include "libshapeproc/io/fit_record_io.hpp"
#include "libshapeproc/io/neighbour_offsets_io.hpp"
#include "libshapeproc/io/scene_writers.hpp"
#include "libshapeproc/io/svg_grammar.hpp"
#include "libshapeproc/io/svg_path_data.hpp"
#include "libshapeproc/io/text.hpp"

namespace shapeproc::io {

using nlohmann::json;
using namespace shapeproc::model;

namespace {

constexpr const char* kFormat = "shapeproc-model";
constexpr int kVersion = 1;

json number_or_null(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

json shape_json(const geometry::Shape& shape) {
  if (const auto* planar = std::get_if<geometry::PlanarShape>(&shape.geometry)) {
    json parts = json::array();
    for (const geometry::Drawable2& part : planar->parts) {
      parts.push_back(
          {{"d", svg_path_data(part.paths)},
           {"fill_rule", part.fill_rule == geometry::FillRule::evenodd ? "evenodd" : "nonzero"},
           {"style", part.style}});
    }
    return {{"type", "paths"}, {"parts", parts}};
  }
  if (const auto* mesh = std::get_if<geometry::MeshShape>(&shape.geometry)) {
    json vertices = json::array(), triangles = json::array();
    for (const geometry::Vec3& v : mesh->mesh.vertices) vertices.push_back({v.x(), v.y(), v.z()});
    for (const auto& t : mesh->mesh.triangles) triangles.push_back({t[0], t[1], t[2]});
    return {{"type", "mesh"}, {"vertices", vertices}, {"triangles", triangles}};
  }
  return {{"type", "point"}};
}

const char* distance_name(geometry::DistanceKind d) {
  switch (d) {
    case geometry::DistanceKind::shape:
      return "shape";
    case geometry::DistanceKind::centroid:
      return "centroid";
    case geometry::DistanceKind::hausdorff:
      return "hausdorff";
  }
  return "shape";
}

// Reading with paths in messages.
class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    throw core::InputError(file_, 0, where + ": " + what);
  }
  const json& field(const json& object, const std::string& where, const char* name) const {
    if (!object.is_object() || !object.contains(name))
      fail(where.empty() ? name : where + "." + name, "missing");
    return object.at(name);
  }
  double number(const json& v, const std::string& where) const {
    if (v.is_null()) return std::numeric_limits<double>::quiet_NaN();
    if (!v.is_number()) fail(where, "expected a number, got " + v.dump());
    return v.get<double>();
  }
  int integer(const json& v, const std::string& where) const {
    if (!v.is_number_integer()) fail(where, "expected an integer, got " + v.dump());
    // Read wide and checked: 4294967298 must not wrap around to 2.
    if (v.is_number_unsigned() ? v.get<std::uint64_t>() > std::numeric_limits<int>::max()
                               : v.get<std::int64_t>() < std::numeric_limits<int>::min() ||
                                     v.get<std::int64_t>() > std::numeric_limits<int>::max())
      fail(where, "expected an integer in the range of an int, got " + v.dump());
    return v.get<int>();
  }
  bool boolean(const json& v, const std::string& where) const {
    if (!v.is_boolean()) fail(where, "expected true or false, got " + v.dump());
    return v.get<bool>();
  }
  std::string text(const json& v, const std::string& where) const {
    if (!v.is_string()) fail(where, "expected a string, got " + v.dump());
    return v.get<std::string>();
  }
  std::vector<double> numbers(const json& v, const std::string& where) const {
    if (!v.is_array()) fail(where, "expected an array of numbers");
    std::vector<double> out;
    for (std::size_t k = 0; k < v.size(); ++k)
      out.push_back(number(v[k], where + "[" + std::to_string(k) + "]"));
    return out;
  }
  const json& array(const json& v, const std::string& where) const {
    if (!v.is_array()) fail(where, "expected an array");
    return v;
  }

  geometry::Shape shape(const json& j, const std::string& where, int dimension) const {
    const std::string type = text(field(j, where, "type"), where + ".type");
    if (type == "point") return geometry::Shape{geometry::PointShape{}, ""};
    if (type == "paths") {
      if (dimension != 2) fail(where + ".type", "paths in a 3D model");
      geometry::PlanarShape planar;
      const json& parts = array(field(j, where, "parts"), where + ".parts");
      for (std::size_t k = 0; k < parts.size(); ++k) {
        const std::string at = where + ".parts[" + std::to_string(k) + "]";
        geometry::Drawable2 drawable;
        try {
          drawable.paths = svg::parse_path_data(text(field(parts[k], at, "d"), at + ".d"));
        } catch (const svg::GrammarError& e) {
          fail(at + ".d", e.what());
        }
        if (drawable.paths.empty()) fail(at + ".d", "no path");
        if (parts[k].contains("fill_rule")) {
          const std::string rule = text(parts[k]["fill_rule"], at + ".fill_rule");
          if (rule != "evenodd" && rule != "nonzero")
            fail(at + ".fill_rule", "expected evenodd or nonzero");
          drawable.fill_rule =
              rule == "evenodd" ? geometry::FillRule::evenodd : geometry::FillRule::nonzero;
        }
        if (parts[k].contains("style")) {
          const json& style = parts[k]["style"];
          if (!style.is_object()) fail(at + ".style", "expected an object of SVG properties");
          for (const auto& [name, value] : style.items())
            drawable.style[name] = text(value, at + ".style." + name);
        }
        planar.parts.push_back(std::move(drawable));
      }
      if (planar.parts.empty()) fail(where + ".parts", "at least one part is needed");
      return geometry::Shape{std::move(planar), ""};
    }
    if (type == "mesh") {
      if (dimension != 3) fail(where + ".type", "a mesh in a 2D model");
      geometry::MeshShape mesh;
      const json& vertices = array(field(j, where, "vertices"), where + ".vertices");
      for (std::size_t k = 0; k < vertices.size(); ++k) {
        const std::vector<double> v =
            numbers(vertices[k], where + ".vertices[" + std::to_string(k) + "]");
        if (v.size() != 3 ||
            !std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); })) {
          fail(where + ".vertices[" + std::to_string(k) + "]", "expected three finite numbers");
        }
        mesh.mesh.vertices.emplace_back(v[0], v[1], v[2]);
      }
      const json& triangles = array(field(j, where, "triangles"), where + ".triangles");
      for (std::size_t k = 0; k < triangles.size(); ++k) {
        const std::string at = where + ".triangles[" + std::to_string(k) + "]";
        const json& t = array(triangles[k], at);
        if (t.size() != 3) fail(at, "expected three vertex indices");
        std::array<int, 3> tri{};
        for (int c = 0; c < 3; ++c) {
          tri[static_cast<std::size_t>(c)] = integer(t[static_cast<std::size_t>(c)], at);
          if (tri[static_cast<std::size_t>(c)] < 0 ||
              tri[static_cast<std::size_t>(c)] >= static_cast<int>(mesh.mesh.vertices.size())) {
            fail(at, "vertex index out of range");
          }
        }
        mesh.mesh.triangles.push_back(tri);
      }
      if (mesh.mesh.triangles.empty())
        fail(where + ".triangles", "at least one triangle is needed");
      return geometry::Shape{std::move(mesh), ""};
    }
    fail(where + ".type", "expected paths, mesh or point, got '" + type + "'");
  }

 private:
  std::string file_;
};

ParameterStatus status_from(const std::string& s, const Reader& reader, const std::string& where) {
  if (s == "free") return ParameterStatus::free;
  if (s == "boundary") return ParameterStatus::boundary;
  if (s == "unidentifiable") return ParameterStatus::unidentifiable;
  if (s == "unbounded") return ParameterStatus::unbounded;
  if (s == "unreachable") return ParameterStatus::unreachable;
  if (s == "fixed") return ParameterStatus::fixed;
  reader.fail(
      where,
      "expected free, boundary, unidentifiable, unbounded, unreachable or fixed, got '" + s + "'");
}

// A model file nests a few levels; deeper nesting is refused before the parser and the code that
// walks the document (recursive in places) see it.
constexpr int kMaxJsonNesting = 64;

void check_json_nesting(std::string_view text, const std::string& file_name) {
  int depth = 0, line = 1;
  bool in_string = false, escaped = false;
  for (const char c : text) {
    if (c == '\n') ++line;
    if (in_string) {
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
      } else if (c == '"') {
        in_string = false;
      }
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonNesting) {
        throw core::InputError(file_name, line,
                               "JSON nests more than " + std::to_string(kMaxJsonNesting) +
                                   " levels deep, the most a model file may");
      }
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
}

}  // namespace

std::string model_to_json(const ShapeProcessModel& model) {
  json categories = json::array();
  for (const CategoryParameters& c : model.categories) {
    categories.push_back({{"name", c.name},
                          {"beta", c.beta},
                          {"beta_standard_error", number_or_null(c.beta_standard_error)},
                          {"beta_status", to_string(c.beta_status)}});
    if (c.layer != 0) categories.back()["layer"] = c.layer;
    if (c.anchor >= 0) {
      categories.back()["anchor"] = c.anchor;
      categories.back()["anchor_reach"] = c.anchor_reach;
    }
    if (c.hidden) categories.back()["hidden"] = true;
  }
  json interaction = json::array();
  for (const PairInteraction& pair : model.interactions) {
    json axes = json::array();
    for (const AxisParameters& a : pair.axes) {
      json direction = json::array();
      for (int k = 0; k < model.dimension; ++k) direction.push_back(a.direction[k]);
      json errors = json::array(), status = json::array();
      for (std::size_t k = 0; k < a.gammas.size(); ++k) {
        errors.push_back(
            number_or_null(k < a.gamma_standard_errors.size() ? a.gamma_standard_errors[k] : NAN));
        status.push_back(to_string(k < a.status.size() ? a.status[k] : ParameterStatus::fixed));
      }
      json axis = {{"direction", direction},
                   {"thresholds", a.thresholds},
                   {"gammas", a.gammas},
                   {"gamma_standard_errors", errors},
                   {"status", status}};
      if (!a.observed_pairs.empty()) axis["observed_pairs"] = a.observed_pairs;
      if (std::any_of(a.saturations.begin(), a.saturations.end(), [](int s) { return s > 0; }))
        axis["saturations"] = a.saturations;
      axes.push_back(axis);
    }
    json entry = {{"categories", {pair.first, pair.second}}, {"axes", axes}};
    if (!pair.choice.empty()) entry["choice"] = pair.choice;
    interaction.push_back(std::move(entry));
  }
  json shapes = json::array();
  for (const ModelShape& s : model.shapes) {
    json entry = {{"category", s.category}, {"geometry", shape_json(s.shape)}};
    if (s.shape_class >= 0) entry["class"] = s.shape_class;
    if (!s.shape.name.empty()) entry["name"] = s.shape.name;
    shapes.push_back(entry);
  }
  json document = {{"format", kFormat},
                   {"version", kVersion},
                   {"dimension", model.dimension},
                   {"units", model.units},
                   {"measurement",
                    {{"distance", distance_name(model.measurement.distance)},
                     {"direction", model.measurement.direction == geometry::DirectionKind::centroid
                                       ? "centroid"
                                       : "gravitation"},
                     {"directions", model.measurement.directions},
                     {"proxy_tolerance", model.measurement.proxy_tolerance}}},
                   {"categories", categories},
                   {"interaction", interaction},
                   {"shapes", shapes}};
  if (!model.shape_classes.empty()) {
    json classes = json::array();
    for (const model::ShapeClass& c : model.shape_classes)
      classes.push_back({{"category", c.category}, {"weight", c.weight}, {"label", c.label}});
    document["shape_classes"] = classes;
  }
  if (!model.neighbour_offsets.empty())
    document["neighbour_offsets"] =
        neighbour_offsets_json(model.neighbour_offsets, model.dimension);
  if (model.fit) document["fit"] = fit_record_json(*model.fit);
  return document.dump(2) + "\n";
}

std::optional<double> recorded_exemplar_density(const ShapeProcessModel& model) {
  return model.fit ? model.fit->exemplar_density() : std::nullopt;
}

void write_model(const ShapeProcessModel& model, const std::filesystem::path& file) {
  const std::string text = model_to_json(model);
  core::write_file_atomically(file, [&](std::ostream& out) { out << text; });
}

namespace {

// The text as JSON; malformed text is an InputError naming the file and, where known, the line.
json parse_document(std::string_view text, const std::string& file_name) {
  if (trim(text).empty()) throw core::InputError(file_name, 0, "the file is empty");
  check_json_nesting(text, file_name);
  try {
    return json::parse(text.begin(), text.end());
  } catch (const json::parse_error& e) {
    const std::size_t byte = std::min(e.byte, text.size());
    const int line = 1 + static_cast<int>(std::count(
                             text.begin(), text.begin() + static_cast<std::ptrdiff_t>(byte), '\n'));
    std::string message = e.what();
    if (const std::size_t colon = message.rfind(": "); colon != std::string::npos)
      message = message.substr(colon + 2);
    throw core::InputError(file_name, line, "malformed JSON: " + message);
  } catch (const json::exception& e) {  // a number beyond a double's range, too deep a nesting
    std::string message = e.what();
    if (const std::size_t bracket = message.find("] "); bracket != std::string::npos)
      message = message.substr(bracket + 2);
    throw core::InputError(file_name, 0, "malformed JSON: " + message);
  }
}

std::vector<CategoryParameters> parse_categories(const json& document, const Reader& r) {
  std::vector<CategoryParameters> out;
  const json& categories = r.array(r.field(document, "", "categories"), "categories");
  for (std::size_t c = 0; c < categories.size(); ++c) {
    const std::string where = "categories[" + std::to_string(c) + "]";
    CategoryParameters category;
    category.name = r.text(r.field(categories[c], where, "name"), where + ".name");
    category.beta = r.number(r.field(categories[c], where, "beta"), where + ".beta");
    if (categories[c].contains("beta_standard_error"))
      category.beta_standard_error = r.number(categories[c]["beta_standard_error"], where);
    if (categories[c].contains("beta_status")) {
      category.beta_status = status_from(
          r.text(categories[c]["beta_status"], where + ".beta_status"), r, where + ".beta_status");
    }
    if (categories[c].contains("layer"))
      category.layer = r.integer(categories[c]["layer"], where + ".layer");
    if (categories[c].contains("anchor"))
      category.anchor = r.integer(categories[c]["anchor"], where + ".anchor");
    if (categories[c].contains("anchor_reach"))
      category.anchor_reach = r.number(categories[c]["anchor_reach"], where + ".anchor_reach");
    if (categories[c].contains("hidden"))
      category.hidden = r.boolean(categories[c]["hidden"], where + ".hidden");
    out.push_back(category);
  }
  return out;
}

// One axis of a pair, at `at` ("interaction[p].axes[i]").
AxisParameters parse_axis(const json& value, const std::string& at, int dimension,
                          const Reader& r) {
  AxisParameters axis;
  const std::vector<double> direction =
      r.numbers(r.field(value, at, "direction"), at + ".direction");
  if (static_cast<int>(direction.size()) != dimension) {
    r.fail(at + ".direction", "expected " + std::to_string(dimension) + " numbers for a " +
                                  std::to_string(dimension) + "D model");
  }
  axis.direction = geometry::Vec3::Zero();
  for (int k = 0; k < dimension; ++k) axis.direction[k] = direction[static_cast<std::size_t>(k)];
  axis.thresholds = r.numbers(r.field(value, at, "thresholds"), at + ".thresholds");
  axis.gammas = r.numbers(r.field(value, at, "gammas"), at + ".gammas");
  const std::size_t bands = axis.gammas.size();
  axis.gamma_standard_errors.assign(bands, std::numeric_limits<double>::quiet_NaN());
  axis.status.assign(bands, ParameterStatus::fixed);
  if (value.contains("gamma_standard_errors")) {
    const std::vector<double> se =
        r.numbers(value["gamma_standard_errors"], at + ".gamma_standard_errors");
    if (se.size() != bands) r.fail(at + ".gamma_standard_errors", "expected one per gamma");
    axis.gamma_standard_errors = se;
  }
  if (value.contains("status")) {
    const json& status = r.array(value["status"], at + ".status");
    if (status.size() != bands) r.fail(at + ".status", "expected one per gamma");
    for (std::size_t k = 0; k < bands; ++k) {
      axis.status[k] = status_from(r.text(status[k], at + ".status"), r,
                                   at + ".status[" + std::to_string(k) + "]");
    }
  }
  if (value.contains("observed_pairs")) {
    for (const json& v : r.array(value["observed_pairs"], at + ".observed_pairs"))
      axis.observed_pairs.push_back(r.integer(v, at + ".observed_pairs"));
  }
  if (value.contains("saturations")) {
    const json& saturations = r.array(value["saturations"], at + ".saturations");
    if (saturations.size() != bands) r.fail(at + ".saturations", "expected one per gamma");
    for (const json& v : saturations) axis.saturations.push_back(r.integer(v, at + ".saturations"));
  }
  return axis;
}

// The pairs' interactions; `axes_seen`: the most axes of any pair (what the directions default
// to).
std::vector<PairInteraction> parse_interactions(const json& document, int dimension,
                                                const Reader& r, std::size_t& axes_seen) {
  std::vector<PairInteraction> out;
  const json& interaction = r.array(r.field(document, "", "interaction"), "interaction");
  axes_seen = 0;
  for (std::size_t p = 0; p < interaction.size(); ++p) {
    const std::string where = "interaction[" + std::to_string(p) + "]";
    PairInteraction pair;
    const json& cats = r.array(r.field(interaction[p], where, "categories"), where + ".categories");
    if (cats.size() != 2) r.fail(where + ".categories", "expected two category indices");
    pair.first = r.integer(cats[0], where + ".categories[0]");
    pair.second = r.integer(cats[1], where + ".categories[1]");
    if (pair.first > pair.second) std::swap(pair.first, pair.second);
    const json& axes = r.array(r.field(interaction[p], where, "axes"), where + ".axes");
    axes_seen = std::max(axes_seen, axes.size());
    for (std::size_t i = 0; i < axes.size(); ++i)
      pair.axes.push_back(
          parse_axis(axes[i], where + ".axes[" + std::to_string(i) + "]", dimension, r));
    if (interaction[p].contains("choice"))
      pair.choice = r.text(interaction[p]["choice"], where + ".choice");
    out.push_back(std::move(pair));
  }
  return out;
}

// Measurement settings; the number of directions defaults to what the axes imply.
void parse_measurement(const json& document, std::size_t axes_seen, const Reader& r,
                       ShapeProcessModel& model) {
  int directions =
      axes_seen <= 1 ? 1 : (model.dimension == 2 ? static_cast<int>(2 * axes_seen) : 12);
  if (document.contains("measurement")) {
    const json& m = document["measurement"];
    if (!m.is_object()) r.fail("measurement", "expected an object");
    if (m.contains("distance")) {
      const std::string d = r.text(m["distance"], "measurement.distance");
      if (d == "shape")
        model.measurement.distance = geometry::DistanceKind::shape;
      else if (d == "centroid")
        model.measurement.distance = geometry::DistanceKind::centroid;
      else if (d == "hausdorff")
        model.measurement.distance = geometry::DistanceKind::hausdorff;
      else
        r.fail("measurement.distance", "expected shape, centroid or hausdorff, got '" + d + "'");
    }
    if (m.contains("direction")) {
      const std::string d = r.text(m["direction"], "measurement.direction");
      if (d == "gravitation")
        model.measurement.direction = geometry::DirectionKind::gravitation;
      else if (d == "centroid")
        model.measurement.direction = geometry::DirectionKind::centroid;
      else
        r.fail("measurement.direction", "expected gravitation or centroid, got '" + d + "'");
    }
    if (m.contains("directions")) directions = r.integer(m["directions"], "measurement.directions");
    if (m.contains("proxy_tolerance")) {
      model.measurement.proxy_tolerance =
          r.number(m["proxy_tolerance"], "measurement.proxy_tolerance");
      if (!(model.measurement.proxy_tolerance >= 0 && model.measurement.proxy_tolerance < 1)) {
        r.fail("measurement.proxy_tolerance", "must be in [0, 1)");
      }
    }
  }
  model.measurement.directions = directions;
}

// The shapes, centred on their bounding boxes, and the shape classes.
void parse_shapes(const json& document, const Reader& r, ShapeProcessModel& model) {
  const json& shapes = r.array(r.field(document, "", "shapes"), "shapes");
  for (std::size_t s = 0; s < shapes.size(); ++s) {
    const std::string where = "shapes[" + std::to_string(s) + "]";
    ModelShape shape;
    shape.category = r.integer(r.field(shapes[s], where, "category"), where + ".category");
    shape.shape =
        r.shape(r.field(shapes[s], where, "geometry"), where + ".geometry", model.dimension);
    if (shapes[s].contains("name")) shape.shape.name = r.text(shapes[s]["name"], where + ".name");
    if (shapes[s].contains("class"))
      shape.shape_class = r.integer(shapes[s]["class"], where + ".class");
    // Shapes are stored centred on their bounding box; hand-written ones are centred here. One
    // centred already (to within rounding) is left as written, so that reading a model written
    // from a model read gives it back bit for bit (the sampler follows every bit).
    const geometry::Box3 box = geometry::bounding_box(shape.shape);
    if (!box.isEmpty() && box.center().norm() > 1e-12 * box.sizes().norm())
      geometry::translate(shape.shape, -box.center());
    model.shapes.push_back(std::move(shape));
  }
  if (!document.contains("shape_classes")) return;
  const json& classes = r.array(document["shape_classes"], "shape_classes");
  for (std::size_t k = 0; k < classes.size(); ++k) {
    const std::string where = "shape_classes[" + std::to_string(k) + "]";
    model::ShapeClass c;
    c.category = r.integer(r.field(classes[k], where, "category"), where + ".category");
    c.weight = r.number(r.field(classes[k], where, "weight"), where + ".weight");
    if (classes[k].contains("label")) c.label = r.text(classes[k]["label"], where + ".label");
    model.shape_classes.push_back(c);
  }
}

}  // namespace

ShapeProcessModel parse_model(std::string_view text, const std::string& file_name) {
  const json document = parse_document(text, file_name);
  const Reader r(file_name);
  if (!document.is_object() || !document.contains("format") || document["format"] != kFormat) {
    throw core::InputError(
        file_name, 0,
        std::string("not a shapeproc model file (it has no \"format\": \"") + kFormat + "\")");
  }
  const int version = r.integer(r.field(document, "", "version"), "version");
  if (version != kVersion)
    r.fail("version", "this shapeproc reads version " + std::to_string(kVersion) + ", got " +
                          std::to_string(version));
  ShapeProcessModel model;
  model.dimension = r.integer(r.field(document, "", "dimension"), "dimension");
  if (model.dimension != 2 && model.dimension != 3) r.fail("dimension", "must be 2 or 3");
  model.units = document.contains("units") ? r.text(document["units"], "units")
                                           : (model.dimension == 2 ? "px" : "1");
  model.categories = parse_categories(document, r);
  std::size_t axes_seen = 0;
  model.interactions = parse_interactions(document, model.dimension, r, axes_seen);
  parse_measurement(document, axes_seen, r, model);
  parse_shapes(document, r, model);
  if (document.contains("neighbour_offsets"))
    model.neighbour_offsets =
        parse_neighbour_offsets(document["neighbour_offsets"], model.dimension, file_name);
  if (document.contains("fit")) {
    if (!document["fit"].is_object()) r.fail("fit", "must be an object");
    model.fit = parse_fit_record(document["fit"]);
  }
  try {
    validate(model);
  } catch (const std::invalid_argument& e) {
    throw core::InputError(file_name, 0, e.what());
  }
  return model;
}

ShapeProcessModel read_model(const std::filesystem::path& file) {
  const std::string extension = extension_of(file);
  if (extension == "svg" || extension == "obj" || extension == "ply" || extension == "off" ||
      extension == "stl" || extension == "csv") {
    throw core::UsageError(
        file.string() + ": this is an exemplar, not a model; use shapeproc synthesize " +
        file.string() + " (or shapeproc fit " + file.string() + " -o model.json first)");
  }
  const std::string text = read_text_file(file);
  return parse_model(text, file.string());
}

}  // namespace shapeproc::io
