#include "libshapeproc/fit/anchored_quadrature.hpp"

#include <algorithm>
#include <cmath>

#include "libshapeproc/core/random.hpp"
#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/geometry/neighbour_grid.hpp"

namespace shapeproc::fit {

namespace {

constexpr std::uint64_t kSeed = 0x5eed'a9c4;
constexpr double kPi = 3.14159265358979323846;

using geometry::Element;
using geometry::Vec3;

struct Disc {
  Vec3 centre;
  double radius;
};

// The statistic t(ξ | exemplar) of a candidate point, or false where λ is 0 (a hard core, or off
// every base).
bool point_counts(const Element& xi, const std::vector<Element>& data,
                  const geometry::NeighbourGrid& grid, double reach,
                  const geometry::PairMeasurer& measurer, const model::Interaction& interaction,
                  model::InteractionCounts& counts) {
  counts = {};
  bool allowed = true;
  grid.for_each_candidate_within(xi.position, reach, [&](int j) {
    if (!allowed) return;
    const Element& other = data[static_cast<std::size_t>(j)];
    const model::PairEffect effect = model::pair_effect(interaction, measurer, xi, other);
    if (effect.band == model::Interaction::kHardCore) allowed = false;
    if (effect.band >= 0)
      counts.add(interaction.parameter(xi.category, other.category, effect.axis, effect.band));
  });
  return allowed && interaction.anchored(xi.category, counts.counts);
}

}  // namespace

std::vector<QuadraturePoint> anchored_quadrature(const geometry::Scene& exemplar,
                                                 const FitRegion& region,
                                                 const geometry::PairMeasurer& measurer,
                                                 const model::Interaction& interaction,
                                                 const std::vector<std::vector<int>>& shapes_of,
                                                 const geometry::Domain& window, int per_base) {
  const bool periodic = window.periodic();
  std::vector<QuadraturePoint> out;
  if (exemplar.dimension != 2) return out;
  double max_radius = 0.0;
  for (std::size_t s = 0; s < exemplar.shapes.size(); ++s)
    max_radius = std::max(max_radius, measurer.radius(static_cast<int>(s)));
  const double reach = interaction.range() + 2 * max_radius;
  geometry::NeighbourGrid grid(exemplar.window, 2, std::max(reach, 1e-12), periodic);
  for (std::size_t k = 0; k < exemplar.elements.size(); ++k)
    grid.insert(static_cast<int>(k), exemplar.elements[k].position);
  const Vec3& period = window.period();
  core::Random random(kSeed);
  for (int c = 0; c < interaction.category_count(); ++c) {
    const int anchor = interaction.anchor(c);
    const std::vector<int>& shapes = shapes_of[static_cast<std::size_t>(c)];
    if (anchor < 0 || shapes.empty()) continue;
    double own = 0.0;
    for (int s : shapes) own = std::max(own, measurer.radius(s));
    std::vector<Disc> discs;
    for (const Element& base : exemplar.elements)
      if (base.category == anchor)
        discs.push_back({base.position, measurer.radius(base.shape) + own +
                                            std::max(0.0, interaction.anchor_reach(c))});
    std::size_t next_shape = 0;
    for (const Disc& disc : discs) {
      const double weight = kPi * disc.radius * disc.radius / per_base;
      for (int n = 0; n < per_base; ++n) {
        // Uniform in the disc.
        const double r = disc.radius * std::sqrt(random.uniform());
        const double angle = 2 * kPi * random.uniform();
        Element xi;
        xi.category = c;
        xi.shape = shapes[next_shape++ % shapes.size()];
        xi.position = disc.centre + Vec3(r * std::cos(angle), r * std::sin(angle), 0.0);
        if (periodic) xi.position = window.wrap(xi.position);
        if (!region.contains(xi.position) || !exemplar.window.contains(xi.position)) continue;
        int covering = 0;
        for (const Disc& other : discs)
          covering +=
              geometry::minimum_image(xi.position - other.centre, period).norm() < other.radius;
        QuadraturePoint q;
        model::InteractionCounts counts;
        if (covering == 0 ||
            !point_counts(xi, exemplar.elements, grid, reach, measurer, interaction, counts))
          continue;
        q.weight = weight / covering;
        q.category = c;
        q.counts = std::move(counts.counts);
        out.push_back(std::move(q));
      }
    }
  }
  return out;
}

}  // namespace shapeproc::fit
