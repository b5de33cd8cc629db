#include "libshapeproc/sample/compression.hpp"

#include <algorithm>

#include "libshapeproc/core/check.hpp"

namespace shapeproc::sample {

long long CompressionOptions::stage_steps(int elements) const {
  return steps > 0
             ? steps
             : std::max(kLeastStageSteps, kStepsPerElement * static_cast<long long>(elements));
}

model::ShapeProcessModel with_scaled_hard_cores(const model::ShapeProcessModel& model,
                                                double scale) {
  core::check(scale > 0 && scale <= 1, "sample", "a hard core's scale must be in (0, 1]");
  model::ShapeProcessModel scaled = model;
  for (model::PairInteraction& pair : scaled.interactions)
    for (model::AxisParameters& axis : pair.axes)
      if (!axis.thresholds.empty()) axis.thresholds.front() *= scale;
  return scaled;
}

void check_compression(const CompressionOptions& options) {
  core::check(options.steps >= 0 && options.release_steps >= 0 && options.log_boost >= 0 &&
                  options.stages >= 0 && options.start_scale > 0 && options.start_scale <= 1,
              "sample",
              "the compressing burn-in needs steps >= 0, a boost >= 0, stages >= 0 and a start "
              "scale in (0, 1]");
}

CompressionSchedule::CompressionSchedule(const CompressionOptions& options) : options_(options) {
  check_compression(options);
  if (!options.enabled()) return;
  phase_ = Phase::compress;
  boost_ = options.log_boost;
}

void CompressionSchedule::after_step(long long step, int elements) {
  switch (phase_) {
    case Phase::compress: {
      if (first_phase_ == 0)
        first_phase_ =
            options_.release_steps > 0 ? options_.release_steps : options_.stage_steps(elements);
      if (step < first_phase_) return;
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
