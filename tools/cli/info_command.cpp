// shapeproc info EXEMPLAR [--json]: what the readers made of a file.
#include <iomanip>
#include <memory>
#include <sstream>

#include "libshapeproc/core/format.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/io/text.hpp"
#include "tools/cli/commands.hpp"
#include "tools/cli/common.hpp"

namespace shapeproc::cli {

namespace {

struct InfoArguments {
  std::string input;
  bool json = false;
  ReaderFlags reader;
};

const char* shape_kind(const geometry::Shape& shape) {
  switch (geometry::dimension(shape)) {
    case 0:
      return "point";
    case 2:
      return "paths";
    default:
      return "mesh";
  }
}

nlohmann::json box_json(const geometry::Box3& box, int dimension) {
  nlohmann::json min = nlohmann::json::array(), max = nlohmann::json::array();
  for (int axis = 0; axis < dimension; ++axis) {
    min.push_back(box.min()[axis]);
    max.push_back(box.max()[axis]);
  }
  return {{"min", min}, {"max", max}};
}

// Seven significant digits: enough to read, free of float-to-double noise (JSON keeps all digits).
std::string short_number(double value) {
  std::ostringstream text;
  text << std::setprecision(7) << value;
  return text.str();
}

std::string box_text(const geometry::Box3& box, int dimension) {
  std::string text;
  for (int axis = 0; axis < dimension; ++axis) {
    if (axis > 0) text += " x ";
    text += "[" + short_number(box.min()[axis]) + ", " + short_number(box.max()[axis]) + "]";
  }
  return text;
}

nlohmann::json describe(const geometry::Scene& scene, const std::string& input) {
  const std::vector<std::size_t> counts = geometry::category_counts(scene);
  nlohmann::json categories = nlohmann::json::array();
  for (std::size_t c = 0; c < scene.categories.size(); ++c) {
    categories.push_back({{"name", scene.categories[c].name}, {"count", counts[c]}});
  }
  nlohmann::json elements = nlohmann::json::array();
  std::size_t primitives = 0;
  for (std::size_t i = 0; i < scene.elements.size(); ++i) {
    const geometry::Element& e = scene.elements[i];
    const geometry::Shape& shape = scene.shapes.at(e.shape);
    geometry::Box3 box = geometry::bounding_box(shape);
    box.translate(e.position);
    const std::size_t count = geometry::primitive_count(shape);
    primitives += count;
    nlohmann::json item = {
        {"index", i},
        {"category", scene.categories.at(e.category).name},
        {"shape", e.shape},
        {"kind", shape_kind(shape)},
        {"position", std::vector<double>(e.position.data(), e.position.data() + scene.dimension)},
        {"bbox", box_json(box, scene.dimension)}};
    if (scene.dimension == 2) {
      item["paths"] = geometry::path_count(shape);
      item["segments"] = count;
    } else {
      item["triangles"] = count;
    }
    if (!shape.name.empty()) item["name"] = shape.name;
    elements.push_back(item);
  }
  const double mean = scene.elements.empty() ? 0.0
                                             : static_cast<double>(primitives) /
                                                   static_cast<double>(scene.elements.size());
  return {{"file", input},
          {"dimension", scene.dimension},
          {"window", box_json(scene.window, scene.dimension)},
          {"window_measure", scene.window_measure()},
          {"units", scene.units},
          {"element_count", scene.elements.size()},
          {"categories", categories},
          {scene.dimension == 2 ? "segments_total" : "triangles_total", primitives},
          {"primitives_per_element", mean},
          {"notes", scene.notes},
          {"elements", elements}};
}

void print_text(const geometry::Scene& scene, const nlohmann::json& d, std::ostream& out) {
  const bool planar = scene.dimension == 2;
  out << "file:       " << d["file"].get<std::string>() << '\n'
      << "dimension:  " << scene.dimension << '\n'
      << "window:     " << box_text(scene.window, scene.dimension) << "  ("
      << (planar ? "area " : "volume ") << short_number(scene.window_measure()) << ")\n"
      << "units:      " << scene.units << '\n'
      << "elements:   " << scene.elements.size() << "  (" << std::fixed << std::setprecision(1)
      << d["primitives_per_element"].get<double>() << (planar ? " segments" : " triangles")
      << " per element)\n";
  out.unsetf(std::ios::fixed);
  for (const std::string& note : scene.notes)
    out << "note:       " << core::printable(note, 2000) << '\n';
  out << "categories: " << scene.categories.size() << '\n';
  for (const auto& c : d["categories"]) {
    out << "  " << core::printable(c["name"].get<std::string>()) << ": "
        << c["count"].get<std::size_t>() << '\n';
  }
  out << "\n  index  category        " << (planar ? "paths  segments" : "triangles")
      << "  bounding box\n";
  for (const auto& e : d["elements"]) {
    const geometry::Element& element = scene.elements[e["index"].get<std::size_t>()];
    geometry::Box3 box = geometry::bounding_box(scene.shapes.at(element.shape));
    box.translate(element.position);
    out << "  " << std::setw(5) << e["index"].get<std::size_t>() << "  " << std::left
        << std::setw(14) << core::printable(e["category"].get<std::string>(), 40) << std::right
        << "  ";
    if (planar) {
      out << std::setw(5) << e["paths"].get<std::size_t>() << "  " << std::setw(8)
          << e["segments"].get<std::size_t>();
    } else {
      out << std::setw(9) << e["triangles"].get<std::size_t>();
    }
    out << "  " << box_text(box, scene.dimension) << '\n';
  }
}

}  // namespace

void add_info_command(CLI::App& app, Action& action) {
  auto args = std::make_shared<InfoArguments>();
  CLI::App* command = app.add_subcommand(
      "info",
      "Describe an exemplar: dimension, window, units, elements, categories, and per "
      "element its segment or triangle count and bounding box");
  command->add_option("EXEMPLAR", args->input, "input file (.svg, .obj, .ply, .off, .stl, .csv)")
      ->required();
  command->add_flag("--json", args->json, "print JSON instead of text");
  args->reader.add_to(*command);
  command->callback([&action, args] {
    action = [args](std::ostream& out) {
      const geometry::Scene scene = io::read_scene(args->input, args->reader.options());
      const nlohmann::json description = describe(scene, args->input);
      if (args->json) {
        out << description.dump(2) << '\n';
      } else {
        print_text(scene, description, out);
      }
      return 0;
    };
  });
}

}  // namespace shapeproc::cli
