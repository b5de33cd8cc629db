// Element neighbourhoods and their distance, as Ma et al. 2011 define them (§3.2, eq. 1): the one
// definition the neighbourhood metric (Davison et al. 2018, eq. 5) and the neighbourhood-EM
// synthesis method (compare/neighbourhood_em) share.
//
// The neighbourhood n(s) of an element or sample s holds the others whose positions lie within
// the radius r of s's (minimum image on a torus), as offsets p(s') − p(s). Each carries a key
// (what a partner must share: the metric's category, the EM's sample id) and an attribute q (the
// EM's category and shape class). The distance of an output neighbourhood n(o) to an exemplar
// neighbourhood n(e) is
//     |n(o) − n(e)| = Σ_{o' ∈ n(o)} min(|p̂(o') − p̂(e')|² + α [q(o') ≠ q(e')], r²),
// where o' is paired with an exemplar e' of the same key by Ma's greedy rule (the closest
// remaining pair first, by position); an o' left without a partner closer than r costs r².
// The cap makes a neighbourhood of radius 2r on the exemplar side as good as Ma's unbounded one.
#pragma once

#include <utility>
#include <vector>

#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/geometry/neighbour_grid.hpp"
#include "libshapeproc/geometry/scene.hpp"

namespace shapeproc::geometry {

struct Neighbour {
  Vec3 offset;        // p(e') − p(e), minimum image on a torus
  int key;            // partners share it (-1: pairs with nothing)
  int element;        // index of e' among the index's positions
  int attribute = 0;  // q(e'): pairs whose attributes differ cost α more
};
using Neighbourhood = std::vector<Neighbour>;

// The neighbourhoods of a set of elements, found through a grid (each query visits the cells
// around the centre, not every element).
class NeighbourhoodIndex {
 public:
  // Keys are the elements' categories, renumbered by `category_map` (empty: unchanged).
  NeighbourhoodIndex(const std::vector<Element>& elements, const Domain& domain, double radius,
                     const std::vector<int>& category_map = {});
  // Any points with their keys and attributes (empty: all 0).
  NeighbourhoodIndex(std::vector<Vec3> positions, std::vector<int> keys,
                     std::vector<int> attributes, const Domain& domain, double radius);

  // The points within the radius of point `centre` (itself excluded), in index order.
  Neighbourhood of(std::size_t centre) const;
  // The points within the radius of `position`, except `skip` (-1: none), in index order.
  Neighbourhood around(const Vec3& position, int skip = -1) const;

  double radius() const { return radius_; }

 private:
  std::vector<Vec3> positions_;
  std::vector<int> keys_, attributes_;
  const Domain& domain_;
  double radius_;
  NeighbourGrid grid_;
};

// The greedy pairing of Ma et al.: (index in `output`, index in `exemplar`) pairs of one key,
// closest first, each used once, none at r or farther.
std::vector<std::pair<int, int>> match_neighbourhoods(const Neighbourhood& output,
                                                      const Neighbourhood& exemplar, double radius);

// |n(o) − n(e)| of eq. 1, with the greedy pairing and attribute weight `alpha`.
double neighbourhood_distance(const Neighbourhood& output, const Neighbourhood& exemplar,
                              double radius, double alpha = 0.0);

// The cost of one pair of eq. 1: min(|Δp̂|² + α [q ≠ q'], r²).
inline double pair_cost(const Neighbour& output, const Neighbour& exemplar, double radius,
                        double alpha) {
  const double c = (output.offset - exemplar.offset).squaredNorm() +
                   (output.attribute != exemplar.attribute ? alpha : 0.0);
  return c < radius * radius ? c : radius * radius;
}

}  // namespace shapeproc::geometry
