#include "libshapeproc/evaluation/envelope.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "libshapeproc/core/format.hpp"
#include "libshapeproc/core/random.hpp"
#include "libshapeproc/fit/output_sampling.hpp"
#include "libshapeproc/metrics/scene_statistics.hpp"
#include "libshapeproc/sample/birth_death_sampler.hpp"

namespace shapeproc::evaluation {

namespace {

// The nearest-neighbour CDFs of a scene at `r`, all directions first, then each axis; last, the
// pair correlation g in its bins (NaN where undefined, as compute_statistics gives it).
// `g_r`, when given, receives g's bin centres.
std::vector<std::vector<double>> curves_of(const geometry::Scene& scene,
                                           const metrics::StatisticsOptions& options,
                                           const std::vector<double>& r,
                                           std::vector<double>* g_r = nullptr) {
  const metrics::SceneStatistics s = metrics::compute_statistics(scene, options, core::Random(1));
  if (g_r) *g_r = s.correlation_r;
  std::vector<std::vector<double>> out;
  const auto cdf = [&](const metrics::Distribution& d) {
    std::vector<double> values;
    for (const double x : r) values.push_back(d.empty() ? 0.0 : d.cdf(x));
    return values;
  };
  out.push_back(cdf(s.all.nearest));
  for (const metrics::DirectionalStatistics& a : s.axes) out.push_back(cdf(a.nearest));
  out.push_back(s.correlation);
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
  stats.measurement.proxy.tolerance = geometry::kOutlineTolerance;
  stats.offset_samples = 4096;  // g's reference measure: enough for a band of 19 samples
  const double range =
      std::pow(exemplar.window_measure() /
                   std::max<double>(1.0, static_cast<double>(exemplar.elements.size())),
               1.0 / exemplar.dimension);
  stats.range = range;
  std::vector<double> r;
  for (int i = 1; i <= options.points; ++i) r.push_back(range * i / options.points);

  std::vector<double> g_r;
  const std::vector<std::vector<double>> observed = curves_of(exemplar, stats, r, &g_r);
  std::vector<std::vector<double>> low, high;
  for (const std::vector<double>& c : observed) {
    low.emplace_back(c.size(), std::numeric_limits<double>::infinity());
    high.emplace_back(c.size(), -std::numeric_limits<double>::infinity());
  }
  const auto widen = [&](std::size_t c, std::size_t i, double value) {
    if (!std::isfinite(value)) return;
    low[c][i] = std::min(low[c][i], value);
    high[c][i] = std::max(high[c][i], value);
  };
  const geometry::Domain window(exemplar.window, exemplar.dimension, boundary);
  fit::OutputSampling sampling;  // as outputs are sampled, however dense the model gets
  sampling.iterations = options.steps;
  sampling.stop_runaway = false;
  sampling.decompose = fit::Decomposition::off;
  const sample::ShapeProcessSampler sampler = fit::output_sampler(model, window, sampling);
  for (int k = 0; k < options.samples; ++k) {
    core::Random random(options.seed + static_cast<std::uint64_t>(k));
    const geometry::Scene sampled = sampler.sample(random).scene;
    if (sampled.elements.size() < 2) {  // no neighbours: every CDF 0, g undefined
      for (std::size_t c = 0; c + 1 < observed.size(); ++c)
        for (std::size_t i = 0; i < r.size(); ++i) widen(c, i, 0.0);
      continue;
    }
    const std::vector<std::vector<double>> curves = curves_of(sampled, stats, r);
    for (std::size_t c = 0; c < observed.size() && c < curves.size(); ++c)
      for (std::size_t i = 0; i < observed[c].size() && i < curves[c].size(); ++i)
        widen(c, i, curves[c][i]);
  }

  std::vector<EnvelopeCurve> out;
  const int axes = static_cast<int>(observed.size()) - 2;
  for (std::size_t c = 0; c < observed.size(); ++c) {
    EnvelopeCurve e;
    const bool g = c + 1 == observed.size();
    if (c == 0) {
      e.label = "G, all directions";
    } else if (g) {
      e.label = "g(r), all directions";
    } else {
      e.label = "G, axis " + std::to_string(c - 1);
      if (exemplar.dimension == 2)
        e.label += " (" + core::format_general(180.0 * static_cast<double>(c - 1) / axes, 6) + "°)";
    }
    e.r = g ? g_r : r;
    e.exemplar = observed[c];
    e.low = low[c];
    e.high = high[c];
    // Distances where the exemplar's curve or the band is undefined (g where no pair could be)
    // are not judged.
    int outside = 0, judged = 0;
    const double slack = 1e-9;
    for (std::size_t i = 0; i < e.exemplar.size(); ++i) {
      if (!std::isfinite(e.exemplar[i]) || !(e.low[i] <= e.high[i])) continue;
      ++judged;
      outside += e.exemplar[i] < e.low[i] - slack || e.exemplar[i] > e.high[i] + slack;
    }
    e.outside = judged > 0 ? static_cast<double>(outside) / judged : 0.0;
    out.push_back(std::move(e));
  }
  return out;
}

}  // namespace shapeproc::evaluation
