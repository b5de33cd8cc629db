#include "libshapeproc/fit/detail/cell_cuts.hpp"

#include <algorithm>
#include <cmath>

namespace shapeproc::fit {

int piece_axis(const PlaneNeighbour& n, const std::vector<PlaneCut>& cuts, std::uint64_t inside) {
  for (int c = n.first_cut; c < n.first_cut + n.cut_count; ++c) {
    const PlaneCut& cut = cuts[static_cast<std::size_t>(c)];
    if (cut.sector && holds(inside, c)) return cut.other_axis;
  }
  return n.axis;
}

double piece_distance(const PlaneNeighbour& n, const std::vector<PlaneCut>& cuts,
                      std::uint64_t inside, int axis) {
  double lower = -1.0, upper = -1.0;  // breakpoints of the piece's interval (-1: none)
  int m = 0, below = 0;
  for (int c = n.first_cut; c < n.first_cut + n.cut_count; ++c) {
    const PlaneCut& cut = cuts[static_cast<std::size_t>(c)];
    if (cut.sector || !holds(cut.axes, axis)) continue;
    ++m;
    if (holds(inside, c) == cut.inside_below) ++below;
  }
  if (m == 0) return n.distance;
  const int first_above = m - below;
  int k = 0;
  for (int c = n.first_cut; c < n.first_cut + n.cut_count; ++c) {
    const PlaneCut& cut = cuts[static_cast<std::size_t>(c)];
    if (cut.sector || !holds(cut.axes, axis)) continue;
    if (k == first_above - 1) lower = cut.breakpoint;
    if (k == first_above) upper = cut.breakpoint;
    ++k;
  }
  if (upper < 0) return std::max(n.distance, lower);
  if (lower < 0) return std::min(n.distance, std::nextafter(upper, 0.0));
  return 0.5 * (lower + upper);
}

}  // namespace shapeproc::fit
