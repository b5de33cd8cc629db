#include "libshapeproc/metrics/neighbourhood_distance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace shapeproc::metrics {

using geometry::Vec3;

namespace {

struct Neighbour {
  Vec3 offset;
  int category;  // in the exemplar's numbering (-1: absent from the exemplar)
};

Vec3 offset_between(const geometry::Scene& scene, bool periodic, const Vec3& from, const Vec3& to) {
  Vec3 t = to - from;
  if (periodic) {
    const Vec3 period = scene.window.sizes();
    for (int k = 0; k < scene.dimension; ++k) {
      if (period[k] > 0) t[k] -= period[k] * std::round(t[k] / period[k]);
    }
  }
  return t;
}

// The other elements within `radius` of element `centre`, as offsets.
std::vector<Neighbour> neighbourhood(const geometry::Scene& scene, bool periodic, std::size_t centre, double radius,
                                     const std::vector<int>& category_map) {
  std::vector<Neighbour> out;
  const Vec3& p = scene.elements[centre].position;
  for (std::size_t j = 0; j < scene.elements.size(); ++j) {
    if (j == centre) continue;
    const Vec3 t = offset_between(scene, periodic, p, scene.elements[j].position);
    if (t.norm() < radius) out.push_back({t, category_map[static_cast<std::size_t>(scene.elements[j].category)]});
  }
  return out;
}

// Ma et al.'s greedy pairing: the closest remaining (o', e') pair of one category first; pairs at
// r or farther are not formed and each o' without a partner costs r².
double neighbourhood_distance(const std::vector<Neighbour>& output, const std::vector<Neighbour>& exemplar,
                              double radius) {
  const double cap = radius * radius;
  std::vector<std::tuple<double, int, int>> candidates;
  for (std::size_t a = 0; a < output.size(); ++a) {
    for (std::size_t b = 0; b < exemplar.size(); ++b) {
      if (output[a].category != exemplar[b].category || output[a].category < 0) continue;
      const double c = (output[a].offset - exemplar[b].offset).squaredNorm();
      if (c < cap) candidates.emplace_back(c, static_cast<int>(a), static_cast<int>(b));
    }
  }
  std::sort(candidates.begin(), candidates.end());
  std::vector<bool> used_output(output.size(), false), used_exemplar(exemplar.size(), false);
  double sum = 0.0;
  std::size_t paired = 0;
  for (const auto& [c, a, b] : candidates) {
    if (used_output[a] || used_exemplar[b]) continue;
    used_output[a] = used_exemplar[b] = true;
    sum += c;
    if (++paired == output.size()) break;
  }
  return sum + static_cast<double>(output.size() - paired) * cap;
}

double inner_distance(const geometry::Scene& scene, const Vec3& p) {
  double b = std::numeric_limits<double>::infinity();
  for (int k = 0; k < scene.dimension; ++k) {
    b = std::min({b, p[k] - scene.window.min()[k], scene.window.max()[k] - p[k]});
  }
  return b;
}

}  // namespace

NeighbourhoodDistance average_neighbourhood_distance(const geometry::Scene& output, bool output_periodic,
                                                     const geometry::Scene& exemplar, bool exemplar_periodic,
                                                     double radius) {
  if (output.elements.empty() || exemplar.elements.empty()) throw std::invalid_argument("a scene has no elements");
  if (output.dimension != exemplar.dimension) throw std::invalid_argument("the scenes' dimensions differ");
  const int dim = exemplar.dimension;
  const double spacing = std::pow(exemplar.window_measure() / static_cast<double>(exemplar.elements.size()), 1.0 / dim);
  NeighbourhoodDistance result;
  result.radius = radius > 0 ? radius : 2.0 * spacing;
  const double r = result.radius;

  // Categories are matched by name; the exemplar's numbering is the common one.
  std::vector<int> exemplar_map(exemplar.categories.size());
  for (std::size_t c = 0; c < exemplar_map.size(); ++c) exemplar_map[c] = static_cast<int>(c);
  std::vector<int> output_map(output.categories.size(), -1);
  for (std::size_t c = 0; c < output.categories.size(); ++c) {
    for (std::size_t e = 0; e < exemplar.categories.size(); ++e) {
      if (output.categories[c].name == exemplar.categories[e].name) output_map[c] = static_cast<int>(e);
    }
  }

  // Every exemplar element is a candidate centre: a neighbourhood cut by the exemplar's edge only
  // matches worse, and the minimum passes over it.
  std::vector<std::vector<std::vector<Neighbour>>> exemplar_hoods(exemplar.categories.size());
  for (std::size_t e = 0; e < exemplar.elements.size(); ++e) {
    exemplar_hoods[static_cast<std::size_t>(exemplar.elements[e].category)].push_back(
        neighbourhood(exemplar, exemplar_periodic, e, 2.0 * r, exemplar_map));
  }
  result.exemplar_centres = static_cast<int>(exemplar.elements.size());

  // Output centres whose neighbourhood an open window cuts are left out, unless that is all of them.
  std::vector<std::size_t> centres;
  for (std::size_t o = 0; o < output.elements.size(); ++o) {
    if (output_periodic || inner_distance(output, output.elements[o].position) >= r) centres.push_back(o);
  }
  if (centres.empty()) {
    for (std::size_t o = 0; o < output.elements.size(); ++o) centres.push_back(o);
  }

  double total = 0.0, neighbours = 0.0;
  for (const std::size_t o : centres) {
    const std::vector<Neighbour> hood = neighbourhood(output, output_periodic, o, r, output_map);
    neighbours += static_cast<double>(hood.size());
    double best = static_cast<double>(hood.size()) * r * r;  // no exemplar neighbourhood at all
    const int category = output_map[static_cast<std::size_t>(output.elements[o].category)];
    if (category >= 0) {
      for (const std::vector<Neighbour>& candidate : exemplar_hoods[static_cast<std::size_t>(category)]) {
        best = std::min(best, neighbourhood_distance(hood, candidate, r));
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
