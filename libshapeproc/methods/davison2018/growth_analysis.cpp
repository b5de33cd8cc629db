#include "libshapeproc/methods/davison2018/growth_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/methods/davison2018/detail/growth_palette.hpp"
#include "libshapeproc/metrics/novelty.hpp"

namespace shapeproc::methods {

namespace {

void check_options(const GrowthOptions& o) {
  if (!(o.rings > 0 && o.rings <= 10))
    throw core::ArgumentError("region growing", "rings: expected rings in (0, 10]");
  if (o.k < 1 || o.k > 100) throw core::ArgumentError("region growing", "k: expected 1 to 100");
  if (!(o.alpha >= 0))
    throw core::ArgumentError("region growing", "alpha: the weight must be >= 0");
  if (!(o.ratio > 1.0)) throw core::ArgumentError("region growing", "ratio: the ratio must be > 1");
  if (!(o.patch_radius >= 0))
    throw core::ArgumentError("region growing", "patch_radius: the patch radius must be >= 0");
  if (!(o.seed_separation > 0 && o.seed_separation <= 1))
    throw core::ArgumentError("region growing", "the seed separation must be in (0, 1]");
  if (!(o.bounding_radius >= 0))
    throw core::ArgumentError("region growing", "bounding_radius: expected a radius >= 0");
}

// Half of each exemplar element's nearest distance (its shape's bounding circle when it has no
// neighbour within the neighbourhood radius), so that the exemplar itself has no overlap.
std::vector<double> bounding_radii(const EmExemplar& em, double fixed) {
  std::vector<double> out;
  for (std::size_t s = 0; s < em.samples.size(); ++s) {
    if (fixed > 0.0) {
      out.push_back(fixed);
      continue;
    }
    double r = std::numeric_limits<double>::infinity();
    for (const geometry::Neighbour& n : em.near[s]) r = std::min(r, 0.5 * n.offset.norm());
    if (!std::isfinite(r)) {
      const geometry::Element& e =
          em.scene.elements[static_cast<std::size_t>(em.samples.element[s])];
      r = 0.5 *
          geometry::bounding_box(em.scene.shapes[static_cast<std::size_t>(e.shape)]).sizes().norm();
    }
    out.push_back(std::max(r, 1e-9 * em.spacing));
  }
  return out;
}

}  // namespace

GrowthExemplar analyse_growth_exemplar(const geometry::Scene& exemplar, geometry::Boundary boundary,
                                       const GrowthOptions& options) {
  check_options(options);
  GrowthExemplar g;
  SampleOptions samples;
  samples.per_element = 1;
  g.em = analyse_exemplar(exemplar, boundary, options.rings, samples);
  const double unit = g.em.spacing * g.em.spacing;
  g.sets = build_similarity_sets(g.em, options.k, options.alpha * unit);
  g.radius = bounding_radii(g.em, options.bounding_radius);
  g.free = free_space_vectors(g.em, g.sets, g.radius, options.cluster_eps * g.em.spacing,
                              std::min(options.cluster_min_points, options.k));
  // (Not value_or: its argument, the lattice test, would run even when the option decides.)
  g.exact =
      options.exact_overlap ? *options.exact_overlap : !metrics::is_lattice_exemplar(exemplar);
  geometry::ProxyOptions proxy;
  proxy.tolerance = geometry::kOutlineTolerance;  // as `stats` judges collisions
  for (const geometry::Shape& shape : g.em.scene.shapes) {
    g.shape_radius.push_back(0.5 * geometry::bounding_box(shape).sizes().norm());
    if (!g.exact) continue;
    if (g.em.scene.dimension == 3)
      g.proxy3.push_back(geometry::make_proxy3(shape, proxy));
    else
      g.proxy2.push_back(geometry::make_proxy2(shape, proxy));
  }
  if (!g.exact) g.shape_radius.assign(g.shape_radius.size(), 0.0);
  g.reach.assign(g.em.samples.size(), g.em.radius);
  g.spacing.assign(g.em.samples.size(), g.em.spacing);
  g.part.assign(g.em.samples.size(), 0);
  g.part_density = {g.em.density};
  return g;
}

GrowthExemplar analyse_growth_palette(const std::vector<GrowthSource>& sources,
                                      const GrowthOptions& options, int dimension) {
  if (sources.empty()) throw core::ArgumentError("region growing", "no exemplar to grow from");
  GrowthOptions shared = options;
  if (!shared.exact_overlap) {
    shared.exact_overlap = std::any_of(sources.begin(), sources.end(), [](const GrowthSource& s) {
      return !metrics::is_lattice_exemplar(s.scene);
    });
  }
  std::vector<GrowthExemplar> parts;
  for (const GrowthSource& source : sources) {
    if (source.scene.dimension != dimension)
      throw core::ArgumentError("region growing",
                                "an exemplar is " + std::to_string(source.scene.dimension) +
                                    "D but the domain is " + std::to_string(dimension) + "D");
    GrowthOptions own = shared;
    if (source.rings > 0) own.rings = source.rings;
    if (source.bounding_radius >= 0) own.bounding_radius = source.bounding_radius;
    parts.push_back(analyse_growth_exemplar(source.scene, source.boundary, own));
  }
  return parts.size() == 1 ? std::move(parts.front()) : merge_palette(std::move(parts));
}

}  // namespace shapeproc::methods
