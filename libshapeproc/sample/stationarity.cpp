#include "libshapeproc/sample/stationarity.hpp"

#include <algorithm>
#include <cmath>

namespace shapeproc::sample {

namespace {

// The means of the second half's two quarters, a quarter of the run apart: a trend that would
// move the statistic by max(floor, 1%) over as many steps again keeps the chain going (packed
// exemplars creep up by an element every few ten thousand steps, with little noise).
CountTrend quarter_trend(const std::vector<double>& values, std::size_t least, double floor) {
  const std::size_t half = values.size() / 2, length = values.size() - half;
  if (length < std::max<std::size_t>(least, 10)) return {};
  constexpr int kBatches = 10;
  std::vector<double> batch(kBatches, 0.0);
  const std::size_t per_batch = length / kBatches;
  for (int b = 0; b < kBatches; ++b) {
    for (std::size_t i = 0; i < per_batch; ++i) batch[b] += values[half + b * per_batch + i];
    batch[b] /= static_cast<double>(per_batch);
  }
  double first = 0.0, second = 0.0, mean = 0.0;
  for (int b = 0; b < kBatches; ++b) {
    (b < kBatches / 2 ? first : second) += batch[b] / (kBatches / 2);
    mean += batch[b] / kBatches;
  }
  double variance = 0.0;
  for (double m : batch) variance += (m - mean) * (m - mean) / (kBatches - 1);
  const double standard_error = std::sqrt(variance * (2.0 / (kBatches / 2)));
  return {std::abs(second - first) <=
              0.25 * std::max(floor, 0.01 * std::abs(mean)) + 2.0 * standard_error,
          first, second, standard_error};
}

}  // namespace

CountTrend count_trend(const std::vector<int>& counts, std::size_t least) {
  return quarter_trend(std::vector<double>(counts.begin(), counts.end()), least, 1.0);
}

CountTrend value_trend(const std::vector<double>& values, std::size_t least) {
  return quarter_trend(values, least, 0.0);
}

StationarityRule::Verdict StationarityRule::after_step(long long step, int elements,
                                                       const std::vector<double>& statistics) {
  // Found stationary at step T, a chain with a run-on goes on to 2T, so that the state it ends in
  // does not depend on the test having passed (agreeing quarters come more often in a quiet
  // stretch of a count that swings).
  if (settled_at_ > 0)
    return step >= std::min(max_steps_, 2 * settled_at_) ? Verdict::stationary
                                                         : Verdict::keep_going;
  if (step % kStride == 0) {
    counts_.push_back(elements);
    for (std::size_t c = 0; c < by_category_.size() && c < statistics.size(); ++c)
      by_category_[c].push_back(static_cast<int>(statistics[c]));
  }
  if (step < next_check_) return Verdict::keep_going;
  if (step >= kStepsPerElement * elements) {
    last_ = count_trend(counts_);
    for (const std::vector<int>& counts : by_category_)
      if (last_.stationary && !count_trend(counts).stationary) last_.stationary = false;
    if (last_.stationary) {
      if (!run_on_ || step >= max_steps_) return Verdict::stationary;
      settled_at_ = step;
      return Verdict::keep_going;
    }
  }
  if (step >= max_steps_) return Verdict::gave_up;
  next_check_ = std::min(max_steps_, std::max(step + 10000, step + step / 4));
  return Verdict::keep_going;
}

}  // namespace shapeproc::sample
