#include "libshapeproc/methods/physics/collision_shapes.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>

#include "libshapeproc/geometry/proxy.hpp"

namespace shapeproc::methods {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Triangulation = CGAL::Constrained_Delaunay_triangulation_2<Kernel, CGAL::Default,
                                                                 CGAL::Exact_intersections_tag>;
using geometry::Vec2;

void constrain_ring(Triangulation& cdt, const std::vector<Vec2>& ring) {
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2& a = ring[i];
    const Vec2& b = ring[(i + 1) % ring.size()];
    if (a != b) cdt.insert_constraint(Kernel::Point_2(a.x(), a.y()), Kernel::Point_2(b.x(), b.y()));
  }
}

// Twice the triangle's area over its longest side: its smallest height.
double smallest_height(const std::array<Vec2, 3>& t) {
  const Vec2 u = t[1] - t[0], v = t[2] - t[0];
  const double twice_area = std::abs(u.x() * v.y() - u.y() * v.x());
  const double longest =
      std::max({(t[1] - t[0]).norm(), (t[2] - t[1]).norm(), (t[0] - t[2]).norm()});
  return longest > 0.0 ? twice_area / longest : 0.0;
}

CollisionShape planar_pieces(const geometry::Shape& shape, double thinnest) {
  CollisionShape out;
  const geometry::Proxy2 proxy = geometry::make_proxy2(shape, geometry::ProxyOptions{});
  Triangulation cdt;
  for (const geometry::Proxy2::Region& region : proxy.regions)
    for (int ring : region.rings)
      constrain_ring(cdt, proxy.polylines[static_cast<std::size_t>(ring)].points);
  for (const auto& strip : proxy.strips)
    for (const auto& ring : strip) constrain_ring(cdt, ring);
  for (auto face = cdt.finite_faces_begin(); face != cdt.finite_faces_end(); ++face) {
    std::array<Vec2, 3> t;
    for (int k = 0; k < 3; ++k) {
      const Kernel::Point_2& p = face->vertex(k)->point();
      t[static_cast<std::size_t>(k)] = Vec2(p.x(), p.y());
    }
    if (!proxy.in_mass((t[0] + t[1] + t[2]) / 3.0) || smallest_height(t) < thinnest) continue;
    out.triangles.push_back(t);
    for (const Vec2& p : t) out.radius = std::max(out.radius, p.norm());
  }
  return out;
}

}  // namespace

CollisionShape collision_shape(const geometry::Shape& shape, double thinnest) {
  switch (geometry::dimension(shape)) {
    case 2:
      return planar_pieces(shape, thinnest);
    case 3: {
      CollisionShape out;
      const geometry::Proxy3 proxy = geometry::make_proxy3(shape, geometry::ProxyOptions{});
      out.hull_points = proxy.vertices;
      for (const geometry::Vec3& p : proxy.vertices) out.radius = std::max(out.radius, p.norm());
      return out;
    }
    default:
      return {};
  }
}

}  // namespace shapeproc::methods
