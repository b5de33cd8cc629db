// A picture of a graph over a scene's window: its edges as lines, its nodes as dots labelled by
// index. It shows an exemplar's connectivity (`synthesize --method ijiri --show-connectivity`), so
// that a user can name the edges to flip.
#pragma once

#include <filesystem>
#include <utility>
#include <vector>

#include "libshapeproc/geometry/types.hpp"

namespace shapeproc::io {

// Writes the SVG atomically. Each edge is drawn from node `first` to node `first` + `offset`
// (so that an edge across a torus seam is drawn once, leaving the window); `open` marks nodes
// drawn hollow (e.g. border elements).
struct GraphEdge {
  int first = 0;
  geometry::Vec3 offset = geometry::Vec3::Zero();
};
void write_graph_svg(const std::filesystem::path& file, const geometry::Box3& window,
                     const std::vector<geometry::Vec3>& nodes, const std::vector<GraphEdge>& edges,
                     const std::vector<bool>& open);

}  // namespace shapeproc::io
