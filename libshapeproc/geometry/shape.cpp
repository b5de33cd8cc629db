#include "libshapeproc/geometry/shape.hpp"

namespace shapeproc::geometry {

namespace {
template <class... Fs>
struct Overloaded : Fs... {
  using Fs::operator()...;
};
template <class... Fs>
Overloaded(Fs...) -> Overloaded<Fs...>;
}  // namespace

bool Drawable2::filled() const {
  const auto it = style.find("fill");
  return it == style.end() || it->second != "none";
}

int dimension(const Shape& shape) {
  return std::visit(
      Overloaded{[](const PointShape&) { return 0; }, [](const PlanarShape&) { return 2; },
                 [](const MeshShape&) { return 3; }},
      shape.geometry);
}

Box3 bounding_box(const Shape& shape) {
  return std::visit(Overloaded{[](const PointShape&) { return Box3(Vec3::Zero()); },
                               [](const PlanarShape& planar) {
                                 Box2 box;
                                 for (const Drawable2& part : planar.parts)
                                   for (const Path2& path : part.paths)
                                     box.extend(bounding_box(path));
                                 return lift(box);
                               },
                               [](const MeshShape& m) { return bounding_box(m.mesh); }},
                    shape.geometry);
}

void translate(Shape& shape, const Vec3& offset) {
  std::visit(Overloaded{[](PointShape&) {},
                        [&](PlanarShape& planar) {
                          for (Drawable2& part : planar.parts)
                            for (Path2& path : part.paths) translate(path, offset.head<2>());
                        },
                        [&](MeshShape& m) { translate(m.mesh, offset); }},
             shape.geometry);
}

std::size_t primitive_count(const Shape& shape) {
  return std::visit(Overloaded{[](const PointShape&) -> std::size_t { return 0; },
                               [](const PlanarShape& planar) {
                                 std::size_t n = 0;
                                 for (const Drawable2& part : planar.parts)
                                   for (const Path2& path : part.paths) n += path.segments.size();
                                 return n;
                               },
                               [](const MeshShape& m) { return m.mesh.triangles.size(); }},
                    shape.geometry);
}

std::size_t path_count(const Shape& shape) {
  if (const auto* planar = std::get_if<PlanarShape>(&shape.geometry)) {
    std::size_t n = 0;
    for (const Drawable2& part : planar->parts) n += part.paths.size();
    return n;
  }
  return 0;
}

}  // namespace shapeproc::geometry
