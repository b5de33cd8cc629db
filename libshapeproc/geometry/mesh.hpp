// Triangle meshes: the geometry of 3D elements.
#pragma once

#include <array>
#include <vector>

#include "libshapeproc/geometry/types.hpp"

namespace shapeproc::geometry {

struct TriangleMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;  // indices into `vertices`, counter-clockwise outside
};

Box3 bounding_box(const TriangleMesh& mesh);
void translate(TriangleMesh& mesh, const Vec3& offset);

}  // namespace shapeproc::geometry
