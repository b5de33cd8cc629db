// Birth-death Metropolis-Hastings sampling of the shape process (Geyer & Møller 1994; paper §6.3;
// math note "Birth-death Metropolis-Hastings"), with shift moves. From the empty configuration,
// each step is with probability p_s a shift, otherwise with equal probability a birth or a death:
// - birth: u uniform in the domain D, category c uniform among the C categories, shape uniform in
//   S_c; accepted with probability min(1, λ(ξ | x) |D| C / (n + 1));
// - death: an element chosen uniformly; accepted with probability min(1, n / (|D| C λ(x_i | x \ x_i)));
// - shift: an element chosen uniformly moves by an offset uniform in a ball of radius ρ (same shape
//   and category; wrapped on a torus, rejected when it leaves an open domain); the proposal is
//   symmetric, so it is accepted with probability min(1, λ(x_i' | x \ x_i) / λ(x_i | x \ x_i)) and
//   the chain keeps the same target density.
// λ comes from model::Interaction and model::pair_effect, the implementation the fit uses.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/model/shape_process_model.hpp"
#include "libshapeproc/geometry/raster.hpp"

namespace shapeproc::sample {

struct SamplerOptions {
  // Steps; 0 = run until the element count is stationary: checked after 20,000 steps and then
  // every max(10,000, a quarter of the steps so far); the run stops once it has made at least
  // 1,000 steps per element present and the second half of the run, cut into ten batches, has
  // quarters whose mean counts differ by at most a quarter of max(1, 1% of the mean) plus two
  // standard errors from the batch means; or at `max_iterations` (then SampleResult::stationary
  // is false).
  long long iterations = 0;
  long long max_iterations = 5'000'000;
  double shift_probability = 1.0 / 3.0;  // share of steps that shift an element (0: pure birth-death)
  double shift_radius = 0.0;             // ρ; 0 = half the model's interaction range (1/20 of the
                                         // domain's shorter side for a model without interaction)
  std::uint64_t seed = 1;
  bool periodic = true;  // toroidal distances on the rectangular or box domain
  long long trace_every = 0;  // record the state every so many steps (0: no trace)
  // 2D, stretched over the domain (x right, y down): a shape mask (inside where ≥ 0.5; every
  // element must lie inside entirely, its proxy outline tested at half-pixel spacing) and an
  // intensity map (β_c × value). Either may be null. β = 0 outside the mask.
  const geometry::Raster* mask = nullptr;
  const geometry::Raster* intensity = nullptr;
  // Called now and then with the steps done so far (for a progress bar); may be empty.
  std::function<void(long long done, long long total)> progress;
};

struct TracePoint {
  long long step = 0;
  int elements = 0;
  double log_density = 0.0;  // unnormalised log f(x)
};

struct SampleResult {
  geometry::Scene scene;  // the model's shapes, the sampled elements, the domain as window
  long long iterations = 0;
  long long births_accepted = 0, deaths_accepted = 0, births_proposed = 0, deaths_proposed = 0;
  long long shifts_accepted = 0, shifts_proposed = 0;
  bool stationary = true;  // false when the automatic rule hit max_iterations
  std::vector<TracePoint> trace;
};

// Seed of chain `chain` of a run seeded `seed` (chain 0 keeps the seed).
std::uint64_t chain_seed(std::uint64_t seed, int chain);

// Samples the model on `domain` (a rectangle in 2D, a box in 3D). Throws std::invalid_argument on
// an empty domain, or a mask or intensity map given for a 3D model.
SampleResult sample_shape_process(const model::ShapeProcessModel& model, const geometry::Box3& domain,
                                  const SamplerOptions& options);

}  // namespace shapeproc::sample
