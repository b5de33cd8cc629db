// 3D proxies: quadric-error edge collapses with OpenMesh's decimater, solid tests, mass cubature.
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModHausdorffT.hh>
#include <OpenMesh/Tools/Decimater/ModNormalFlippingT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>
#include <cmath>
#include <map>

#include "libshapeproc/core/constants.hpp"
#include "libshapeproc/geometry/proxy.hpp"

namespace shapeproc::geometry {

namespace {

struct DoubleTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using OmMesh = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;

// Signed solid angle of triangle (a, b, c) seen from the origin (Van Oosterom & Strackee).
double solid_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double la = a.norm(), lb = b.norm(), lc = c.norm();
  const double numerator = a.dot(b.cross(c));
  const double denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
  return 2.0 * std::atan2(numerator, denominator);
}

bool mesh_is_closed(const std::vector<std::array<int, 3>>& triangles) {
  std::map<std::pair<int, int>, int> edges;
  for (const auto& t : triangles) {
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      ++edges[{std::min(a, b), std::max(a, b)}];
    }
  }
  for (const auto& [edge, count] : edges) {
    if (count != 2) return false;
  }
  return !triangles.empty();
}

// Error-bounded decimation: edge collapses ordered by quadric error (below tolerance^2), each
// allowed only while every removed vertex stays within `tolerance` of the simplified surface
// (OpenMesh's Hausdorff module: the quadric alone lets thin parts such as legs drift by many times
// the tolerance) and no face normal flips by more than 60 degrees. Topology-preserving collapses
// only, so closed meshes stay closed.
void decimate(TriangleMesh& mesh, double tolerance) {
  if (tolerance <= 0.0 || mesh.triangles.size() <= 4) return;
  OmMesh om;
  std::vector<OmMesh::VertexHandle> handles;
  for (const Vec3& v : mesh.vertices)
    handles.push_back(om.add_vertex(OmMesh::Point(v.x(), v.y(), v.z())));
  for (const auto& t : mesh.triangles) om.add_face(handles[t[0]], handles[t[1]], handles[t[2]]);
  om.request_vertex_status();
  om.request_edge_status();
  om.request_face_status();
  om.request_face_normals();
  om.update_face_normals();
  using Decimater = OpenMesh::Decimater::DecimaterT<OmMesh>;
  using Quadric = OpenMesh::Decimater::ModQuadricT<OmMesh>::Handle;
  using NormalFlipping = OpenMesh::Decimater::ModNormalFlippingT<OmMesh>::Handle;
  using Hausdorff = OpenMesh::Decimater::ModHausdorffT<OmMesh>::Handle;
  Decimater decimater(om);
  Quadric quadric;
  NormalFlipping flipping;
  Hausdorff hausdorff;
  decimater.add(quadric);
  decimater.add(flipping);
  decimater.add(hausdorff);
  decimater.module(hausdorff).set_tolerance(tolerance);
  decimater.module(quadric).set_max_err(tolerance * tolerance, false);
  decimater.module(flipping).set_max_normal_deviation(60.0);
  if (!decimater.initialize()) return;
  decimater.decimate();
  om.garbage_collection();
  TriangleMesh result;
  for (const auto vh : om.vertices()) {
    const auto& p = om.point(vh);
    result.vertices.emplace_back(p[0], p[1], p[2]);
  }
  for (const auto fh : om.faces()) {
    std::array<int, 3> t{};
    int k = 0;
    for (const auto vh : om.fv_range(fh)) t[k++] = vh.idx();
    result.triangles.push_back(t);
  }
  if (!result.triangles.empty()) mesh = std::move(result);
}

}  // namespace

bool Proxy3::inside(const Vec3& p) const {
  if (!closed || !box.contains(p)) return false;
  double total = 0.0;
  for (const auto& t : triangles) {
    total += solid_angle(vertices[t[0]] - p, vertices[t[1]] - p, vertices[t[2]] - p);
  }
  return std::abs(total) > 2.0 * core::kPi;  // winding number above one half
}

Proxy3 make_proxy3(const Shape& shape, const ProxyOptions& options) {
  Proxy3 proxy;
  if (std::holds_alternative<PointShape>(shape.geometry)) {
    proxy.point = true;
    proxy.vertices.push_back(Vec3::Zero());
    proxy.box = Box3(Vec3::Zero(), Vec3::Zero());
    proxy.triangle_tree = BoxTree<3>::build({proxy.box});
    proxy.mass = make_mass_model(std::vector<Vec3>{Vec3::Zero()}, {1.0});
    return proxy;
  }
  TriangleMesh mesh = std::get<MeshShape>(shape.geometry).mesh;
  proxy.source_triangles = mesh.triangles.size();
  const Box3 source_box = bounding_box(mesh);
  decimate(mesh, options.tolerance * source_box.diagonal().norm());
  proxy.vertices = std::move(mesh.vertices);
  proxy.triangles = std::move(mesh.triangles);
  proxy.closed = mesh_is_closed(proxy.triangles);
  std::vector<Box3> boxes;
  for (const auto& t : proxy.triangles) {
    Box3 box(proxy.vertices[t[0]]);
    box.extend(proxy.vertices[t[1]]).extend(proxy.vertices[t[2]]);
    boxes.push_back(box);
    proxy.box.extend(box);
  }
  proxy.triangle_tree = BoxTree<3>::build(boxes);

  // Mass: closed meshes are solids, integrated through their boundary (region_gravitation.hpp);
  // open surfaces are shells one cell thick, sampled at triangle points.
  std::vector<Vec3> points;
  std::vector<double> weights;
  const double h = proxy.box.sizes().maxCoeff() / options.mass_resolution_3d;
  if (proxy.closed) {
    proxy.solid = MassSurface3::from_closed_mesh(proxy.vertices, proxy.triangles);
    proxy.mass = make_mass_model(std::vector<Vec3>{proxy.solid.centroid}, {proxy.solid.volume});
    return proxy;
  }
  for (const auto& t : proxy.triangles) {
    const Vec3 &a = proxy.vertices[t[0]], &b = proxy.vertices[t[1]], &c = proxy.vertices[t[2]];
    const double area = 0.5 * (b - a).cross(c - a).norm();
    // Split into m^2 similar triangles so that samples are about a cell apart.
    const int m = std::max(1, static_cast<int>(std::ceil(std::sqrt(area) / std::max(h, 1e-300))));
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < m - i; ++j) {
        // upright sub-triangle centroid, and the inverted one when it exists
        points.push_back(a + ((i + 1.0 / 3) * (b - a) + (j + 1.0 / 3) * (c - a)) / m);
        weights.push_back(area / (m * m) * std::max(h, 1e-300));
        if (i + j + 1 < m) {
          points.push_back(a + ((i + 2.0 / 3) * (b - a) + (j + 2.0 / 3) * (c - a)) / m);
          weights.push_back(area / (m * m) * std::max(h, 1e-300));
        }
      }
  }
  if (points.empty()) {
    points.push_back(proxy.box.center());
    weights.push_back(1.0);
  }
  proxy.mass = make_mass_model(std::move(points), std::move(weights));
  return proxy;
}

MassModel3 sample_mass(const Proxy3& proxy, double cell) {
  std::vector<Vec3> points;
  std::vector<double> weights;
  Eigen::Vector3i n;
  for (int axis = 0; axis < 3; ++axis)
    n[axis] = std::max(1, static_cast<int>(std::ceil(proxy.box.sizes()[axis] / cell)));
  const Vec3 origin = proxy.box.center() - 0.5 * cell * n.cast<double>();
  for (int i = 0; i < n.x(); ++i)
    for (int j = 0; j < n.y(); ++j)
      for (int k = 0; k < n.z(); ++k) {
        const Vec3 p = origin + cell * Vec3(i + 0.5, j + 0.5, k + 0.5);
        if (proxy.inside(p)) {
          points.push_back(p);
          weights.push_back(cell * cell * cell);
        }
      }
  if (points.empty()) return make_mass_model(std::vector<Vec3>{proxy.box.center()}, {1.0});
  return make_mass_model(std::move(points), std::move(weights));
}

Shape proxy_as_shape(const Proxy3& proxy) {
  MeshShape mesh;
  mesh.mesh.vertices = proxy.vertices;
  mesh.mesh.triangles = proxy.triangles;
  return Shape{mesh, "proxy"};
}

}  // namespace shapeproc::geometry
