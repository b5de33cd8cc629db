#include "tools/cli/common.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <system_error>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/format.hpp"
#include "libshapeproc/geometry/tile_repeat.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/io/text.hpp"

namespace shapeproc::cli {

void BudgetFlags::add_to(CLI::App& command) {
  command
      .add_option("--max-elements", max_elements,
                  "refuse a request estimated to need more elements than this")
      ->check(positive_number())
      ->capture_default_str();
  command.add_option("--max-memory", max_memory,
                     "refuse a request estimated to need more memory than this, e.g. 8G (default: "
                     "16G or 3/4 of the machine's memory)");
}

core::ResourceBudget BudgetFlags::budget() const {
  core::ResourceBudget budget;
  budget.max_elements = max_elements;
  if (!max_memory.empty()) budget.max_memory = core::parse_bytes(max_memory, "--max-memory");
  return budget;
}

void ReaderFlags::add_to(CLI::App& command) {
  command
      .add_option("--elements", elements,
                  "SVG: what an element is: visual (a connected piece of ink), groups, paths or "
                  "subpaths; auto: groups when the file has non-layer groups, else visual")
      ->check(CLI::IsMember({"auto", "visual", "groups", "paths", "subpaths"}))
      ->capture_default_str();
  command
      .add_option("--nested", nested,
                  "SVG visual elements: a piece inside another's hole joins it or stays separate")
      ->check(CLI::IsMember({"join", "separate"}))
      ->capture_default_str();
  command.add_flag("--tile", tile,
                   "SVG, meshes: the file is one period of a seamless repeat: pieces the "
                   "border (a mesh's --window box) cuts join across it, and fits use periodic "
                   "edges");
  command.add_flag("--split-subpaths", split_subpaths,
                   "SVG: each disjoint subpath of a path is its own element (holes stay); the "
                   "same as --elements subpaths");
  command.add_option("--groups", groups, "SVG: a non-layer <g> is one element or a container")
      ->check(CLI::IsMember({"element", "container"}))
      ->capture_default_str();
  command.add_option("--category-by", category_by, "SVG: none|fill|stroke|class|layer|attr:NAME")
      ->capture_default_str();
  command.add_option("--split", split, "meshes: elements are connected components or OBJ groups")
      ->check(CLI::IsMember({"components", "groups"}))
      ->capture_default_str();
  command.add_option("--window", window,
                     "xmin,xmax,ymin,ymax[,zmin,zmax]: required for CSV, optional for meshes");
}

std::vector<std::string> ReaderFlags::arguments() const {
  // Only what differs from the defaults, so that no flag meets one it excludes.
  const ReaderFlags defaults;
  std::vector<std::string> out;
  const auto add = [&](const char* flag, const std::string& value, const std::string& standard) {
    if (value != standard) out.insert(out.end(), {flag, value});
  };
  add("--elements", elements, defaults.elements);
  add("--nested", nested, defaults.nested);
  add("--groups", groups, defaults.groups);
  add("--category-by", category_by, defaults.category_by);
  add("--split", split, defaults.split);
  if (tile) out.push_back("--tile");
  if (split_subpaths) out.push_back("--split-subpaths");
  if (!window.empty()) out.insert(out.end(), {"--window", window});
  return out;
}

io::ReaderOptions ReaderFlags::options() const {
  io::ReaderOptions options;
  options.elements = elements == "visual"     ? io::ElementRule::visual
                     : elements == "groups"   ? io::ElementRule::groups
                     : elements == "paths"    ? io::ElementRule::paths
                     : elements == "subpaths" ? io::ElementRule::subpaths
                                              : io::ElementRule::automatic;
  options.nested_separate = nested == "separate";
  options.tile = tile;
  options.split_subpaths = split_subpaths;
  options.groups = groups == "container" ? io::GroupMode::container : io::GroupMode::element;
  options.category_by = io::CategoryRule::parse(category_by);
  options.mesh_split = split == "groups" ? io::MeshSplit::groups : io::MeshSplit::components;
  if (!window.empty()) options.window = io::WindowOption::parse(window);
  return options;
}

nlohmann::json ReaderFlags::to_json() const {
  nlohmann::json j = {{"elements", elements}, {"nested", nested},
                      {"tile", tile},         {"split_subpaths", split_subpaths},
                      {"groups", groups},     {"category_by", category_by},
                      {"split", split}};
  if (!window.empty()) j["window"] = window;
  return j;
}

FittingExemplar read_fitting_exemplar(const std::string& input, const ReaderFlags& reader,
                                      int repeats) {
  FittingExemplar result{io::read_scene(input, reader.options()), 1};
  if (reader.tile && result.scene.dimension == 2) {
    result.repeats = repeats > 0 ? repeats : geometry::tile_repeats(result.scene.elements.size());
    result.scene = geometry::repeat_tile(result.scene, result.repeats);
  }
  return result;
}

int model_tile_repeats(const model::ShapeProcessModel& model) {
  return model.fit ? std::clamp(model.fit->tile_repeats, 0, 64) : 0;
}

void add_measurement_kind_options(CLI::App& command, std::string& distance,
                                  std::string& direction) {
  command.add_option("--distance", distance, "shape, centroid or hausdorff")
      ->check(CLI::IsMember({"shape", "centroid", "hausdorff"}))
      ->capture_default_str();
  command.add_option("--direction", direction, "gravitation or centroid")
      ->check(CLI::IsMember({"gravitation", "centroid"}))
      ->capture_default_str();
}

geometry::DistanceKind distance_kind(const std::string& name) {
  if (name == "centroid") return geometry::DistanceKind::centroid;
  if (name == "hausdorff") return geometry::DistanceKind::hausdorff;
  return geometry::DistanceKind::shape;
}

geometry::DirectionKind direction_kind(const std::string& name) {
  return name == "centroid" ? geometry::DirectionKind::centroid
                            : geometry::DirectionKind::gravitation;
}

void check_output_extension(const std::string& file, const std::string& option) {
  std::error_code unreadable;  // a name the system refuses is no directory
  if (std::filesystem::is_directory(file, unreadable))
    throw core::UsageError(
        option + ": '" + file +
        "' is a directory; name the output file (.svg, .obj, .ply, .csv or .png)");
  const std::string extension = io::extension_of(file);
  if (extension == "svg" || extension == "obj" || extension == "ply" || extension == "csv" ||
      extension == "png")
    return;
  throw core::UsageError(option + ": unknown output format '." + extension + "' of '" + file +
                         "': expected .svg, .obj, .ply, .csv or .png (a picture)");
}

namespace {
CLI::Validator number_check(const std::string& name, bool allow_zero) {
  return CLI::Validator(
      [allow_zero](std::string& text) -> std::string {
        double value = 0.0;
        if (!CLI::detail::lexical_cast(text, value) || !std::isfinite(value))
          return "expected a number, got '" + text + "'";
        if (allow_zero ? value < 0 : value <= 0)
          return std::string("must be ") + (allow_zero ? ">= 0" : "> 0") + ", got " + text;
        return {};
      },
      name);
}
}  // namespace

CLI::Validator positive_number() { return number_check("POSITIVE", false); }
CLI::Validator non_negative_number() { return number_check("NONNEGATIVE", true); }

std::string command_line(const std::vector<std::string>& arguments) {
  std::string out;
  for (std::size_t i = 0; i < arguments.size(); ++i) {
    if (i > 0) out += ' ';
    out += i == 0 ? "shapeproc" : arguments[i];
  }
  return out;
}

io::Provenance make_provenance(const std::string& command,
                               const std::vector<std::string>& arguments,
                               const nlohmann::json& parameters) {
  const nlohmann::json record = {{"tool", "shapeproc"},
                                 {"version", SHAPEPROC_VERSION},
                                 {"command", command},
                                 {"arguments", arguments},
                                 {"parameters", parameters}};
  return io::Provenance{record.dump()};
}

std::string one_line(std::string text) {
  for (char& c : text) {
    if (c == '\n' || c == '\r' || c == '\t') c = ' ';
  }
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return core::printable(text, 600);
}

std::string flag_for(std::string_view option) {
  if (option == "mesh_split") return "--split";
  std::string flag = "--" + std::string(option);
  std::replace(flag.begin(), flag.end(), '_', '-');
  return flag;
}

}  // namespace shapeproc::cli
