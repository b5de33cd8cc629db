#include "libshapeproc/report/metrics_json.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

namespace shapeproc::report {

namespace {

// A number, or null where it is not finite (JSON has no infinities).
nlohmann::json number(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

// A distribution's CDF at `points` distances from 0 to `range`, its sample count and mean.
nlohmann::json cdf_json(const metrics::Distribution& d, double range, int points = 33) {
  nlohmann::json r = nlohmann::json::array(), f = nlohmann::json::array();
  for (int k = 0; k < points; ++k) {
    const double x = range * k / (points - 1);
    r.push_back(x);
    f.push_back(d.empty() ? nlohmann::json(nullptr) : nlohmann::json(d.cdf(x)));
  }
  return {{"r", r}, {"F", f}, {"samples", d.samples}, {"mean", number(d.mean())}};
}

nlohmann::json novelty_json(const metrics::Novelty& n) {
  auto measures = [](const metrics::CopyMeasures& m) {
    return nlohmann::json{{"copy", m.copy},
                          {"patch", m.patch},
                          {"largest_patch", m.largest_patch},
                          {"repetition", m.repetition}};
  };
  return {{"tolerance", n.tolerance},
          {"output", measures(n.output)},
          {"chance", measures(n.chance)},
          {"lattice_exemplar", n.lattice_exemplar},
          {"repeats_exemplar", n.repeats_exemplar}};
}

const char* boundary_name(evaluation::BoundaryChoice b) {
  return b == evaluation::BoundaryChoice::torus  ? "torus"
         : b == evaluation::BoundaryChoice::open ? "open"
                                                 : "auto";
}

const char* edge_name(metrics::EdgeTreatment e) {
  return e == metrics::EdgeTreatment::border ? "border"
         : e == metrics::EdgeTreatment::none ? "none"
                                             : "auto";
}

}  // namespace

nlohmann::json evaluation_json(const evaluation::EvaluatedScene& scene,
                               const evaluation::Evaluation& e) {
  const metrics::SceneStatistics& s = e.statistics;
  nlohmann::json categories = nlohmann::json::array();
  for (std::size_t c = 0; c < s.categories.size(); ++c) {
    nlohmann::json entry = {
        {"name", s.categories[c]}, {"count", s.counts[c]}, {"intensity", s.intensity[c]}};
    if (e.comparison) entry["intensity_ratio"] = number(e.comparison->intensity_ratio[c]);
    if (!s.relations.empty()) {
      entry["nested"] = s.relations.nested[c];
      entry["overlapping"] = s.relations.overlapping[c];
    }
    categories.push_back(entry);
  }
  auto directional = [&](const metrics::DirectionalStatistics& d,
                         const metrics::DistributionDistances* w) {
    nlohmann::json j = {{"neighbours", d.neighbours},
                        {"nearest", cdf_json(d.nearest, s.range)},
                        {"pairs", cdf_json(d.pairs, s.range)}};
    if (w) j["w1"] = {{"nearest", number(w->nearest)}, {"pairs", number(w->pairs)}};
    return j;
  };
  nlohmann::json axes = nlohmann::json::array();
  for (std::size_t k = 0; k < s.axes.size(); ++k) {
    nlohmann::json a = directional(s.axes[k], e.comparison ? &e.comparison->axes[k] : nullptr);
    const geometry::Vec3& v = s.axes[k].direction;
    a["direction"] =
        s.dimension == 2 ? nlohmann::json{v.x(), v.y()} : nlohmann::json{v.x(), v.y(), v.z()};
    axes.push_back(a);
  }
  nlohmann::json correlation = {{"r", s.correlation_r}, {"g", nlohmann::json::array()}};
  for (double g : s.correlation) correlation["g"].push_back(number(g));
  nlohmann::json collisions = {
      {"pairs", s.collisions.pairs.size()},
      {"elements", s.collisions.elements},
      {"fraction",
       s.elements() > 0 ? static_cast<double>(s.collisions.elements) / s.elements() : 0.0},
      {"list", s.collisions.pairs},
      {"touching", s.collisions.touching.size()},
      {"touching_list", s.collisions.touching}};
  nlohmann::json j = {{"scene", scene.file},
                      {"dimension", s.dimension},
                      {"boundary", geometry::to_string(s.boundary)},
                      {"edge", s.periodic()                               ? "none"
                               : s.edge == metrics::EdgeTreatment::border ? "border"
                                                                          : "none"},
                      {"elements", s.elements()},
                      {"window_measure", s.window_measure},
                      {"units", scene.scene.units},
                      {"range", s.range},
                      {"mean_spacing", s.mean_spacing},
                      {"categories", categories},
                      {"collisions", collisions},
                      {"all", directional(s.all, e.comparison ? &e.comparison->all : nullptr)},
                      {"axes", axes},
                      {"pair_correlation", correlation},
                      {"seconds", s.seconds}};
  if (e.comparison) j["w1_scale"] = e.comparison->scale;
  if (e.novelty) j["novelty"] = novelty_json(*e.novelty);
  if (e.neighbourhood) {
    const metrics::NeighbourhoodDistance& n = *e.neighbourhood;
    j["neighbourhood_distance"] = {{"mean", n.mean},
                                   {"normalised", n.normalised},
                                   {"radius", n.radius},
                                   {"mean_neighbours", n.mean_neighbours},
                                   {"output_centres", n.output_centres},
                                   {"exemplar_centres", n.exemplar_centres}};
  }
  return j;
}

nlohmann::json metric_options_json(const evaluation::MetricOptions& o) {
  return {
      {"boundary", boundary_name(o.boundary)},
      {"edge", edge_name(o.edge)},
      {"range", o.range},
      {"neighbourhood", o.neighbourhood},
      {"directions", o.directions},
      {"direction", o.direction == geometry::DirectionKind::centroid ? "centroid" : "gravitation"},
      {"proxy_tolerance", o.proxy_tolerance}};
}

}  // namespace shapeproc::report
