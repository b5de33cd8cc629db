#include "libshapeproc/io/scene_io.hpp"

#include <fstream>
#include <pugixml.hpp>

#include "libshapeproc/core/atomic_file.hpp"
#include "libshapeproc/core/error.hpp"
#include "libshapeproc/io/csv_reader.hpp"
#include "libshapeproc/io/mesh_reader.hpp"
#include "libshapeproc/io/svg_reader.hpp"
#include "libshapeproc/io/text.hpp"

namespace shapeproc::io {

namespace {

// Coordinates beyond this (or not finite, e.g. after a transform that overflows) are refused:
// squared distances and areas of such a scene leave a double's range or its precision.
constexpr double kMaxCoordinate = 1e12;

bool within_range(const geometry::Vec3& p) {
  return p.allFinite() && p.cwiseAbs().maxCoeff() <= kMaxCoordinate;
}

void check_coordinates(const geometry::Scene& scene, const std::filesystem::path& file) {
  const auto refuse = [&](const std::string& what) {
    throw core::InputError(file.string(), 0,
                           what + " has coordinates beyond ±1e12 or not finite (after transforms)");
  };
  if (!within_range(scene.window.min()) || !within_range(scene.window.max())) refuse("the window");
  for (std::size_t i = 0; i < scene.elements.size(); ++i) {
    const geometry::Element& e = scene.elements[i];
    const geometry::Box3 box = geometry::bounding_box(scene.shapes.at(e.shape));
    if (!within_range(e.position) || !within_range(box.min()) || !within_range(box.max())) {
      const std::string& name = scene.shapes.at(e.shape).name;
      refuse("element " + std::to_string(i + 1) + (name.empty() ? "" : " ('" + name + "')"));
    }
  }
}

geometry::Scene read_any(const std::filesystem::path& file, const ReaderOptions& options) {
  const std::string ext = extension_of(file);
  if (ext == "svg") return read_svg(file, options);
  if (ext == "obj" || ext == "ply" || ext == "off" || ext == "stl")
    return read_mesh_scene(file, options);
  if (ext == "csv") return read_csv_points(file, options);
  throw core::InputError(
      file.string(), 0,
      "unknown format '." + ext + "' (expected .svg, .obj, .ply, .off, .stl or .csv)");
}

}  // namespace

geometry::Scene read_scene(const std::filesystem::path& file, const ReaderOptions& options) {
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) throw core::InputError(file.string(), 0, "no such file");
  geometry::Scene scene = read_any(file, options);
  check_coordinates(scene, file);
  return scene;
}

void write_scene(const geometry::Scene& scene, const std::filesystem::path& file,
                 const Provenance& provenance) {
  const std::string ext = extension_of(file);
  if (ext == "svg") {
    if (scene.dimension != 2)
      throw core::UsageError(file.string() + ": SVG holds 2D scenes only; use .obj, .ply or .csv");
    core::write_file_atomically(file,
                                [&](std::ostream& out) { write_svg(scene, out, provenance); });
  } else if (ext == "obj" || ext == "ply") {
    if (scene.dimension != 3)
      throw core::UsageError(file.string() + ": " + ext +
                             " holds 3D scenes only; use .svg or .csv");
    if (!scene.elements.empty() && !std::holds_alternative<geometry::MeshShape>(
                                       scene.shapes.at(scene.elements.front().shape).geometry)) {
      throw core::UsageError(file.string() + ": point elements have no mesh to write; use .csv");
    }
    core::write_file_atomically(file, [&](std::ostream& out) {
      if (ext == "obj")
        write_obj(scene, out, provenance);
      else
        write_ply(scene, out, provenance);
    });
  } else if (ext == "csv") {
    core::write_file_atomically(file, [&](std::ostream& out) { write_csv(scene, out); });
    if (!provenance.json.empty()) {
      core::write_file_atomically(file.string() + ".json",
                                  [&](std::ostream& out) { out << provenance.json << '\n'; });
    }
  } else {
    throw core::UsageError(file.string() + ": unknown output format '." + ext +
                           "' (expected .svg, .obj, .ply or .csv)");
  }
}

std::string read_provenance(const std::filesystem::path& file) {
  const std::string ext = extension_of(file);
  if (ext == "svg") {
    pugi::xml_document document;
    if (!document.load_file(file.c_str())) return {};
    for (pugi::xml_node node : document.document_element().children()) {
      if (std::string(node.name()) == "metadata" &&
          std::string(node.attribute("id").value()) == "shapeproc") {
        return node.child_value();
      }
    }
    return {};
  }
  if (ext == "obj" || ext == "ply") {
    const std::string marker = ext == "obj" ? "# provenance " : "comment provenance ";
    std::ifstream in(file);
    std::string line;
    for (int n = 0; n < 64 && std::getline(in, line); ++n) {
      if (line.rfind(marker, 0) == 0) return line.substr(marker.size());
    }
    return {};
  }
  if (ext == "csv") {
    std::ifstream in(file.string() + ".json");
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  return {};
}

}  // namespace shapeproc::io
