#include "libshapeproc/metrics/neighbourhood_distance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/geometry/element_neighbourhood.hpp"
#include "libshapeproc/geometry/tile_repeat.hpp"

namespace shapeproc::metrics {

using geometry::Vec3;

namespace {

// A scene's window as a domain, torus or open.
geometry::Domain scene_domain(const geometry::Scene& scene, geometry::Boundary boundary) {
  return geometry::Domain(scene.window, scene.dimension, boundary);
}

double inner_distance(const geometry::Scene& scene, const Vec3& p) {
  double b = std::numeric_limits<double>::infinity();
  for (int k = 0; k < scene.dimension; ++k) {
    b = std::min({b, p[k] - scene.window.min()[k], scene.window.max()[k] - p[k]});
  }
  return b;
}

}  // namespace

NeighbourhoodDistance average_neighbourhood_distance(const geometry::Scene& output,
                                                     geometry::Boundary output_boundary,
                                                     const geometry::Scene& tile,
                                                     geometry::Boundary exemplar_boundary,
                                                     double radius) {
  const geometry::Scene& exemplar = tile;
  if (output.elements.empty() || exemplar.elements.empty())
    throw core::ArgumentError("neighbourhood distance", "a scene has no elements");
  if (output.dimension != exemplar.dimension)
    throw core::ArgumentError("neighbourhood distance", "the scenes' dimensions differ");
  const int dim = exemplar.dimension;
  const double spacing = std::pow(
      exemplar.window_measure() / static_cast<double>(exemplar.elements.size()), 1.0 / dim);
  NeighbourhoodDistance result;
  result.radius = radius > 0 ? radius : 2.0 * spacing;
  const double r = result.radius;
  // A periodic exemplar smaller than its neighbourhoods' diameter (4r) is repeated, so that the
  // nearest image does not hide an element's further images.
  const geometry::Scene repeated = exemplar_boundary == geometry::Boundary::torus
                                       ? geometry::repeat_to_reach(tile, 4.0 * r)
                                       : geometry::Scene{};
  const geometry::Scene& exemplar_scene =
      exemplar_boundary == geometry::Boundary::torus ? repeated : tile;

  // Categories are matched by name; the exemplar's numbering is the common one.
  std::vector<int> exemplar_map(exemplar.categories.size());
  for (std::size_t c = 0; c < exemplar_map.size(); ++c) exemplar_map[c] = static_cast<int>(c);
  std::vector<int> output_map(output.categories.size(), -1);
  for (std::size_t c = 0; c < output.categories.size(); ++c) {
    for (std::size_t e = 0; e < exemplar.categories.size(); ++e) {
      if (output.categories[c].name == exemplar.categories[e].name)
        output_map[c] = static_cast<int>(e);
    }
  }

  // Every exemplar element is a candidate centre: a neighbourhood cut by the exemplar's edge only
  // matches worse, and the minimum passes over it.
  const geometry::Domain exemplar_domain = scene_domain(exemplar_scene, exemplar_boundary);
  const geometry::NeighbourhoodIndex exemplar_index(exemplar_scene.elements, exemplar_domain,
                                                    2.0 * r, exemplar_map);
  std::vector<std::vector<geometry::Neighbourhood>> exemplar_hoods(exemplar.categories.size());
  for (std::size_t e = 0; e < exemplar_scene.elements.size(); ++e) {
    exemplar_hoods[static_cast<std::size_t>(exemplar_scene.elements[e].category)].push_back(
        exemplar_index.of(e));
  }
  result.exemplar_centres = static_cast<int>(exemplar_scene.elements.size());

  // Output centres whose neighbourhood an open window cuts are left out, unless that is all of
  // them.
  std::vector<std::size_t> centres;
  for (std::size_t o = 0; o < output.elements.size(); ++o) {
    if (output_boundary == geometry::Boundary::torus ||
        inner_distance(output, output.elements[o].position) >= r)
      centres.push_back(o);
  }
  if (centres.empty()) {
    for (std::size_t o = 0; o < output.elements.size(); ++o) centres.push_back(o);
  }

  const geometry::Domain output_domain = scene_domain(output, output_boundary);
  const geometry::NeighbourhoodIndex output_index(output.elements, output_domain, r, output_map);
  double total = 0.0, neighbours = 0.0;
  for (const std::size_t o : centres) {
    const geometry::Neighbourhood hood = output_index.of(o);
    neighbours += static_cast<double>(hood.size());
    double best = static_cast<double>(hood.size()) * r * r;  // no exemplar neighbourhood at all
    const int category = output_map[static_cast<std::size_t>(output.elements[o].category)];
    if (category >= 0) {
      for (const geometry::Neighbourhood& candidate :
           exemplar_hoods[static_cast<std::size_t>(category)]) {
        best = std::min(best, geometry::neighbourhood_distance(hood, candidate, r));
        if (best == 0.0) break;
      }
    }
    total += best;
  }
  result.output_centres = static_cast<int>(centres.size());
  result.mean = total / static_cast<double>(centres.size());
  result.normalised = result.mean / (spacing * spacing);
  result.mean_neighbours = neighbours / static_cast<double>(centres.size());
  return result;
}

}  // namespace shapeproc::metrics
