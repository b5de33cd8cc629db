#include "libshapeproc/evaluation/envelope.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "libshapeproc/core/random.hpp"
#include "libshapeproc/metrics/scene_statistics.hpp"
#include "libshapeproc/sample/birth_death_sampler.hpp"

namespace shapeproc::evaluation {

namespace {

// The nearest-neighbour CDFs of a scene at `r`: all directions first, then each axis.
std::vector<std::vector<double>> nearest_cdfs(const geometry::Scene& scene,
                                              const metrics::StatisticsOptions& options,
                                              const std::vector<double>& r) {
  const metrics::SceneStatistics s = metrics::compute_statistics(scene, options, core::Random(1));
  std::vector<std::vector<double>> out;
  const auto cdf = [&](const metrics::Distribution& d) {
    std::vector<double> values;
    for (const double x : r) values.push_back(d.empty() ? 0.0 : d.cdf(x));
    return values;
  };
  out.push_back(cdf(s.all.nearest));
  for (const metrics::DirectionalStatistics& a : s.axes) out.push_back(cdf(a.nearest));
  return out;
}

}  // namespace

std::vector<EnvelopeCurve> nearest_envelopes(const geometry::Scene& exemplar,
                                             geometry::Boundary boundary,
                                             const model::ShapeProcessModel& model,
                                             const EnvelopeOptions& options) {
  const bool periodic = boundary == geometry::Boundary::torus;
  metrics::StatisticsOptions stats;
  stats.measurement = model.measurement_options(periodic);
  stats.measurement.proxy.tolerance = 0.002;
  stats.offset_samples = 256;  // g(r) is not used here
  const double range =
      std::pow(exemplar.window_measure() /
                   std::max<double>(1.0, static_cast<double>(exemplar.elements.size())),
               1.0 / exemplar.dimension);
  stats.range = range;
  std::vector<double> r;
  for (int i = 1; i <= options.points; ++i) r.push_back(range * i / options.points);

  const std::vector<std::vector<double>> observed = nearest_cdfs(exemplar, stats, r);
  std::vector<std::vector<double>> low(observed.size(), std::vector<double>(r.size(), 2.0)),
      high(observed.size(), std::vector<double>(r.size(), -1.0));
  const geometry::Domain window(exemplar.window, exemplar.dimension, boundary);
  sample::SamplerOptions sampling;
  sampling.iterations = options.steps;
  const sample::ShapeProcessSampler sampler(model, window, sampling);
  for (int k = 0; k < options.samples; ++k) {
    core::Random random(options.seed + static_cast<std::uint64_t>(k));
    const geometry::Scene sampled = sampler.sample(random).scene;
    if (sampled.elements.empty()) {
      for (std::size_t c = 0; c < observed.size(); ++c)
        for (std::size_t i = 0; i < r.size(); ++i) {
          low[c][i] = std::min(low[c][i], 0.0);
          high[c][i] = std::max(high[c][i], 0.0);
        }
      continue;
    }
    const std::vector<std::vector<double>> curves = nearest_cdfs(sampled, stats, r);
    for (std::size_t c = 0; c < observed.size() && c < curves.size(); ++c)
      for (std::size_t i = 0; i < r.size(); ++i) {
        low[c][i] = std::min(low[c][i], curves[c][i]);
        high[c][i] = std::max(high[c][i], curves[c][i]);
      }
  }

  std::vector<EnvelopeCurve> out;
  const int axes = static_cast<int>(observed.size()) - 1;
  for (std::size_t c = 0; c < observed.size(); ++c) {
    EnvelopeCurve e;
    if (c == 0) {
      e.label = "G, all directions";
    } else {
      char text[64];
      std::snprintf(text, sizeof text, "G, axis %d (%g°)", static_cast<int>(c) - 1,
                    exemplar.dimension == 2 ? 180.0 * static_cast<double>(c - 1) / axes : 0.0);
      e.label = exemplar.dimension == 2 ? text : "G, axis " + std::to_string(c - 1);
    }
    e.r = r;
    e.exemplar = observed[c];
    e.low = low[c];
    e.high = high[c];
    int outside = 0;
    const double slack = 1e-9;
    for (std::size_t i = 0; i < r.size(); ++i)
      outside += e.exemplar[i] < e.low[i] - slack || e.exemplar[i] > e.high[i] + slack;
    e.outside = static_cast<double>(outside) / static_cast<double>(r.size());
    out.push_back(std::move(e));
  }
  return out;
}

}  // namespace shapeproc::evaluation
