// Options that decide how a file becomes a scene: what an element is, which category it gets,
// and which window it is observed in.
#pragma once

#include <optional>
#include <string>

#include "libshapeproc/geometry/types.hpp"

namespace shapeproc::io {

// How SVG elements get their category (`--category-by`).
struct CategoryRule {
  enum class Kind { none, fill, stroke, class_name, layer, attribute };
  Kind kind = Kind::none;
  std::string attribute;  // for Kind::attribute: the attribute's qualified name

  // Parses "none", "fill", "stroke", "class", "layer" or "attr:NAME"; throws UsageError.
  static CategoryRule parse(const std::string& text);
  std::string to_string() const;
};

// What a non-layer SVG `<g>` is: one element (Inkscape's habit) or a container like a layer.
enum class GroupMode { element, container };
// How a mesh file is split into elements: connected components, or OBJ `o`/`g` groups.
enum class MeshSplit { components, groups };

// An observation window given on the command line.
struct WindowOption {
  int dimension = 2;
  geometry::Box3 box;

  // Parses "xmin,xmax,ymin,ymax[,zmin,zmax]"; throws UsageError on bad syntax or empty ranges.
  static WindowOption parse(const std::string& text);
};

struct ReaderOptions {
  bool split_subpaths = false;
  GroupMode groups = GroupMode::element;
  CategoryRule category_by;
  MeshSplit mesh_split = MeshSplit::components;
  std::optional<WindowOption> window;
};

}  // namespace shapeproc::io
