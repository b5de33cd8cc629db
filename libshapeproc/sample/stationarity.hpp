// The automatic stopping rule of a birth-death chain: run until the element count is stationary
// (docs/sample.md). Checked after 20,000 steps and then every max(10,000, a quarter of the steps
// so far); the chain stops once it has made at least 1,000 steps per element present and the
// second half of the run, cut into ten batches, has quarters whose mean counts differ by at most
// a quarter of max(1, 1% of the mean) plus two standard errors from the batch means, for the
// total count and for every category's (a rare category, large trees among grass, can creep up
// while the total is steady); or at the step limit (then it is not stationary).
#pragma once

#include <cstddef>
#include <vector>

namespace shapeproc::sample {

// The test on counts recorded at even intervals: the means of the second half's two quarters,
// the standard error of their difference (batch means), and whether they agree within the rule's
// tolerance; not stationary with fewer than `least` counts in the second half.
struct CountTrend {
  bool stationary = false;
  double first = 0.0, second = 0.0, standard_error = 0.0;
};
CountTrend count_trend(const std::vector<int>& counts, std::size_t least = 100);
// The same test on any statistic recorded at even intervals (a decomposed run's mean nearest
// distance, once per sweep): its quarters agree within a quarter of 1% of its mean plus two
// standard errors (no floor of one, which suits a count only).
CountTrend value_trend(const std::vector<double>& values, std::size_t least = 100);
inline bool is_stationary(const std::vector<int>& counts, std::size_t least = 100) {
  return count_trend(counts, least).stationary;
}

class StationarityRule {
 public:
  // With `run_on`, a chain found stationary at step T stops at 2T (at most max_steps): for chains
  // that sample the model from empty. Chains from given elements stop at T (a packed exemplar's
  // compressing burn-in starts the rule at its end, compression.hpp).
  // `categories`: the counts per category tested besides the total (after_step's statistics).
  explicit StationarityRule(long long max_steps, bool run_on = false, int categories = 1)
      : max_steps_(max_steps), by_category_(categories > 1 ? categories : 0), run_on_(run_on) {}

  enum class Verdict { keep_going, stationary, gave_up };
  // Called after every step with the element count and, for a rule of several categories, the
  // chain's statistics, whose first entries are the counts per category.
  Verdict after_step(long long step, int elements, const std::vector<double>& statistics = {});
  // The last check's quarters (all zero before the first check).
  const CountTrend& last_check() const { return last_; }

 private:
  static constexpr long long kMinimumSteps = 20000, kStride = 10, kStepsPerElement = 1000;
  long long max_steps_;
  long long next_check_ = kMinimumSteps;
  std::vector<int> counts_;                    // every kStride steps
  std::vector<std::vector<int>> by_category_;  // the same, per category (none for one)
  CountTrend last_;
  bool run_on_ = false;
  long long settled_at_ = 0;  // the step whose check found the count stationary (0: none yet)
};

}  // namespace shapeproc::sample
