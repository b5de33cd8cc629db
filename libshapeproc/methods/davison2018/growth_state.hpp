// The output of region growing (Davison et al. 2018) while it grows: its elements (position, the
// exemplar element it was copied from, its current best match, its bounding radius), the
// free-space points around them (Davison's F, eq. 3) and the grids that answer "what is near
// here". Elements and free-space points are indexed by grids of the neighbourhood radius, on the
// domain's torus or in its box.
//
// A free-space point belongs to the element whose free-space vector made it; it is free while no
// element's bounding circle (sphere) overlaps it. When an element moves, its points are made
// again at its new place (eq. 3 for the elements that moved).
#pragma once

#include <limits>
#include <vector>

#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/geometry/neighbour_grid.hpp"
#include "libshapeproc/geometry/proxy.hpp"
#include "libshapeproc/methods/common/em_exemplar.hpp"
#include "libshapeproc/methods/davison2018/free_space.hpp"

namespace shapeproc::methods {

// What growth learns from the exemplar once. Every exemplar element carries its own parameters
// (Davison §4.1), so that exemplars of different scales can grow together from one palette
// (growth_palette.hpp): `em`'s global radius and spacing are those of the first exemplar only.
struct GrowthExemplar {
  EmExemplar em;                                   // single-sample elements, neighbourhoods
  SimilaritySets sets;                             // co(e), k per element
  std::vector<double> radius;                      // bounding radius r_e per exemplar element
  std::vector<double> reach;                       // neighbourhood radius r̄_e per element
  std::vector<double> spacing;                     // its exemplar's mean nearest distance d̄
  std::vector<int> part;                           // its exemplar's index in the palette
  std::vector<double> part_density;                // per palette exemplar: elements per area
  std::vector<std::vector<FreeSpaceVector>> free;  // free(e)
  // With exact overlaps: per exemplar shape, its proxy (2D or 3D) and bounding-circle radius.
  bool exact = false;
  std::vector<geometry::Proxy2> proxy2;
  std::vector<geometry::Proxy3> proxy3;
  std::vector<double> shape_radius;

  double reach_of(int e) const { return reach[static_cast<std::size_t>(e)]; }
  double spacing_of(int e) const { return spacing[static_cast<std::size_t>(e)]; }
  std::size_t parts() const { return part_density.size(); }
};

class GrowthState {
 public:
  GrowthState(const GrowthExemplar& exemplar, const geometry::Domain& domain);

  std::size_t size() const { return position_.size(); }
  const Vec3& position(int e) const { return position_[static_cast<std::size_t>(e)]; }
  int source(int e) const { return source_[static_cast<std::size_t>(e)]; }
  int match(int e) const { return match_[static_cast<std::size_t>(e)]; }
  void set_match(int e, int m) { match_[static_cast<std::size_t>(e)] = m; }

  // Whether a bounding circle of `radius` at `p` lies where elements may be: anywhere on a torus,
  // else with its centre in the domain's box and mask.
  bool in_domain(const Vec3& p) const;
  // Whether the bounding circle of an element other than `skip` overlaps one of `radius` at `p`.
  bool overlaps(const Vec3& p, double radius, int skip = -1) const;
  // Whether a copy of exemplar element `source` at `p` would overlap an element other than
  // `skip`: bounding circles, or with exact overlaps the shapes' signed distance below 0
  // (touching is allowed), as `stats` counts overlapping pairs.
  bool collides(int source, const Vec3& p, int skip = -1) const;
  // Whether a free-space point overlaps a bounding circle of `radius` at `p` / lies within
  // `distance` of `p`.
  bool on_free_point(const Vec3& p, double radius) const;
  bool free_point_within(const Vec3& p, double distance) const;
  std::size_t free_points() const { return alive_; }
  double largest_radius() const { return largest_radius_; }

  // Adds an element copying exemplar element `source` at `p` (wrapped); returns its index.
  int add(int source, const Vec3& p);
  // Moves element e to `p` (wrapped) and makes its free-space points again.
  void move(int e, const Vec3& p);

  // Output elements within the neighbourhood radius of element e's source (itself excluded), as
  // the neighbourhood metric takes them.
  geometry::Neighbourhood neighbourhood(int e) const;
  // Indices of the elements within `distance` (at most the largest neighbourhood radius) of `p`.
  std::vector<int> elements_within(const Vec3& p, double distance) const;
  // How many elements lie within `distance` of p (elements_within's size, without the list),
  // counted up to `enough` at most.
  std::size_t count_within(const Vec3& p, double distance,
                           std::size_t enough = std::numeric_limits<std::size_t>::max()) const;

 private:
  struct FreePoint {
    Vec3 position;
    double radius;
    int owner;
    bool alive;
  };
  struct Nearby {
    Vec3 offset;
    double radius;
  };
  void add_free_points(int e);
  void consume_free_points(int e);
  void kill(std::size_t point);

  const GrowthExemplar& exemplar_;
  const geometry::Domain& domain_;
  double largest_radius_;
  double reach_;    // the largest neighbourhood radius, at least twice the largest bounding radius
  double contact_;  // the farthest two elements can be apart and still overlap
  std::vector<Vec3> position_;
  std::vector<int> source_, match_;
  std::vector<std::vector<int>> owned_;  // per element: its free-space points
  std::vector<FreePoint> points_;
  std::vector<int> unused_;   // slots of dead points, for new ones
  std::vector<Nearby> near_;  // add_free_points' scratch
  std::size_t alive_ = 0;
  // Elements by neighbourhood radius (neighbourhoods) and by contact distance (overlap tests,
  // which then visit a few elements, not a neighbourhood's worth); free-space points.
  geometry::NeighbourGrid elements_, contacts_, free_;
};

}  // namespace shapeproc::methods
