// The relaxation of Ijiri et al. 2008 (§5.5, eq. 5): positions that bring every node's ring shape
// as close as they can to the one it wants,
//   min Σ_i Σ_(j ∈ w(i)) |x_j − (x_i + r_ji)|²,
// with fixed nodes held where they are (eq. 6).
//
// The paper solves the whole system in closed form after every growth step, which makes growth
// quadratic in the number of elements (its 1,000 elements take 5 s, mostly relaxing). We relax
// by Gauss–Seidel sweeps over the nodes near each growth step instead (each sweep sets a node to
// the minimiser of its own terms), and over every node once growth ends; far from the front
// nothing has changed, so the local sweeps lose little.
#pragma once

#include <functional>
#include <vector>

#include "libshapeproc/methods/ijiri2008/detail/growth_graph.hpp"

namespace shapeproc::methods {

// The nodes within `hops` edges of `centre`, itself included, live ones only.
std::vector<int> graph_neighbourhood(const GrowthGraph& graph, int centre, int hops);

// `sweeps` Gauss–Seidel sweeps of eq. 5 over `nodes`; a node stays put when it is fixed or when
// its new place would leave the domain (GrowthGraph::in_domain) or `allowed` (when given)
// refuses it. Returns the energy of the swept nodes' terms after the last sweep.
using MoveFilter = std::function<bool(int node, const Vec3& position)>;
double relax_rings(GrowthGraph& graph, const std::vector<int>& nodes, int sweeps,
                   const MoveFilter& allowed = {});

}  // namespace shapeproc::methods
