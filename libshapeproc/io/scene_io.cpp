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

geometry::Scene read_scene(const std::filesystem::path& file, const ReaderOptions& options) {
  const std::string ext = extension_of(file);
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) throw core::InputError(file.string(), 0, "no such file");
  if (ext == "svg") return read_svg(file, options);
  if (ext == "obj" || ext == "ply" || ext == "off" || ext == "stl")
    return read_mesh_scene(file, options);
  if (ext == "csv") return read_csv_points(file, options);
  throw core::InputError(
      file.string(), 0,
      "unknown format '." + ext + "' (expected .svg, .obj, .ply, .off, .stl or .csv)");
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
