#include "libshapeproc/fit/anchored_quadrature.hpp"

#include <algorithm>
#include <cmath>

#include "libshapeproc/core/random.hpp"
#include "libshapeproc/geometry/domain.hpp"

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

}  // namespace

std::vector<QuadraturePoint> anchored_quadrature(const geometry::Scene& exemplar,
                                                 const FitRegion& region,
                                                 const geometry::PairMeasurer& measurer,
                                                 const model::Interaction& interaction,
                                                 const std::vector<std::vector<int>>& shapes_of,
                                                 const geometry::Domain& window,
                                                 const PointCounter& counter, int per_base) {
  const bool periodic = window.periodic();
  std::vector<QuadraturePoint> out;
  if (exemplar.dimension != 2) return out;
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
        if (covering == 0 || !counter.counts(xi, counts)) continue;
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
