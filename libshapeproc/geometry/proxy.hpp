// Proxy geometry (paper §4, Fig. 2): coarse versions of the element shapes on which the pair
// measurements are computed. 2D: curves flattened adaptively, then simplified by Douglas–Peucker
// (Boost.Geometry) within an error bound; 3D: error-bounded edge collapses with quadric error
// metrics (OpenMesh's decimater, with normal-flip protection). Each proxy also carries the
// bounding-volume hierarchy used by the distance queries and the mass model of its gravitation.
#pragma once

#include <vector>

#include "libshapeproc/geometry/box_tree.hpp"
#include "libshapeproc/geometry/gravitation.hpp"
#include "libshapeproc/geometry/region_gravitation.hpp"
#include "libshapeproc/geometry/shape.hpp"

namespace shapeproc::geometry {

// The proxy tolerance at which collisions are judged (`stats`, `fidelity`, the growth methods)
// and the sampler keeps drawn outlines apart (sample/overlap_guard.hpp): close enough to the drawn
// outlines that what overlaps at it overlaps in the drawing, far finer than the measurements'
// default (ProxyOptions::tolerance).
inline constexpr double kOutlineTolerance = 0.002;

struct ProxyOptions {
  // Simplification error bound as a fraction of the element's bounding-box diagonal (2D:
  // Douglas–Peucker distance; 3D: quadric error as a distance). Curves are flattened first at a
  // quarter of it.
  double tolerance = 0.01;
  // Mass of curves (2D outlines that bound no filled region): a strip of this half-width, as a
  // fraction of the element's diagonal, unless the drawable has a stroke-width (half of it).
  double curve_half_width = 0.005;
  // Mass cubature of open meshes (3D): grid cells along the longest side.
  int mass_resolution_3d = 16;
};

// 2D proxy: polylines (closed rings and open curves) and the filled regions they bound.
struct Proxy2 {
  struct Polyline {
    std::vector<Vec2> points;  // a closed ring does not repeat its first point
    bool closed = false;
  };
  // A filled drawable: its closed rings, combined by its fill rule.
  struct Region {
    std::vector<int> rings;  // indices into polylines
    FillRule rule = FillRule::nonzero;
  };
  std::vector<Polyline> polylines;
  std::vector<Region> regions;
  std::vector<Vec2> segment_start, segment_end;  // every proxy segment (points: zero length)
  std::vector<int> segment_polyline;             // the polyline each segment belongs to
  BoxTree<2> segment_tree;
  Box2 box;
  // The mass whose gravitation gives the relative orientation: the filled regions, plus strips
  // around curves (rings: closed polygons combined even-odd, one group per strip polygon).
  std::vector<std::vector<std::vector<Vec2>>> strips;
  MassBoundary2 mass;
  std::size_t source_segments = 0;  // segments of the shape before flattening and simplification

  std::size_t segment_count() const { return segment_start.size(); }
  // Whether p lies in a filled region (on the fill rule of each region).
  bool inside(const Vec2& p) const;
  // Whether p lies in the mass (a filled region or a curve's strip).
  bool in_mass(const Vec2& p) const;
};

// Midpoint-rule samples of a 2D proxy's mass on the square lattice of spacing `cell` through
// `lattice`, each cell tested at subsamples^2 points (weight = covered area, at the covered
// centroid; with 1 subsample, plain cell centres): a dense, independent reference for tests.
MassModel2 sample_mass(const Proxy2& proxy, double cell, const Vec2& lattice = Vec2::Zero(),
                       int subsamples = 4);

// 3D proxy: a simplified triangle mesh; closed meshes are solids.
struct Proxy3 {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;
  bool closed = false;
  bool point = false;  // a point element: vertices[0] only
  BoxTree<3> triangle_tree;
  Box3 box;
  MassSurface3 solid;  // closed meshes: the solid's mass, through its boundary
  MassModel3 mass;     // open meshes and points: cubature points (a shell one cell thick)
  std::size_t source_triangles = 0;

  // Whether p lies inside the solid (closed meshes only): generalized winding number > 1/2.
  bool inside(const Vec3& p) const;
};

// Midpoint samples of a closed 3D proxy's solid on a cubic lattice of spacing `cell` (cell
// centres inside the mesh): a dense, independent reference for tests.
MassModel3 sample_mass(const Proxy3& proxy, double cell);

// `shape` must be a point or planar shape (local coordinates).
Proxy2 make_proxy2(const Shape& shape, const ProxyOptions& options);
// `shape` must be a point or mesh shape.
Proxy3 make_proxy3(const Shape& shape, const ProxyOptions& options);

// The proxies drawn as shapes (2D: one drawable of line segments with no fill; 3D: the mesh), to
// look at them (`shapeproc measure --proxy-out`).
Shape proxy_as_shape(const Proxy2& proxy);
Shape proxy_as_shape(const Proxy3& proxy);

}  // namespace shapeproc::geometry
