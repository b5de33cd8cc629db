#include "libshapeproc/geometry/mesh.hpp"

namespace shapeproc::geometry {

Box3 bounding_box(const TriangleMesh& mesh) {
  Box3 box;
  for (const Vec3& v : mesh.vertices) box.extend(v);
  return box;
}

void translate(TriangleMesh& mesh, const Vec3& offset) {
  for (Vec3& v : mesh.vertices) v += offset;
}

}  // namespace shapeproc::geometry
