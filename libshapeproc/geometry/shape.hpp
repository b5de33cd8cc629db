// Element shapes: a point, a set of styled 2D paths, or a triangle mesh.
#pragma once

#include <map>
#include <string>
#include <variant>
#include <vector>

#include "libshapeproc/geometry/mesh.hpp"
#include "libshapeproc/geometry/path.hpp"

namespace shapeproc::geometry {

enum class FillRule { nonzero, evenodd };

// Presentation properties needed to redraw a drawable, as SVG property names and values
// ("fill" -> "#ff0000", "stroke-width" -> "2"). Inherited values are already resolved.
using Style = std::map<std::string, std::string>;

// One SVG drawable after normalisation: its subpaths (outlines and holes together, as the fill rule
// decides), in absolute coordinates.
struct Drawable2 {
  std::vector<Path2> paths;
  FillRule fill_rule = FillRule::nonzero;
  Style style;

  // A drawable is a filled region unless its fill is "none"; otherwise only its outline counts.
  bool filled() const;
};

struct PointShape {};
struct PlanarShape {
  std::vector<Drawable2> parts;
};
struct MeshShape {
  TriangleMesh mesh;
};

// A shape of the shape space. Scenes keep shapes in local coordinates: the centre of the bounding
// box is the origin, and an element places its shape at its reference position.
struct Shape {
  std::variant<PointShape, PlanarShape, MeshShape> geometry;
  std::string name;  // where it came from (SVG id, OBJ group), may be empty
};

// 0 for points, 2 for planar shapes, 3 for meshes.
int dimension(const Shape& shape);
// Exact bounding box (z = 0 for planar shapes; a single point for point shapes).
Box3 bounding_box(const Shape& shape);
void translate(Shape& shape, const Vec3& offset);
// Number of path segments (2D) or triangles (3D); 0 for points.
std::size_t primitive_count(const Shape& shape);
std::size_t path_count(const Shape& shape);

}  // namespace shapeproc::geometry
