// One growth step of seed-and-grow (Ijiri et al. 2008, §5.1–5.4; seed_and_grow.hpp says what
// each step does): the state of one chain (its graph, queue of seeds and counters) and the
// steps that change it.
#pragma once

#include <algorithm>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <utility>
#include <vector>

#include "libshapeproc/geometry/proxy.hpp"
#include "libshapeproc/methods/ijiri2008/detail/growth_graph.hpp"
#include "libshapeproc/methods/ijiri2008/detail/ring_relaxation.hpp"
#include "libshapeproc/methods/ijiri2008/seed_and_grow.hpp"

namespace shapeproc::methods {

// What the heuristics did, for the run's summary.
struct Counters {
  long long steps = 0, merged = 0, angle = 0, crossing = 0, outside = 0, extra = 0, dropped = 0;
};

// The growing arrangement and what one chain needs.
struct Growth {
  const SeedGrowthExemplar& exemplar;
  const SeedGrowthOptions& options;
  GrowthGraph graph;
  MatchWeights weights;
  double l_short = 0.0, neighbourhood = 0.0;
  std::vector<int> symbol_priority;  // per symbol
  int lowest_priority = 0;
  std::vector<Vec3> origins;  // the initial seeds
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  Counters counters;
  long long elements = 0;
  // With exact overlaps: proxies per (shape, turn step), made when first needed.
  std::map<std::pair<int, long>, geometry::Proxy2> proxies;
  double largest_radius = 0.0;  // of the shapes' bounding circles
  double largest_circle = 0.0;  // of the elements' circles of the circle overlap test

  int priority(int node) const {
    const int s = graph.node(node).symbol;
    return s < 0 || symbol_priority.empty() ? lowest_priority
                                            : symbol_priority[static_cast<std::size_t>(s)];
  }
  void push_seed(int node) {
    double key = std::numeric_limits<double>::infinity();
    for (const Vec3& o : origins)
      key = std::min(key, graph.domain().minimum_image(graph.node(node).position - o).norm());
    queue.emplace(key, node);
  }
};

// Step 1: the next seed to grow, nearest the origins, or a seed of higher priority near it; -1
// when none is left.
int next_seed(Growth& g);

// Steps 2 and 3 at seed s: match, copy, overlay the ring, join it, relax around it. False when
// the seed had nothing to match and was dropped.
bool grow(Growth& g, int s, core::Random& random);

// With exact overlaps, what the relaxation may not do: move an element onto another.
MoveFilter move_filter(Growth& g);

}  // namespace shapeproc::methods
