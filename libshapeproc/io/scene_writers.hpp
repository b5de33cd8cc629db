// Writers for scenes: SVG (2D), OBJ and PLY (3D), CSV placements (any dimension).
#pragma once

#include <ostream>
#include <string>

#include "libshapeproc/geometry/scene.hpp"

namespace shapeproc::io {

// What produced an output, recorded inside it (SVG <metadata>, OBJ/PLY comments) or beside it
// (CSV: a JSON sidecar). `json` is one JSON object, e.g. the command, its parameters and seed.
struct Provenance {
  std::string json;
};

// Each element drawn with its own style; the window is the viewBox. An element with one drawable
// is a <path>, one with several is a <g> of paths; each carries `data-category` with its category
// name, so `--category-by attr:data-category` (or `layer`) reads the categories back. Each
// category is an Inkscape layer named for it, holding its elements in scene order. Throws
// UsageError for non-2D scenes.
void write_svg(const geometry::Scene& scene, std::ostream& out, const Provenance& provenance);

// One `o` object per element (named e<index>, with `# category` comments); 3D scenes only.
void write_obj(const geometry::Scene& scene, std::ostream& out, const Provenance& provenance);

// ASCII PLY of all elements' triangles (double coordinates); 3D scenes only.
void write_ply(const geometry::Scene& scene, std::ostream& out, const Provenance& provenance);

// Placements: header `x,y[,z],category,shape`, one row per element; category is the category
// name, shape the index into the scene's shapes.
void write_csv(const geometry::Scene& scene, std::ostream& out);

}  // namespace shapeproc::io
