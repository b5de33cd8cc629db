#include "libshapeproc/methods/ijiri2008/delaunay_connectivity.hpp"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "libshapeproc/core/constants.hpp"
#include "libshapeproc/core/error.hpp"

namespace shapeproc::methods {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using DataStructure =
    CGAL::Triangulation_data_structure_2<VertexBase, CGAL::Triangulation_face_base_2<Kernel>>;
using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, DataStructure>;
using Triangle = std::array<int, 3>;  // counter-clockwise

// The points triangulated: the positions, and on a torus their eight periodic images too
// (image t holds point t n + i; image 4 is the tile itself).
struct PointSet {
  std::vector<Vec3> point;
  int n = 0;
  bool periodic = false;
  int original(int p) const { return p % n; }
  bool central(int p) const { return !periodic || p / n == 4; }
};

PointSet replicate(const std::vector<Vec3>& positions, const geometry::Domain& domain) {
  PointSet set;
  set.n = static_cast<int>(positions.size());
  set.periodic = domain.periodic();
  if (!set.periodic) {
    set.point = positions;
    return set;
  }
  const Vec3 period = domain.period();
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx)
      for (const Vec3& p : positions)
        set.point.push_back(p + Vec3(dx * period.x(), dy * period.y(), 0));
  return set;
}

double orientation(const Vec3& a, const Vec3& b, const Vec3& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

// The largest interior angle of triangle abc.
double largest_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
  const auto angle = [](const Vec3& at, const Vec3& u, const Vec3& v) {
    const Vec3 p = u - at, q = v - at;
    return std::atan2(std::abs(p.x() * q.y() - p.y() * q.x()), p.x() * q.x() + p.y() * q.y());
  };
  return std::max({angle(a, b, c), angle(b, c, a), angle(c, a, b)});
}

// Step 1: Delaunay, less the skewed triangles.
std::vector<Triangle> unskewed_triangles(const PointSet& set) {
  std::vector<std::pair<Kernel::Point_2, int>> input;
  for (std::size_t i = 0; i < set.point.size(); ++i)
    input.emplace_back(Kernel::Point_2(set.point[i].x(), set.point[i].y()), static_cast<int>(i));
  Delaunay delaunay(input.begin(), input.end());
  std::vector<Triangle> kept;
  constexpr double skewed = 2.0 * core::kPi / 3.0;
  for (auto f = delaunay.finite_faces_begin(); f != delaunay.finite_faces_end(); ++f) {
    const Triangle t{f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
    const Vec3 &a = set.point[static_cast<std::size_t>(t[0])],
               &b = set.point[static_cast<std::size_t>(t[1])],
               &c = set.point[static_cast<std::size_t>(t[2])];
    if (largest_angle(a, b, c) <= skewed) kept.push_back(t);
  }
  return kept;
}

// The position of triangle t's directed edge a→b (0, 1 or 2 for a at t[0], t[1], t[2]), or -1.
int directed_edge(const Triangle& t, int a, int b) {
  for (int k = 0; k < 3; ++k)
    if (t[static_cast<std::size_t>(k)] == a && t[static_cast<std::size_t>((k + 1) % 3)] == b)
      return k;
  return -1;
}

// Flips the edge between points a and b; false when it does not border two kept triangles.
bool flip_edge(std::vector<Triangle>& triangles, const PointSet& set, int a, int b,
               const EdgeFlip& asked) {
  int first = -1, second = -1, ka = -1, kb = -1;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    if (const int k = directed_edge(triangles[t], a, b); k >= 0)
      first = static_cast<int>(t), ka = k;
    if (const int k = directed_edge(triangles[t], b, a); k >= 0)
      second = static_cast<int>(t), kb = k;
  }
  if (first < 0 || second < 0) return false;
  const int c = triangles[static_cast<std::size_t>(first)][static_cast<std::size_t>((ka + 2) % 3)];
  const int d = triangles[static_cast<std::size_t>(second)][static_cast<std::size_t>((kb + 2) % 3)];
  const auto& p = set.point;
  const auto at = [&](int i) { return p[static_cast<std::size_t>(i)]; };
  if (orientation(at(a), at(d), at(c)) <= 0.0 || orientation(at(d), at(b), at(c)) <= 0.0)
    throw core::ArgumentError("edge flips", "the edge " + std::to_string(asked.a) + "-" +
                                                std::to_string(asked.b) +
                                                " cannot flip: its two triangles do not form a "
                                                "convex quadrilateral");
  triangles[static_cast<std::size_t>(first)] = {a, d, c};
  triangles[static_cast<std::size_t>(second)] = {d, b, c};
  return true;
}

// Step 2: the user's flips, on every periodic image of the edge.
void apply_flips(std::vector<Triangle>& triangles, const PointSet& set,
                 const std::vector<EdgeFlip>& flips, const geometry::Domain& domain) {
  for (const EdgeFlip& flip : flips) {
    if (flip.a < 0 || flip.b < 0 || flip.a >= set.n || flip.b >= set.n || flip.a == flip.b)
      throw core::ArgumentError("edge flips", "the edge " + std::to_string(flip.a) + "-" +
                                                  std::to_string(flip.b) +
                                                  " does not join two of the exemplar's " +
                                                  std::to_string(set.n) + " elements");
    const Vec3 offset = domain.minimum_image(set.point[static_cast<std::size_t>(flip.b)] -
                                             set.point[static_cast<std::size_t>(flip.a)]);
    bool flipped = false;
    const int images = set.periodic ? 9 : 1;
    for (int image = 0; image < images; ++image) {
      const int a = image * set.n + flip.a;
      // The image of b at the edge's offset from this image of a, if it is in the point set.
      int b = -1;
      for (int other = 0; other < images && b < 0; ++other) {
        const int candidate = other * set.n + flip.b;
        const Vec3 d =
            set.point[static_cast<std::size_t>(candidate)] - set.point[static_cast<std::size_t>(a)];
        if ((d - offset).norm() <= 1e-9 * (1.0 + offset.norm())) b = candidate;
      }
      if (b >= 0 && flip_edge(triangles, set, a, b, flip)) flipped = true;
    }
    if (!flipped)
      throw core::ArgumentError("edge flips", "the edge " + std::to_string(flip.a) + "-" +
                                                  std::to_string(flip.b) +
                                                  " is not an inner edge of the connectivity");
  }
}

// Step 3: rings, counter-clockwise by angle, and whether each closes.
Connectivity rings_of(const std::vector<Triangle>& triangles, const PointSet& set) {
  std::vector<std::set<int>> around(set.point.size());
  std::vector<std::set<std::pair<int, int>>> successor(set.point.size());
  for (const Triangle& t : triangles)
    for (int k = 0; k < 3; ++k) {
      const int v = t[static_cast<std::size_t>(k)], b = t[static_cast<std::size_t>((k + 1) % 3)],
                c = t[static_cast<std::size_t>((k + 2) % 3)];
      around[static_cast<std::size_t>(v)].insert(b);
      around[static_cast<std::size_t>(v)].insert(c);
      successor[static_cast<std::size_t>(v)].insert({b, c});
    }
  Connectivity out;
  out.rings.resize(static_cast<std::size_t>(set.n));
  std::set<std::pair<int, int>> edges;
  double shortest = std::numeric_limits<double>::infinity(), sum = 0.0;
  int count = 0;
  for (std::size_t v = 0; v < set.point.size(); ++v) {
    if (!set.central(static_cast<int>(v))) continue;
    std::vector<int> ring(around[v].begin(), around[v].end());
    const Vec3& centre = set.point[v];
    const auto angle = [&](int p) {
      const Vec3 d = set.point[static_cast<std::size_t>(p)] - centre;
      return std::atan2(d.y(), d.x());
    };
    std::sort(ring.begin(), ring.end(), [&](int p, int q) { return angle(p) < angle(q); });
    Ring& r = out.rings[static_cast<std::size_t>(set.original(static_cast<int>(v)))];
    r.closed = ring.size() >= 3;
    for (std::size_t k = 0; k < ring.size(); ++k) {
      if (!successor[v].count({ring[k], ring[(k + 1) % ring.size()]})) r.closed = false;
      r.neighbour.push_back(set.original(ring[k]));
      r.offset.push_back(set.point[static_cast<std::size_t>(ring[k])] - centre);
      const double length = r.offset.back().norm();
      shortest = std::min(shortest, length);
      sum += length;
      ++count;
      const int a = set.original(static_cast<int>(v)), b = set.original(ring[k]);
      edges.insert({std::min(a, b), std::max(a, b)});
    }
  }
  out.edges.assign(edges.begin(), edges.end());
  if (count > 0) {
    out.shortest_edge = shortest;
    out.mean_edge = sum / count;
  }
  return out;
}

}  // namespace

std::vector<std::pair<int, Vec3>> ring_edges(const Connectivity& connectivity) {
  std::vector<std::pair<int, Vec3>> out;
  for (std::size_t e = 0; e < connectivity.rings.size(); ++e) {
    const Ring& ring = connectivity.rings[e];
    for (std::size_t k = 0; k < ring.neighbour.size(); ++k) {
      const auto other = static_cast<std::size_t>(ring.neighbour[k]);
      const Vec3& o = ring.offset[k];
      // Each edge is in both ends' rings: keep the end with the smaller index (for an element's
      // own image, the offset pointing up or right).
      if (other > e || (other == e && (o.y() > 0 || (o.y() == 0 && o.x() > 0))))
        out.emplace_back(static_cast<int>(e), o);
    }
  }
  return out;
}

Connectivity delaunay_connectivity(const std::vector<Vec3>& positions,
                                   const geometry::Domain& domain,
                                   const std::vector<EdgeFlip>& flips) {
  if (positions.size() < 3)
    throw core::ArgumentError("delaunay_connectivity", "connectivity needs at least 3 elements");
  const PointSet set = replicate(positions, domain);
  std::vector<Triangle> triangles = unskewed_triangles(set);
  apply_flips(triangles, set, flips, domain);
  return rings_of(triangles, set);
}

}  // namespace shapeproc::methods
