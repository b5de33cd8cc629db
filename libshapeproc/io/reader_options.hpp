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
// What an SVG element is (`--elements`): a connected piece of visible ink (geometry/
// visual_elements.hpp), a non-layer group (drawables outside groups stand alone), each drawable,
// or each disjoint subpath of a drawable. `automatic`: groups when the file has a non-layer group
// with drawables (a group wrapping everything only carries style) or was written by this project
// (its outputs write one drawable or group per element), otherwise visual.
enum class ElementRule { automatic, visual, groups, paths, subpaths };
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
  ElementRule elements = ElementRule::automatic;
  bool split_subpaths = false;   // the older spelling of elements = subpaths
  bool nested_separate = false;  // visual: a piece inside another's hole is its own element
  // The file is one period of a seamless repeat: pieces the border cuts join their counterparts
  // across it (SVG; meshes split by components, on their box window), and the window is the
  // tile.
  bool tile = false;
  GroupMode groups = GroupMode::element;
  CategoryRule category_by;
  MeshSplit mesh_split = MeshSplit::components;
  std::optional<WindowOption> window;
  // A synthesised output of the project's own (an SVG carrying its record) may hold no element:
  // a chain that ended empty. Read it as an empty scene instead of refusing it.
  bool empty_outputs = false;
};

}  // namespace shapeproc::io
