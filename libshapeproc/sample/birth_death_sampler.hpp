// Birth-death Metropolis-Hastings sampling of the shape process (Geyer & Møller 1994; paper §6.3;
// docs/mathematics.md, "Sampling: birth, death and shift"), with shift moves. From the empty
// configuration, each step is with probability p_s a shift, otherwise with equal probability a
// birth or a death:
// - birth: u uniform in the domain D, category c uniform among the C categories, shape uniform in
//   S_c; accepted with probability min(1, λ(ξ | x) |D| C / (n + 1)) (with a model's births near
//   neighbours, neighbour_births.hpp, a share of births is drawn there and the ratio divides by
//   the mixture's density instead);
// - death: an element chosen uniformly; accepted with probability min(1, n / (|D| C λ(x_i | x
// \ x_i)));
// - shift: an element chosen uniformly moves by an offset uniform in a ball of radius ρ (same shape
//   and category; wrapped on a torus, rejected when it leaves an open domain); the proposal is
//   symmetric, so it is accepted with probability min(1, λ(x_i' | x \ x_i) / λ(x_i | x \ x_i)) and
//   the chain keeps the same target density.
// λ comes from model::Interaction and model::pair_effect, the implementation the fit uses; the
// domain's mask and intensity map multiply β by a local factor (0 outside the mask).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "libshapeproc/core/random.hpp"
#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/model/shape_process_model.hpp"
#include "libshapeproc/sample/compression.hpp"
#include "libshapeproc/sample/move_counts.hpp"
#include "libshapeproc/sample/stationarity.hpp"
#include "libshapeproc/synthesis/synthesizer.hpp"

namespace shapeproc::sample {
struct ChainGeometry;
struct ChainTables;
struct ChainRegion;
class CellPartition;
}  // namespace shapeproc::sample

namespace shapeproc::sample {

struct SamplerOptions {
  // Steps; 0 = run until the element count is stationary (stationarity.hpp), or at most
  // `max_iterations` (then the result is not stationary).
  long long iterations = 0;
  long long max_iterations = 5'000'000;
  // With the automatic rule, a chain from empty found stationary at step T runs on to 2T, so that
  // the state it ends in does not depend on the test having passed. False: it stops at T, for a
  // caller that averages the chain's observations rather than keeping its last state.
  bool run_on = true;
  // A chain whose element count passes this many has run away (a model that condenses on this
  // domain): it stops with a core::ArgumentError naming the model's strongest attraction
  // (runaway.hpp). 0: no limit (the maximum-likelihood fit's chains, which probe such models).
  long long runaway_count = 0;
  double shift_probability =
      1.0 / 3.0;  // share of steps that shift an element (0: pure birth-death)
  // The share of birth proposals drawn near an element, at an offset the exemplar showed
  // (neighbour_births.hpp), when the model has offsets; the rest are uniform. The chain's target
  // is the model's at any share. Negative: the model's own (model::NeighbourOffsets::share).
  double near_birth_share = -1.0;
  double shift_radius = 0.0;  // ρ; 0 = half the model's interaction range (1/20 of the
                              // domain's shorter side for a model without interaction)
  long long trace_every = 0;  // record the state every so many steps (0: no trace)
  // Record the sufficient statistics t(x) every so many steps (0: never), for Monte Carlo
  // estimates of E_θ[t] and Cov_θ[t] (maximum-likelihood fits).
  long long observe_every = 0;
  // A layered model's interval for each of its layers in turn, in place of observe_every (a
  // layer of a few large elements changes far faster per element than one of many small ones);
  // empty: observe_every for every layer.
  std::vector<long long> layer_observe_every;
  // When set, each observation is t of the elements in this region (and the pairs within it,
  // Configuration::statistics_in) followed by t(x) of the whole configuration: 2 × p values.
  geometry::Box3 observe_region;
  // Border correction (docs/mathematics.md, "Edge treatment"): elements present from the start that
  // are never removed or moved, and the region where births and shifts place elements' reference
  // positions (empty: the whole domain). The chain then samples the elements of the region given
  // the fixed ones; its statistics t(x) count both, the fixed part being constant.
  std::vector<geometry::Element> fixed;
  geometry::Box3 free_region;
  // Elements the chain starts from, instead of the empty configuration: moved and removed like
  // any other (a hybrid's start, compare/hybrid_synthesis.hpp). One outside the domain or that the
  // hard core forbids beside those before it is left out (SampleResult::start_left_out).
  std::vector<geometry::Element> start;
  // The proxies and outline guard of an earlier sampler's model with the same shapes,
  // measurement and thresholds on the same domain (ChainGeometry): shared instead of built
  // again. Empty: built.
  std::shared_ptr<const ChainGeometry> geometry;
  // The compressing burn-in (compression.hpp): from empty (or `start`), a phase at an annealed β
  // before the chain samples the model. With given `iterations` they include it (its steps must
  // be fewer); with the automatic rule, the rule starts once it is over.
  CompressionOptions compression;
  // Parallel sampling of this one output by domain decomposition (domain_decomposition.hpp) on
  // `threads` threads (0: one per core), where the domain is large enough to cut into cells of
  // the model's reach; otherwise, and with fixed elements, a free region, observations or a
  // saturated band, the whole-domain chain. The output does not depend on the threads.
  bool decompose = false;
  int threads = 0;
  // The processes the decomposed run's cells are shared among (cell_partition.hpp; the
  // distributed module's MPI ranks), each calling sample() with the same seed and options: each
  // returns its own cells' elements, and the counts of the whole. Decomposition is then required:
  // a model or request the decomposed sampler cannot take is refused (core::ArgumentError).
  // Empty: this process owns every cell.
  std::shared_ptr<CellPartition> partition;
};

struct SampleResult {
  geometry::Scene scene;  // the model's shapes, the sampled elements, the domain's box as window
  // The elements of hidden categories (model::CategoryParameters::hidden), placed by the chain
  // and left out of `scene`.
  std::vector<geometry::Element> hidden;
  long long iterations = 0;
  MoveCounts moves;
  bool stationary = true;  // false when the automatic rule hit max_iterations
  std::vector<synthesis::TracePoint> trace;
  // The sufficient statistics t(x) by θ index (model::Interaction's numbering: elements per
  // category, then pairs per interaction parameter) at the end, and every observe_every steps.
  std::vector<double> statistics;
  std::vector<std::vector<double>> observations;
  // A layered model's: the index in `observations` where each layer's chain starts (its
  // observations count the layers below as they were left); empty otherwise.
  std::vector<std::size_t> layer_observations;
  int start_kept = 0, start_left_out = 0;  // of SamplerOptions::start
  // The compressing burn-in's steps and the count it reached at the end of its first phase (0
  // without one).
  long long compression_steps = 0;
  int compressed_count = 0;
  // The moves of its growth stages (their own chains; `moves` counts the chain at the model's
  // hard cores, whose first phases end the burn-in).
  MoveCounts growth_moves;
  // The automatic rule's last check: the mean counts of the two quarters it compared and the
  // standard error of their difference (zero with --iterations).
  CountTrend trend;
  // A decomposed run's second test: its elements' mean nearest distance, once per sweep, whose
  // quarters must agree as well (zero otherwise).
  CountTrend spacing_trend;
  // A decomposed run: its cells, its sweeps and the pilot chain's density (0 otherwise). Its
  // trace has one point per sweep, without a log density; its `statistics` stay empty.
  int cells = 0, sweeps = 0;
  double pilot_density = 0.0;
  // The cells of the last sweep: their side and the offset of their boundaries from the domain's
  // lower corner (to look for seams there).
  geometry::Vec3 cell_side = geometry::Vec3::Zero(), cell_offset = geometry::Vec3::Zero();
};

// The shape process as a synthesis method: construction validates the model and options and
// builds what every chain shares (the shape space's proxies, the compiled interaction, the shapes
// of each category); sample() runs one chain and may be called from several threads at once.
class ShapeProcessSampler : public synthesis::Synthesizer {
 public:
  // Throws core::ArgumentError for an invalid model, a mask or intensity map on a 3D domain, a
  // domain of another dimension than the model's, or options out of range.
  ShapeProcessSampler(const model::ShapeProcessModel& model, geometry::Domain domain,
                      SamplerOptions options = {});
  ~ShapeProcessSampler() override;

  std::string method() const override { return "shape-process"; }
  synthesis::SynthesisResult synthesize(core::Random& random,
                                        const synthesis::ChainControl& control) const override;
  SampleResult sample(core::Random& random, const synthesis::ChainControl& control = {}) const;
  // A sample as synthesize() gives it: its scene, trace, record (method, domain, options, steps)
  // and counters (moves; cells and sweeps when decomposed).
  synthesis::SynthesisResult describe(SampleResult sampled) const;

  const geometry::Domain& domain() const { return domain_; }
  double shift_radius() const;
  // The farthest apart two interacting reference positions can be.
  double reach() const;
  // A torus whose smaller side is under twice the reach: an element can meet its own images, and
  // pairs seen at a nearer image take that image's band (a band with no exemplar pair refuses
  // them).
  bool torus_smaller_than_reach() const;

 private:
  model::ShapeProcessModel model_;
  geometry::Domain domain_;
  SamplerOptions options_;
  std::unique_ptr<const ChainTables> tables_;
  std::unique_ptr<const ChainRegion> region_;  // the whole domain, or the free region
  // A layered model's stages (model::CategoryParameters::layer), each with births of its own
  // categories only; empty for a model of one layer.
  std::vector<std::unique_ptr<const ChainTables>> layers_;
  // A layered model's layers in turn, each given the elements of those below.
  SampleResult sample_layers(core::Random& random, const synthesis::ChainControl& control) const;
  // Why a run with `tables` cannot be decomposed ("a free region"), or empty when it can.
  std::string why_not_decomposed(const ChainTables& tables,
                                 const std::vector<geometry::Element>& fixed,
                                 long long observe_every) const;
  // One chain with `tables`, from `fixed` and `start`: the whole run of an unlayered model, or one
  // layer's given those below.
  SampleResult sample_layer(const ChainTables& tables, const std::vector<geometry::Element>& fixed,
                            const std::vector<geometry::Element>& start, long long observe_every,
                            core::Random& random, const synthesis::ChainControl& control) const;
  // The compressing burn-in's growth stages: the model with its hard cores scaled
  // (compression.hpp), smallest first, or for a crystal's growth one model for every stage (its
  // births near neighbours); empty without compression.
  std::vector<std::unique_ptr<const ChainTables>> growth_;
  bool crystal_ = false;  // the growth is a crystal's (compression.hpp)
  double push_radius_ = 0.0;
  std::unique_ptr<const ChainRegion> growth_region_;  // the region with short, frequent shifts
  void prepare_growth();
  // The growth stages from `start`: the elements they end with; adds their steps to `steps` and
  // their moves to `moves`.
  std::vector<geometry::Element> grow(const std::vector<geometry::Element>& start,
                                      core::Random& random, const synthesis::ChainControl& control,
                                      long long& steps, MoveCounts& moves) const;
};

// One chain on `domain`, for one-off use.
SampleResult sample_shape_process(const model::ShapeProcessModel& model,
                                  const geometry::Domain& domain, const SamplerOptions& options,
                                  core::Random& random);

}  // namespace shapeproc::sample
