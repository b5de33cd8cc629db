#include "libshapeproc/fit/effective_sample_size.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shapeproc::fit {

EffectiveSize effective_size(const std::vector<double>& samples, int p, int k,
                             const std::vector<std::pair<int, int>>& chains) {
  EffectiveSize e;
  const auto at = [&](int row) {
    return samples[static_cast<std::size_t>(row) * static_cast<std::size_t>(p) +
                   static_cast<std::size_t>(k)];
  };
  int n = 0;  // the shortest chain's length
  int total = 0;
  for (const auto& [first, last] : chains) {
    n = n == 0 ? last - first : std::min(n, last - first);
    total += last - first;
  }
  const double m = static_cast<double>(chains.size());
  if (chains.empty() || n < 2) return e;
  std::vector<double> means;
  double within = 0.0;  // W
  for (const auto& [first, last] : chains) {
    double mean = 0.0;
    for (int i = first; i < last; ++i) mean += at(i);
    mean /= static_cast<double>(last - first);
    means.push_back(mean);
    double sum = 0.0;
    for (int i = first; i < last; ++i) sum += (at(i) - mean) * (at(i) - mean);
    within += sum / static_cast<double>(last - first - 1) / m;
  }
  double between = 0.0;  // B / n
  if (chains.size() > 1) {
    double grand = 0.0;
    for (double x : means) grand += x / m;
    for (double x : means) between += (x - grand) * (x - grand) / (m - 1);
  }
  const double dn = static_cast<double>(n);
  e.variance = (dn - 1) / dn * within + between;
  if (!(e.variance > 0.0)) {
    e.effective = static_cast<double>(total);
    return e;  // constant: no error
  }
  // ρ_t for t = 0, 1, ...: the mean over chains of each chain's autocovariance (divided by its
  // length, the usual positive-definite estimate), against var⁺.
  const auto rho = [&](int lag) {
    double mean_autocovariance = 0.0;
    for (std::size_t j = 0; j < chains.size(); ++j) {
      const int first = chains[j].first, last = chains[j].second;
      double sum = 0.0;
      for (int i = first; i + lag < last; ++i) sum += (at(i) - means[j]) * (at(i + lag) - means[j]);
      mean_autocovariance += sum / static_cast<double>(last - first) / m;
    }
    return 1.0 - (within - mean_autocovariance) / e.variance;
  };
  // Geyer's initial positive sequence, made monotone: pairs Γ_s = ρ_2s + ρ_2s+1.
  double sum = 0.0, previous = std::numeric_limits<double>::infinity();
  for (int lag = 0; lag + 1 < n; lag += 2) {
    double pair = (lag == 0 ? 1.0 : rho(lag)) + rho(lag + 1);
    if (!(pair > 0.0)) break;
    pair = std::min(pair, previous);
    previous = pair;
    sum += pair;
  }
  // τ at least 1 / log10(m n), as Stan bounds it (antithetic chains would otherwise claim
  // arbitrarily many effective draws).
  const double draws = static_cast<double>(total);
  e.autocorrelation = std::max(-1.0 + 2.0 * sum, 1.0 / std::log10(std::max(10.0, draws)));
  e.effective = draws / e.autocorrelation;
  e.standard_error = std::sqrt(e.variance / e.effective);
  return e;
}

}  // namespace shapeproc::fit
