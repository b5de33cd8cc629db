#include "libshapeproc/methods/ma2011/em_initialisation.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <utility>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/geometry/neighbour_grid.hpp"
#include "libshapeproc/methods/common/neighbourhood_search.hpp"
#include "libshapeproc/methods/ma2011/detail/patch_copy.hpp"

namespace shapeproc::methods {

const char* to_string(Initialisation initialisation) {
  switch (initialisation) {
    case Initialisation::patch_copy:
      return "patch-copy";
    case Initialisation::random_copy:
      return "random-copy";
    case Initialisation::incremental_add:
      return "incremental-add";
  }
  return "?";
}

Initialisation parse_initialisation(const std::string& text) {
  for (Initialisation i :
       {Initialisation::patch_copy, Initialisation::random_copy, Initialisation::incremental_add}) {
    if (text == to_string(i)) return i;
  }
  throw core::ArgumentError(
      "neighbourhood EM",
      "initialisation: expected patch-copy, random-copy or incremental-add, got '" + text + "'");
}

void InitialOutput::add(const EmExemplar& exemplar, int source, const Vec3& position,
                        double radians) {
  output.add(exemplar, source, position, radians);
  const int first = exemplar.samples.first[static_cast<std::size_t>(source)];
  for (int k = 0; k < exemplar.samples.count_of(source); ++k) copied_from.push_back(first + k);
}

double smallest_gap(const EmExemplar& exemplar) {
  const geometry::Domain domain(exemplar.scene.window, exemplar.scene.dimension, exemplar.boundary);
  const geometry::NeighbourhoodIndex index(exemplar.scene.elements, domain, exemplar.radius);
  double gap = exemplar.spacing;
  for (std::size_t e = 0; e < exemplar.scene.elements.size(); ++e)
    for (const geometry::Neighbour& n : index.of(e)) gap = std::min(gap, n.offset.norm());
  return gap;
}

double expected_elements(const EmExemplar& exemplar, const geometry::Domain& domain) {
  double fraction = 1.0;
  if (domain.mask()) {
    const int n = 128;
    int in = 0;
    const Vec3 lo = domain.box().min(), size = domain.sizes();
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        in += inside(domain, lo + Vec3((i + 0.5) / n * size.x(), (j + 0.5) / n * size.y(), 0.0)) >=
              0.5;
    fraction = static_cast<double>(in) / (n * n);
  }
  return exemplar.density * domain.measure() * fraction;
}

namespace {

Vec3 random_inside(const geometry::Domain& domain, core::Random& random) {
  const Vec3 lo = domain.box().min(), size = domain.sizes();
  Vec3 p = lo;
  for (int tries = 0; tries < 100000; ++tries) {
    for (int a = 0; a < domain.dimension(); ++a) p[a] = lo[a] + random.uniform() * size[a];
    if (inside(domain, p) >= 0.5) return p;
  }
  throw core::ArgumentError("neighbourhood EM", "the domain has no inside to place elements in");
}

void random_copy(const EmExemplar& exemplar, const geometry::Domain& domain,
                 const OrientationField& orientation, core::Random& random, InitialOutput& out) {
  const auto count = static_cast<long long>(std::llround(expected_elements(exemplar, domain)));
  const std::size_t n = exemplar.scene.elements.size();
  for (long long i = 0; i < count; ++i) {
    const int source = static_cast<int>(random.index(n));
    const Vec3 p = random_inside(domain, random);
    out.add(exemplar, source, p, orientation.angle_at(p));
  }
}

void incremental_add(const EmExemplar& exemplar, const geometry::Domain& domain,
                     const OrientationField& orientation, core::Random& random,
                     InitialOutput& out) {
  const geometry::Domain exemplar_domain(exemplar.scene.window, exemplar.scene.dimension,
                                         exemplar.boundary);
  const geometry::NeighbourhoodIndex neighbours(exemplar.scene.elements, exemplar_domain,
                                                exemplar.radius);
  const double gap = std::max(0.5 * smallest_gap(exemplar), 1e-9 * exemplar.spacing);
  const auto cap = static_cast<std::size_t>(2.0 * expected_elements(exemplar, domain) + 1.0);
  geometry::NeighbourGrid grid(domain.box(), domain.dimension(), gap, domain.periodic());
  std::vector<Vec3> placed;
  auto free_at = [&](const Vec3& p) {
    bool free = true;
    grid.for_each_candidate(p, [&](int id) {
      free = free && domain.minimum_image(placed[static_cast<std::size_t>(id)] - p).norm() >= gap;
    });
    return free;
  };
  auto place = [&](int source, const Vec3& p) {
    out.add(exemplar, source, p, orientation.angle_at(p));
    grid.insert(static_cast<int>(placed.size()), p);
    placed.push_back(p);
  };
  Vec3 start = domain.box().center();
  if (inside(domain, start) < 0.5) start = random_inside(domain, random);
  place(static_cast<int>(random.index(exemplar.scene.elements.size())), start);
  std::vector<int> frontier = {0};
  while (!frontier.empty() && placed.size() < cap) {
    const std::size_t pick = random.index(frontier.size());
    const int element = frontier[pick];
    frontier[pick] = frontier.back();
    frontier.pop_back();
    const Vec3 from = placed[static_cast<std::size_t>(element)];
    const int source = out.output.source[static_cast<std::size_t>(element)];
    for (const geometry::Neighbour& n : neighbours.of(static_cast<std::size_t>(source))) {
      const Vec3 p = domain.wrap(from + orientation.turn(n.offset, from));
      if (inside(domain, p) < 0.5 || !free_at(p)) continue;
      place(n.element, p);
      frontier.push_back(static_cast<int>(placed.size()) - 1);
      if (placed.size() >= cap) break;
    }
  }
}

}  // namespace

InitialOutput initialise(const EmExemplar& exemplar, const geometry::Domain& domain,
                         const OrientationField& orientation, Initialisation rule, double alpha,
                         core::Random& random, bool diverse) {
  InitialOutput out;
  switch (rule) {
    case Initialisation::patch_copy:
      patch_copy(exemplar, domain, orientation, alpha, random, out, diverse);
      break;
    case Initialisation::random_copy:
      random_copy(exemplar, domain, orientation, random, out);
      break;
    case Initialisation::incremental_add:
      incremental_add(exemplar, domain, orientation, random, out);
      break;
  }
  if (out.output.samples.first.empty()) out.output.samples.first.push_back(0);
  return out;
}

}  // namespace shapeproc::methods
