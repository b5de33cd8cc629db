#include "libshapeproc/metrics/wasserstein_test.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/random.hpp"

namespace shapeproc::metrics {

namespace {

// The two distributions' mixture, each weighted by its share of the samples: the maximum
// likelihood estimate of the common distribution under the hypothesis, as a cumulative table.
struct Pooled {
  std::vector<double> values, cumulative;

  Pooled(const Distribution& a, const Distribution& b) {
    const double na = a.samples, nb = b.samples;
    std::vector<std::pair<double, double>> mass;
    for (std::size_t i = 0; i < a.values.size(); ++i)
      mass.emplace_back(a.values[i], a.weights[i] * na / (na + nb));
    for (std::size_t i = 0; i < b.values.size(); ++i)
      mass.emplace_back(b.values[i], b.weights[i] * nb / (na + nb));
    std::sort(mass.begin(), mass.end());
    double total = 0.0;
    for (const auto& [value, weight] : mass) {
      total += weight;
      values.push_back(value);
      cumulative.push_back(total);
    }
    for (double& c : cumulative) c /= total;
  }

  // `count` draws by the inverse of the cumulative table, as an empirical distribution.
  Distribution draw(int count, core::Random& random) const {
    std::vector<std::pair<double, double>> drawn(static_cast<std::size_t>(count));
    for (auto& [x, weight] : drawn) {
      const auto at = std::upper_bound(cumulative.begin(), cumulative.end(), random.uniform());
      x = values[std::min<std::size_t>(at - cumulative.begin(), values.size() - 1)];
      weight = 1.0;
    }
    return make_distribution(std::move(drawn), count);
  }
};

// The values that vary independently: a distribution's distinct values, at most its samples. Two
// elements that are each other's nearest neighbour measure one distance twice, so a sample of
// nearest distances holds fewer independent values than elements; counting each twice would
// make chance differences look significant.
int independent_values(const Distribution& d) {
  return std::min(d.samples, static_cast<int>(d.values.size()));
}

}  // namespace

WassersteinTest wasserstein_test(const Distribution& a, const Distribution& b,
                                 const WassersteinTestOptions& options) {
  if (a.empty() || b.empty() || a.samples < 1 || b.samples < 1) {
    throw core::ArgumentError("wasserstein_test", "both distributions need samples");
  }
  if (!(options.level > 0 && options.level < 1) || options.resamples < 1 ||
      options.largest_sample < 1) {
    throw core::ArgumentError("wasserstein_test", "level in (0, 1), resamples and sizes positive");
  }
  WassersteinTest test;
  test.sizes[0] = std::min(independent_values(a), options.largest_sample);
  test.sizes[1] = std::min(independent_values(b), options.largest_sample);
  const Pooled pooled(a, b);
  core::Random random(options.seed);
  std::vector<double> distances;
  distances.reserve(static_cast<std::size_t>(options.resamples));
  for (int r = 0; r < options.resamples; ++r) {
    const Distribution x = pooled.draw(test.sizes[0], random);
    const Distribution y = pooled.draw(test.sizes[1], random);
    distances.push_back(wasserstein1(x, y));
  }
  // The smallest figure at least (1 − level) of the resampled distances do not exceed.
  std::sort(distances.begin(), distances.end());
  const auto rank = static_cast<std::size_t>(
      std::ceil((1.0 - options.level) * static_cast<double>(distances.size())));
  test.critical = distances[std::clamp<std::size_t>(rank, 1, distances.size()) - 1];
  return test;
}

}  // namespace shapeproc::metrics
