// The compressing burn-in (docs/sample.md, "From empty"): how a chain that starts empty reaches
// the density of a packed exemplar. Birth-death moves at the model's β add an element only where
// a proposal happens to fit; near a packing at the hard core almost none does, and a chain from
// empty jams near random sequential filling. The burn-in therefore grows the hard cores while
// births continue (after Lubachevsky and Stillinger 1990), and anneals β:
//   1. growth: the chain runs on models whose hard cores δ_0 are `start_scale` of the model's,
//      then larger in `stages` equal steps up to the model's own; at each step an element that
//      the grown hard cores now forbid is moved to the nearest place found around it (or, where
//      none is found, removed), and births and deaths see β_c e^B (B = `log_boost`), so that every
//      proposal that fits is kept and removals are rare while shifts rearrange the elements.
//      Random elements jam a lattice far below its density (its sites between placed neighbours
//      fit only where both leave room); a lattice exemplar's growth is therefore a crystal's
//      (`crystal`): births at its neighbour offsets, from the first element on;
//   2. at the model's own hard cores, a phase at the same boost, then its release: B falls
//      linearly to 0 over as many steps;
//   3. exact Metropolis–Hastings at the model.
// The burn-in only chooses where the chain starts, from no position of the exemplar; every
// statistic measured after it is the model's.
#pragma once

#include <cmath>

#include "libshapeproc/model/burn_in.hpp"
#include "libshapeproc/model/shape_process_model.hpp"

namespace shapeproc::sample {

struct CompressionOptions {
  // plain: no compressing burn-in; crystal: growth as a crystal (a lattice exemplar): the stages
  // keep the model's own hard cores, and every birth is proposed exactly at one of the
  // exemplar's neighbour offsets from an element (uniformly only into the empty configuration),
  // kept whenever it fits: the lattice grows from its first element. A crystal needs the model's
  // neighbour offsets (without them the cores grow as for compressing).
  model::BurnIn burn_in_kind = model::BurnIn::plain;
  bool enabled() const { return burn_in_kind != model::BurnIn::plain; }
  // Steps of each growth stage; 0: 50 per element present at the stage's start, at least
  // kLeastStageSteps.
  long long steps = 0;
  // Steps of the boosted phase at the model's own hard cores, and again of its release; 0: as a
  // growth stage. A chain of given steps needs them (their double fewer than its steps).
  long long release_steps = 0;
  double log_boost = std::log(1000.0);  // B: β multiplied by 1,000 at first
  double start_scale = 0.5;             // the hard cores grow from this share of the model's
  int stages = 8;                       // growth stages before the model's own hard cores

  static constexpr long long kLeastStageSteps = 2000;
  static constexpr long long kStepsPerElement = 50;
  // The steps of a stage that starts with `elements`.
  long long stage_steps(int elements) const;
};

// The model with every axis's hard core δ_0 multiplied by `scale` (0 < scale <= 1), the other
// thresholds as they are.
model::ShapeProcessModel with_scaled_hard_cores(const model::ShapeProcessModel& model,
                                                double scale);

// Throws core::ArgumentError for options out of range.
void check_compression(const CompressionOptions& options);

class CompressionSchedule {
 public:
  explicit CompressionSchedule(const CompressionOptions& options);

  // The boost of the step to come: B in the first phase, falling linearly to 0 in the second,
  // 0 once done (and without compression).
  double log_boost() const { return boost_; }
  // Called after every step with the element count. The first phase lasts
  // options.release_steps, or with 0 stage_steps of the count at the first call.
  void after_step(long long step, int elements);
  bool done() const { return phase_ == Phase::done; }
  // The step at which the burn-in ended (0 without one or before its end).
  long long finished_at() const { return finished_at_; }
  // The first phase's length (0 before its end).
  long long compressed_for() const { return compressed_for_; }

 private:
  enum class Phase { compress, release, done };
  CompressionOptions options_;
  long long first_phase_ = 0;
  Phase phase_ = Phase::done;
  double boost_ = 0.0;
  long long compressed_for_ = 0, finished_at_ = 0;
};

}  // namespace shapeproc::sample
