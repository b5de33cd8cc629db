// Saturated bands (docs/mathematics.md, "Saturation"; Geyer 1999): a band with saturation s
// contributes γ^{S(x)} to the density, with S(x) = Σ_i min(s, t_i(x)) over the elements of its
// pair's categories and t_i(x) the neighbours of x_i in the band. The statistic that enters the
// conditional intensity of ξ is then the change ξ makes to S:
//   S(x ∪ ξ) − S(x) = min(s, t(ξ, x)) + #{neighbours x_j of ξ in the band : t_j(x) < s},
// its own count capped, plus one for each neighbour that had room. Without saturation (s = ∞)
// every pair counts twice, so a saturated band's γ is per element and neighbour, a pairwise
// band's per pair.
#pragma once

#include <algorithm>
#include <utility>
#include <vector>

#include "libshapeproc/model/interaction.hpp"

namespace shapeproc::model {

// The change of a saturated band's S when an element with `own` neighbours in it joins, of which
// `with_room` had fewer than s.
inline int saturated_change(int saturation, int own, int with_room) {
  return std::min(saturation, own) + with_room;
}

// t(ξ, x) from ξ's neighbours in range, each as (neighbour index, θ index of its band):
// pairwise bands count their neighbours, saturated ones the change above, with
// `neighbour_count(j, parameter)` the neighbour's own count t_j(x) in that band (ξ not among x).
template <class NeighbourCount>
InteractionCounts saturated_counts(const Interaction& interaction,
                                   const std::vector<std::pair<int, int>>& neighbours,
                                   NeighbourCount&& neighbour_count) {
  InteractionCounts counts;
  std::vector<std::pair<int, int>> saturated;  // (θ index, neighbour)
  for (const auto& [j, parameter] : neighbours) {
    if (interaction.saturation(parameter) > 0)
      saturated.emplace_back(parameter, j);
    else
      counts.add(parameter);
  }
  std::sort(saturated.begin(), saturated.end());
  for (std::size_t begin = 0; begin < saturated.size();) {
    const int parameter = saturated[begin].first;
    const int s = interaction.saturation(parameter);
    std::size_t end = begin;
    int with_room = 0;
    for (; end < saturated.size() && saturated[end].first == parameter; ++end)
      with_room += neighbour_count(saturated[end].second, parameter) < s;
    counts.add(parameter, saturated_change(s, static_cast<int>(end - begin), with_room));
    begin = end;
  }
  return counts;
}

}  // namespace shapeproc::model
