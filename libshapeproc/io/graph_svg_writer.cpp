#include "libshapeproc/io/graph_svg_writer.hpp"

#include <algorithm>
#include <cmath>
#include <ostream>

#include "libshapeproc/core/atomic_file.hpp"
#include "libshapeproc/io/text.hpp"

namespace shapeproc::io {

void write_graph_svg(const std::filesystem::path& file, const geometry::Box3& window,
                     const std::vector<geometry::Vec3>& nodes, const std::vector<GraphEdge>& edges,
                     const std::vector<bool>& open) {
  const geometry::Vec3 size = window.sizes();
  // Dots and labels scaled to the mean spacing of the nodes over the window.
  const double spacing =
      std::sqrt(size.x() * size.y() / static_cast<double>(std::max<std::size_t>(nodes.size(), 1)));
  const double dot = 0.06 * spacing, font = 0.22 * spacing, line = 0.02 * spacing;
  const auto n = [](double v) { return core::format_number(v); };
  core::write_file_atomically(file, [&](std::ostream& out) {
    out << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" << n(window.min().x()) << ' '
        << n(window.min().y()) << ' ' << n(size.x()) << ' ' << n(size.y()) << "\">\n";
    out << "<rect x=\"" << n(window.min().x()) << "\" y=\"" << n(window.min().y()) << "\" width=\""
        << n(size.x()) << "\" height=\"" << n(size.y()) << "\" fill=\"white\"/>\n";
    out << "<g stroke=\"#3060c0\" stroke-width=\"" << n(line) << "\">\n";
    for (const GraphEdge& e : edges) {
      const geometry::Vec3& a = nodes[static_cast<std::size_t>(e.first)];
      const geometry::Vec3 b = a + e.offset;
      out << "<line x1=\"" << n(a.x()) << "\" y1=\"" << n(a.y()) << "\" x2=\"" << n(b.x())
          << "\" y2=\"" << n(b.y()) << "\"/>\n";
    }
    out << "</g>\n<g font-family=\"sans-serif\" font-size=\"" << n(font) << "\">\n";
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const geometry::Vec3& p = nodes[i];
      const bool hollow = i < open.size() && open[i];
      out << "<circle cx=\"" << n(p.x()) << "\" cy=\"" << n(p.y()) << "\" r=\"" << n(dot)
          << "\" fill=\"" << (hollow ? "white" : "black") << "\" stroke=\"black\" stroke-width=\""
          << n(line) << "\"/>";
      out << "<text x=\"" << n(p.x() + dot) << "\" y=\"" << n(p.y() - dot) << "\">" << i
          << "</text>\n";
    }
    out << "</g>\n</svg>\n";
  });
}

}  // namespace shapeproc::io
