#include "libshapeproc/io/scene_writers.hpp"

#include <variant>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/format.hpp"
#include "libshapeproc/io/csv_reader.hpp"
#include "libshapeproc/io/svg_path_data.hpp"
#include "libshapeproc/io/text.hpp"

namespace shapeproc::io {

using geometry::Scene;

namespace {

void write_drawable(std::ostream& out, const geometry::Drawable2& drawable,
                    const std::string& attributes) {
  out << "<path" << attributes << " d=\"" << svg_path_data(drawable.paths) << '"';
  if (drawable.fill_rule == geometry::FillRule::evenodd) out << " fill-rule=\"evenodd\"";
  for (const auto& [name, value] : drawable.style) {
    out << ' ' << name << "=\"" << core::xml_escape(value) << '"';
  }
  out << "/>\n";
}

void require_dimension(const Scene& scene, int dimension, const char* format) {
  if (scene.dimension != dimension) {
    throw core::UsageError(std::string("cannot write a ") + std::to_string(scene.dimension) +
                           "D scene as " + format + " (" + std::to_string(dimension) + "D only)");
  }
}

}  // namespace

namespace {

// One element: a <path>, a <g> of paths, or a dot for a point element.
void write_svg_element(const Scene& scene, std::size_t i, std::ostream& out) {
  const geometry::Box3& w = scene.window;
  const geometry::Element& element = scene.elements[i];
  const geometry::Shape shape = scene.placed_shape(i);
  const std::string attributes = " id=\"e" + std::to_string(i) + "\" data-category=\"" +
                                 core::xml_escape(scene.categories.at(element.category).name) +
                                 "\"";
  if (const auto* planar = std::get_if<geometry::PlanarShape>(&shape.geometry)) {
    if (planar->parts.size() == 1) {
      write_drawable(out, planar->parts.front(), attributes);
    } else {
      out << "<g" << attributes << ">\n";
      for (const geometry::Drawable2& part : planar->parts) write_drawable(out, part, "");
      out << "</g>\n";
    }
  } else {
    // A point element: a small dot so that the output shows where it is, marked as a point so
    // that it reads back as one (and measures as its exemplar's points do).
    const double r = 0.005 * w.sizes().head<2>().norm();
    out << "<circle" << attributes << " data-point=\"1\" cx=\""
        << core::format_number(element.position.x()) << "\" cy=\""
        << core::format_number(element.position.y()) << "\" r=\"" << core::format_number(r)
        << "\"/>\n";
  }
}

}  // namespace

void write_svg(const Scene& scene, std::ostream& out, const Provenance& provenance) {
  require_dimension(scene, 2, "SVG");
  const geometry::Box3& w = scene.window;
  const std::string width = core::format_number(w.sizes().x()),
                    height = core::format_number(w.sizes().y());
  const std::string unit = scene.units == "px" ? "" : scene.units;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" "
         "xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" width=\""
      << width << unit << "\" height=\"" << height << unit << "\" viewBox=\""
      << core::format_number(w.min().x()) << ' ' << core::format_number(w.min().y()) << ' ' << width
      << ' ' << height << "\">\n";
  if (!provenance.json.empty()) {
    out << "<metadata id=\"shapeproc\">" << core::xml_escape(provenance.json) << "</metadata>\n";
  }
  // Each category in its own layer (Inkscape's groupmode), elements in scene order within it.
  for (std::size_t c = 0; c < scene.categories.size(); ++c) {
    const std::string name = core::xml_escape(scene.categories[c].name);
    out << "<g inkscape:groupmode=\"layer\" inkscape:label=\"" << name << "\" id=\"layer" << c + 1
        << "\">\n";
    for (std::size_t i = 0; i < scene.elements.size(); ++i) {
      if (scene.elements[i].category == static_cast<int>(c)) write_svg_element(scene, i, out);
    }
    out << "</g>\n";
  }
  out << "</svg>\n";
}

void write_obj(const Scene& scene, std::ostream& out, const Provenance& provenance) {
  require_dimension(scene, 3, "OBJ");
  out << "# written by shapeproc\n";
  if (!provenance.json.empty()) out << "# provenance " << provenance.json << "\n";
  std::size_t offset = 1;
  for (std::size_t i = 0; i < scene.elements.size(); ++i) {
    const geometry::Shape shape = scene.placed_shape(i);
    const auto* mesh = std::get_if<geometry::MeshShape>(&shape.geometry);
    if (!mesh) throw core::UsageError("cannot write a point element as OBJ geometry");
    out << "o e" << i << "\n# category " << scene.categories.at(scene.elements[i].category).name
        << "\n";
    for (const geometry::Vec3& v : mesh->mesh.vertices) {
      out << "v " << core::format_number(v.x()) << ' ' << core::format_number(v.y()) << ' '
          << core::format_number(v.z()) << '\n';
    }
    for (const auto& t : mesh->mesh.triangles) {
      out << "f " << t[0] + offset << ' ' << t[1] + offset << ' ' << t[2] + offset << '\n';
    }
    offset += mesh->mesh.vertices.size();
  }
}

void write_ply(const Scene& scene, std::ostream& out, const Provenance& provenance) {
  require_dimension(scene, 3, "PLY");
  std::size_t vertices = 0, triangles = 0;
  std::vector<geometry::Shape> placed;
  for (std::size_t i = 0; i < scene.elements.size(); ++i) {
    placed.push_back(scene.placed_shape(i));
    const auto* mesh = std::get_if<geometry::MeshShape>(&placed.back().geometry);
    if (!mesh) throw core::UsageError("cannot write a point element as PLY geometry");
    vertices += mesh->mesh.vertices.size();
    triangles += mesh->mesh.triangles.size();
  }
  out << "ply\nformat ascii 1.0\ncomment written by shapeproc\n";
  if (!provenance.json.empty()) out << "comment provenance " << provenance.json << "\n";
  out << "element vertex " << vertices
      << "\nproperty double x\nproperty double y\nproperty double z\n"
      << "element face " << triangles << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const geometry::Shape& shape : placed) {
    for (const geometry::Vec3& v : std::get<geometry::MeshShape>(shape.geometry).mesh.vertices) {
      out << core::format_number(v.x()) << ' ' << core::format_number(v.y()) << ' '
          << core::format_number(v.z()) << '\n';
    }
  }
  std::size_t offset = 0;
  for (const geometry::Shape& shape : placed) {
    const auto& mesh = std::get<geometry::MeshShape>(shape.geometry).mesh;
    for (const auto& t : mesh.triangles) {
      out << "3 " << t[0] + offset << ' ' << t[1] + offset << ' ' << t[2] + offset << '\n';
    }
    offset += mesh.vertices.size();
  }
}

void write_csv(const Scene& scene, std::ostream& out) {
  const bool three = scene.dimension == 3;
  out << (three ? "x,y,z,category,shape\n" : "x,y,category,shape\n");
  for (const geometry::Element& e : scene.elements) {
    out << core::format_number(e.position.x()) << ',' << core::format_number(e.position.y()) << ',';
    if (three) out << core::format_number(e.position.z()) << ',';
    out << csv_field(scene.categories.at(e.category).name) << ',' << e.shape << '\n';
  }
}

}  // namespace shapeproc::io
