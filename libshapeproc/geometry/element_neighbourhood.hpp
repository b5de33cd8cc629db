// Element neighbourhoods and their distance, as Ma et al. 2011 define them (§4, eq. 1): the one
// definition the neighbourhood metric (Davison et al. 2018, eq. 5) and the neighbourhood-EM
// synthesis method share.
//
// The neighbourhood n(e) of an element e holds the other elements whose reference positions lie
// within the radius r of e's (minimum image on a torus), as offsets p(e') − p(e). The distance of
// an output neighbourhood n(o) to an exemplar neighbourhood n(e) is
//     |n(o) − n(e)| = Σ_{o' ∈ n(o)} min(|p̂(o') − p̂(e')|², r²),
// where o' is paired with an exemplar element e' of the same category by Ma's greedy rule (the
// closest remaining pair first); an o' left without a partner closer than r costs r².
#pragma once

#include <utility>
#include <vector>

#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/geometry/neighbour_grid.hpp"
#include "libshapeproc/geometry/scene.hpp"

namespace shapeproc::geometry {

struct Neighbour {
  Vec3 offset;   // p(e') − p(e), minimum image on a torus
  int category;  // in the caller's common numbering (-1: absent from the other scene)
  int element;   // index of e' in its scene
};
using Neighbourhood = std::vector<Neighbour>;

// The neighbourhoods of a set of elements, found through a grid (each query visits the cells
// around the centre, not every element).
class NeighbourhoodIndex {
 public:
  // `category_map` renumbers the elements' categories (empty: unchanged).
  NeighbourhoodIndex(const std::vector<Element>& elements, const Domain& domain, double radius,
                     std::vector<int> category_map = {});

  // The elements within the radius of element `centre` (itself excluded), in element order.
  Neighbourhood of(std::size_t centre) const;
  // The elements within the radius of `position`, except `skip` (-1: none), in element order.
  Neighbourhood around(const Vec3& position, int skip = -1) const;

  double radius() const { return radius_; }

 private:
  const std::vector<Element>& elements_;
  const Domain& domain_;
  double radius_;
  std::vector<int> category_map_;
  NeighbourGrid grid_;
};

// The greedy pairing of Ma et al.: (index in `output`, index in `exemplar`) pairs of one category,
// closest first, each element used once, none at r or farther.
std::vector<std::pair<int, int>> match_neighbourhoods(const Neighbourhood& output,
                                                      const Neighbourhood& exemplar, double radius);

// |n(o) − n(e)| of eq. 1, with the greedy pairing.
double neighbourhood_distance(const Neighbourhood& output, const Neighbourhood& exemplar,
                              double radius);

}  // namespace shapeproc::geometry
