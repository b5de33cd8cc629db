// How far apart two samples of one distribution fall by chance, in the Wasserstein-1 distance: the
// critical value of a two-sample test of "same distribution" with W1 as its statistic
// (docs/metrics.md#spacing). Under the hypothesis both samples come from their pooled
// distribution; the critical value at `level` is the (1 − level) quantile of W1 between two
// resamples of it of the samples' own sizes (a parametric bootstrap with a fixed seed, so the same
// pair of distributions always gets the same figure).
#pragma once

#include <cstdint>

#include "libshapeproc/metrics/scene_statistics.hpp"

namespace shapeproc::metrics {

struct WassersteinTestOptions {
  double level = 0.01;  // the test's size: a same-distribution pair exceeds the figure this often
  int resamples = 499;  // bootstrap pairs drawn
  int largest_sample = 4096;  // sample sizes above this are drawn at this size (the figure
                              // then overstates the chance distance slightly; it is already small)
  std::uint64_t seed = 1;
};

struct WassersteinTest {
  double critical = 0.0;  // W1 that a same-distribution pair exceeds with probability `level`
  // The sample sizes drawn: each distribution's distinct values (a distance two elements measure
  // of each other counts once), at most its samples, capped at largest_sample.
  int sizes[2] = {0, 0};
};

// Throws core::ArgumentError when either distribution is empty or its `samples` is below 1.
WassersteinTest wasserstein_test(const Distribution& a, const Distribution& b,
                                 const WassersteinTestOptions& options = {});

}  // namespace shapeproc::metrics
