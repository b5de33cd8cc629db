#include "libshapeproc/sample/compression.hpp"

#include "libshapeproc/core/check.hpp"

namespace shapeproc::sample {

CompressionSchedule::CompressionSchedule(const CompressionOptions& options, long long max_steps)
    : options_(options), rule_(max_steps) {
  core::check(options.steps >= 0 && options.log_boost >= 0, "sample",
              "the compressing burn-in needs steps >= 0 and a boost >= 0");
  if (!options.enabled) return;
  phase_ = Phase::compress;
  boost_ = options.log_boost;
}

void CompressionSchedule::after_step(long long step, int elements) {
  switch (phase_) {
    case Phase::compress: {
      const bool over = options_.steps > 0 ? step >= options_.steps
                                           : rule_.after_step(step, elements) !=
                                                 StationarityRule::Verdict::keep_going;
      if (!over) return;
      compressed_for_ = step;
      phase_ = Phase::release;
      return;
    }
    case Phase::release: {
      const long long into = step - compressed_for_;
      if (into >= compressed_for_) {
        phase_ = Phase::done;
        boost_ = 0.0;
        finished_at_ = step;
        return;
      }
      boost_ = options_.log_boost *
               (1.0 - static_cast<double>(into) / static_cast<double>(compressed_for_));
      return;
    }
    case Phase::done:
      return;
  }
}

}  // namespace shapeproc::sample
