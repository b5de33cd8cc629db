// Birth-death Metropolis-Hastings sampling of the shape process (Geyer & Møller 1994; paper §6.3;
// math note "Birth-death Metropolis-Hastings"). From the empty configuration, each step is with
// probability 1/2 a birth (u uniform in the domain D, category c uniform among the C categories,
// shape uniform in S_c), accepted with probability min(1, λ(ξ | x) |D| C / (n + 1)), or a death
// (an element chosen uniformly), accepted with probability min(1, n / (|D| C λ(x_i | x \ x_i))).
// λ comes from model::Interaction and model::pair_effect, the implementation the fit uses.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/model/shape_process_model.hpp"
#include "libshapeproc/render/raster.hpp"

namespace shapeproc::sample {

struct SamplerOptions {
  // Steps; 0 = the default rule: 200 steps per expected element (Σ_c β_c |D|), at least 20,000.
  long long iterations = 0;
  std::uint64_t seed = 1;
  bool periodic = true;  // toroidal distances on the rectangular or box domain
  long long trace_every = 0;  // record the state every so many steps (0: no trace)
  // 2D, stretched over the domain (x right, y down): a shape mask (inside where ≥ 0.5; every
  // element must lie inside entirely, its proxy outline tested at half-pixel spacing) and an
  // intensity map (β_c × value). Either may be null. β = 0 outside the mask.
  const render::Raster* mask = nullptr;
  const render::Raster* intensity = nullptr;
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
  std::vector<TracePoint> trace;
};

// Default number of steps for a model and domain (the rule above).
long long default_iterations(const model::ShapeProcessModel& model, const geometry::Box3& domain,
                             const SamplerOptions& options = {});

// Seed of chain `chain` of a run seeded `seed` (chain 0 keeps the seed).
std::uint64_t chain_seed(std::uint64_t seed, int chain);

// Samples the model on `domain` (a rectangle in 2D, a box in 3D). Throws std::invalid_argument on
// an empty domain, or a mask or intensity map given for a 3D model.
SampleResult sample_shape_process(const model::ShapeProcessModel& model, const geometry::Box3& domain,
                                  const SamplerOptions& options);

}  // namespace shapeproc::sample
