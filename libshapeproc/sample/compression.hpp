// The compressing burn-in (docs/sample.md, "From empty"): how a chain that starts empty reaches
// the density of a packed exemplar. Birth-death moves at the model's β add an element only where
// a proposal happens to fit; at a packing near the hard core almost none does, and a chain from
// empty stalls far below the exemplar's count. The burn-in therefore anneals β: for its first
// phase births and deaths see β_c e^B instead of β_c (B = `log_boost`), so that every proposal
// that fits is kept and elements are rarely removed while shifts rearrange them, which opens room
// for more (a compression at high pressure); in its second phase, as long as the first, B falls
// linearly to 0. From then on the chain is exact Metropolis–Hastings at the model: the burn-in
// only chooses where it starts, from no position of the exemplar, and every statistic measured
// after it is the model's.
#pragma once

#include <cmath>

#include "libshapeproc/sample/stationarity.hpp"

namespace shapeproc::sample {

struct CompressionOptions {
  bool enabled = false;
  // Steps of the first phase at the full boost; 0: until the element count is stationary under
  // the boost (StationarityRule, at most the sampler's step limit).
  long long steps = 0;
  double log_boost = std::log(1000.0);  // B: β multiplied by 1,000 at first
};

class CompressionSchedule {
 public:
  CompressionSchedule(const CompressionOptions& options, long long max_steps);

  // The boost of the step to come: B in the first phase, falling linearly to 0 in the second,
  // 0 once done (and without compression).
  double log_boost() const { return boost_; }
  // Called after every step with the element count.
  void after_step(long long step, int elements);
  bool done() const { return phase_ == Phase::done; }
  // The step at which the burn-in ended (0 without one or before its end).
  long long finished_at() const { return finished_at_; }
  // The first phase's length (0 before its end).
  long long compressed_for() const { return compressed_for_; }

 private:
  enum class Phase { compress, release, done };
  CompressionOptions options_;
  StationarityRule rule_;
  Phase phase_ = Phase::done;
  double boost_ = 0.0;
  long long compressed_for_ = 0, finished_at_ = 0;
};

}  // namespace shapeproc::sample
