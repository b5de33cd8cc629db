#include "libshapeproc/sample/birth_death_sampler.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "libshapeproc/core/check.hpp"
#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/format.hpp"
#include "libshapeproc/geometry/pair_measurements.hpp"
#include "libshapeproc/model/interaction.hpp"
#include "libshapeproc/sample/birth_death_chain.hpp"
#include "libshapeproc/sample/domain_decomposition.hpp"
#include "libshapeproc/sample/runaway.hpp"
#include "libshapeproc/sample/stationarity.hpp"

namespace shapeproc::sample {

namespace {
// Places tried around an element the grown hard cores cover before it is removed.
constexpr int kPushAttempts = 24;
// The share of shifts among a growth stage's steps.
constexpr double kGrowthShiftProbability = 0.6;
}  // namespace

ShapeProcessSampler::ShapeProcessSampler(const model::ShapeProcessModel& model,
                                         geometry::Domain domain, SamplerOptions options)
    : model_(model), domain_(std::move(domain)), options_(options) {
  model::validate(model_);
  const int dimension = model_.dimension;
  core::check(domain_.dimension() == dimension, "sample",
              "the domain is " + std::to_string(domain_.dimension()) + "D but the model " +
                  std::to_string(dimension) + "D");
  if (options_.near_birth_share < 0) options_.near_birth_share = model_.neighbour_offsets.share;
  core::check_in_range("sample", "the share of births near neighbours", options_.near_birth_share,
                       0.0, 1.0, true);
  core::check_in_range("sample", "the shift probability", options_.shift_probability, 0.0, 1.0,
                       true);
  core::check_non_negative("sample", "the shift radius", options_.shift_radius);
  core::check(options_.iterations <= 0 || !options_.compression.enabled() ||
                  (options_.compression.release_steps > 0 &&
                   2 * options_.compression.release_steps < options_.iterations),
              "sample",
              "with given steps the compressing burn-in needs its own release steps, fewer than "
              "half of them");
  core::check(
      options_.trace_every >= 0 && options_.observe_every >= 0 &&
          std::all_of(options_.layer_observe_every.begin(), options_.layer_observe_every.end(),
                      [](long long every) { return every >= 0; }),
      "sample", "trace and observation intervals must be >= 0");

  tables_ = std::make_unique<const ChainTables>(model_, domain_, options_.geometry);
  const int categories = static_cast<int>(model_.categories.size());
  const int shapes = static_cast<int>(tables_->geometry->shape_space.shapes.size());
  ChainRegion region{domain_,
                     options_.free_region.isEmpty() ? domain_.box() : options_.free_region};
  if (!options_.free_region.isEmpty()) {
    core::check(!domain_.periodic() && !domain_.has_local_factor(), "sample",
                "a free region (border correction) needs a plain open domain");
    core::check(domain_.box().contains(region.free_region), "sample",
                "the free region must lie inside the domain");
    core::check_positive("sample", "the free region's measure",
                         geometry::measure(region.free_region, dimension));
  }
  for (const geometry::Element& e : options_.fixed) {
    core::check(e.category >= 0 && e.category < categories && e.shape >= 0 && e.shape < shapes,
                "sample", "a fixed element has a category or shape the model does not have");
    core::check(domain_.contains(e.position), "sample", "a fixed element lies outside the domain");
  }
  for (const geometry::Element& e : options_.start)
    core::check(e.category >= 0 && e.category < categories && e.shape >= 0 && e.shape < shapes,
                "sample", "a start element has a category or shape the model does not have");
  region.shift_probability = options_.shift_probability;
  region.near_birth_share = options_.near_birth_share;
  const double range = tables_->interaction->range();
  region.shift_radius = options_.shift_radius > 0 ? options_.shift_radius
                        : range > 0               ? 0.5 * range
                                    : 0.05 * domain_.sizes().head(dimension).minCoeff();
  region_ = std::make_unique<const ChainRegion>(std::move(region));
  check_compression(options_.compression);
  if (model_.layer_count() > 1) {
    core::check(!options_.compression.enabled(), "sample",
                "a layered model's outputs have no compressing burn-in");
    for (int layer = 0; layer < model_.layer_count(); ++layer)
      layers_.push_back(
          std::make_unique<const ChainTables>(model_, domain_, tables_->geometry, false, layer));
  }
  if (options_.compression.enabled() && range > 0) prepare_growth();
}

// The growth stages' models and the short, frequent shifts they move elements by.
void ShapeProcessSampler::prepare_growth() {
  const CompressionOptions& c = options_.compression;
  // An element its neighbours' grown hard cores now cover is looked for a place within twice
  // the growth of one stage of the largest hard core.
  double largest = 0.0;
  for (const model::PairInteraction& pair : model_.interactions)
    for (const model::AxisParameters& axis : pair.axes)
      if (!axis.thresholds.empty()) largest = std::max(largest, axis.thresholds.front());
  push_radius_ =
      std::max(2.0 * (1.0 - c.start_scale) / std::max(1, c.stages) * largest, 1e-3 * reach());
  // Near a packing a shift of half the range is always refused: the growth moves elements by
  // little, often, so that they settle into the room the grown cores leave.
  ChainRegion local = *region_;
  local.shift_radius = push_radius_;
  local.shift_probability = kGrowthShiftProbability;
  crystal_ = c.burn_in_kind == model::BurnIn::crystal && tables_->near_births;
  if (crystal_) {
    // Every birth exactly at an offset from an element, kept whenever it fits: a lattice's
    // offsets add up to its own sites, where jittered ones drift apart over a few cells and
    // leave the sites where two grown fronts meet too narrow for an element.
    model::ShapeProcessModel seeded = model_;
    seeded.neighbour_offsets.radii.assign(1, 0.0);
    growth_.push_back(std::make_unique<const ChainTables>(seeded, domain_, tables_->geometry));
    local.near_birth_share = 1.0;
    local.proposal_corrected = false;
    local.shift_probability = 0.0;  // a shift would move a grown element off its site
  }
  growth_region_ = std::make_unique<const ChainRegion>(std::move(local));
  for (int k = 0; k < c.stages && !crystal_; ++k) {
    const double scale = c.start_scale + (1.0 - c.start_scale) * k / c.stages;
    growth_.push_back(std::make_unique<const ChainTables>(with_scaled_hard_cores(model_, scale),
                                                          domain_, tables_->geometry, true));
  }
}

std::vector<Element> ShapeProcessSampler::grow(const std::vector<Element>& start,
                                               core::Random& random,
                                               const synthesis::ChainControl& control,
                                               long long& steps, MoveCounts& moves) const {
  std::vector<Element> state = start;
  const int stages = options_.compression.stages;
  for (int k = 0; k < stages; ++k) {
    // A crystal's stages share one model (its own hard cores); the others grow them.
    const ChainTables& tables = *growth_[std::min<std::size_t>(k, growth_.size() - 1)];
    BirthDeathChain chain(tables, *growth_region_, random, options_.fixed, {});
    chain.add_or_place_near(state, push_radius_, kPushAttempts);
    chain.set_log_boost(options_.compression.log_boost);
    const long long stage = options_.compression.stage_steps(chain.size());
    for (long long s = 1; s <= stage; ++s) {
      chain.step();
      if (s % 10000 == 0 && control.cancelled()) throw core::Cancelled();
    }
    steps += stage;
    moves += chain.moves();
    state = chain.free_elements();
  }
  return state;
}

ShapeProcessSampler::~ShapeProcessSampler() = default;

double ShapeProcessSampler::shift_radius() const { return region_->shift_radius; }

double ShapeProcessSampler::reach() const { return tables_->reach; }

bool ShapeProcessSampler::torus_smaller_than_reach() const {
  return domain_.periodic() && reach() > 0 &&
         domain_.sizes().head(model_.dimension).minCoeff() < 2.0 * reach();
}

SampleResult ShapeProcessSampler::sample(core::Random& random,
                                         const synthesis::ChainControl& control) const {
  SampleResult result = layers_.empty() ? sample_layer(*tables_, options_.fixed, options_.start,
                                                       options_.observe_every, random, control)
                                        : sample_layers(random, control);
  // The hidden categories' elements leave the output.
  std::vector<Element>& elements = result.scene.elements;
  const auto hidden = [&](const Element& e) {
    return model_.categories[static_cast<std::size_t>(e.category)].hidden;
  };
  for (const Element& e : elements)
    if (hidden(e)) result.hidden.push_back(e);
  elements.erase(std::remove_if(elements.begin(), elements.end(), hidden), elements.end());
  return result;
}

SampleResult ShapeProcessSampler::sample_layers(core::Random& random,
                                                const synthesis::ChainControl& control) const {
  // A layered model: each layer given the elements of those below (the earlier results are its
  // fixed elements); the result is the last layer's, with every layer's steps and moves.
  SampleResult result;
  std::vector<Element> placed = options_.fixed;
  long long steps = 0;
  MoveCounts moves;
  std::vector<synthesis::TracePoint> trace;
  std::vector<std::vector<double>> observations;
  std::vector<std::size_t> starts;
  for (std::size_t layer = 0; layer < layers_.size(); ++layer) {
    std::vector<Element> start;
    for (const Element& e : options_.start)
      if (model_.categories[static_cast<std::size_t>(e.category)].layer == static_cast<int>(layer))
        start.push_back(e);
    const long long observe_every = layer < options_.layer_observe_every.size()
                                        ? options_.layer_observe_every[layer]
                                        : options_.observe_every;
    result = sample_layer(*layers_[layer], placed, start, observe_every, random, control);
    starts.push_back(observations.size());
    for (std::vector<double>& o : result.observations) observations.push_back(std::move(o));
    for (synthesis::TracePoint point : result.trace) {
      point.step += steps;
      trace.push_back(point);
    }
    steps += result.iterations;
    moves += result.moves;
    placed = result.scene.elements;
  }
  result.iterations = steps;
  result.moves = moves;
  result.trace = std::move(trace);
  result.observations = std::move(observations);
  result.layer_observations = std::move(starts);
  return result;
}

std::string ShapeProcessSampler::why_not_decomposed(const ChainTables& tables,
                                                    const std::vector<Element>& fixed,
                                                    long long observe_every) const {
  if (!fixed.empty()) return "fixed elements";
  if (options_.partition && !layers_.empty()) return "a layered model";
  if (!options_.free_region.isEmpty()) return "a free region";
  if (observe_every > 0) return "observations";
  if (options_.compression.enabled())
    return "a model whose outputs need the compressing burn-in (a packed exemplar's)";
  if (tables.interaction->saturated()) return "a model with saturated bands";
  if (!decomposable(domain_, reach()))
    return "this domain: too small to cut into cells of the model's reach (" +
           core::format_general(reach(), 4) + ")";
  return {};
}

SampleResult ShapeProcessSampler::sample_layer(const ChainTables& tables,
                                               const std::vector<Element>& fixed,
                                               const std::vector<Element>& start,
                                               long long observe_every, core::Random& random,
                                               const synthesis::ChainControl& control) const {
  // The decomposed sampler has no compressing burn-in: a model that needs one runs one chain. Nor
  // does it hold its cells' surroundings' own links, which a saturated band's intensity reads.
  const std::string undecomposable = why_not_decomposed(tables, fixed, observe_every);
  if (options_.partition && !undecomposable.empty())
    throw core::ArgumentError("sample",
                              "a run across processes needs the decomposed sampler, "
                              "which cannot take " +
                                  undecomposable);
  if (options_.decompose && undecomposable.empty())
    return sample_by_cells(model_, tables, *region_, options_, random, control);
  SampleResult result;
  long long growth_steps = 0;
  std::vector<Element> grown;
  if (!growth_.empty()) grown = grow(start, random, control, growth_steps, result.growth_moves);
  BirthDeathChain chain(tables, *region_, random, fixed,
                        growth_.empty() ? start : std::vector<Element>{});
  if (!growth_.empty()) chain.add_or_place_near(grown, push_radius_, kPushAttempts);
  const bool automatic = options_.iterations <= 0;
  const long long total = automatic ? 0 : options_.iterations;
  const long long progress_every = automatic ? 10000 : std::max<long long>(1, total / 100);
  StationarityRule rule(options_.max_iterations, options_.run_on && start.empty(),
                        static_cast<int>(model_.categories.size()));
  CompressionSchedule compression(options_.compression);
  long long step = 1;
  for (;; ++step) {
    chain.set_log_boost(compression.log_boost());
    chain.step();
    if (!compression.done()) {
      compression.after_step(step, chain.size());
      if (compression.compressed_for() == step) result.compressed_count = chain.size();
    }
    if (observe_every > 0 && step % observe_every == 0) {
      if (options_.observe_region.isEmpty()) {
        result.observations.push_back(chain.statistics());
      } else {
        std::vector<double> t;
        chain.statistics_in(options_.observe_region, t);
        t.insert(t.end(), chain.statistics().begin(), chain.statistics().end());
        result.observations.push_back(std::move(t));
      }
    }
    if (options_.trace_every > 0 && step % options_.trace_every == 0) {
      result.trace.push_back({step, chain.size(), chain.log_density()});
    }
    if (options_.runaway_count > 0 && chain.size() > options_.runaway_count)
      throw_runaway(model_, chain.size(), options_.runaway_count);
    if (step % progress_every == 0 || step == total) {
      if (control.cancelled()) throw core::Cancelled();
      if (control.progress) control.progress(step, total);
    }
    if (!automatic) {
      if (step >= total) break;
      continue;
    }
    if (!compression.done()) {
      if (step < options_.max_iterations) continue;
      result.stationary = false;
      break;
    }
    const StationarityRule::Verdict verdict =
        rule.after_step(step - compression.finished_at(), chain.size(), chain.statistics());
    if (verdict == StationarityRule::Verdict::keep_going) continue;
    result.stationary = verdict == StationarityRule::Verdict::stationary;
    break;
  }
  result.compression_steps = growth_steps + compression.finished_at();
  result.iterations = step;
  result.trend = rule.last_check();
  if (automatic && control.progress) control.progress(step, step);
  result.moves = chain.moves();
  result.statistics = chain.statistics();
  result.start_kept = chain.start_kept();
  result.start_left_out = chain.start_left_out();
  result.scene = tables_->geometry->shape_space;
  result.scene.elements = chain.elements();
  return result;
}

synthesis::SynthesisResult ShapeProcessSampler::synthesize(
    core::Random& random, const synthesis::ChainControl& control) const {
  return describe(sample(random, control));
}

synthesis::SynthesisResult ShapeProcessSampler::describe(SampleResult sampled) const {
  synthesis::SynthesisResult out;
  out.scene = std::move(sampled.scene);
  out.trace = std::move(sampled.trace);
  out.observations = std::move(sampled.observations);
  out.hidden_elements = static_cast<long long>(sampled.hidden.size());
  synthesis::SynthesisRecord& record = out.record;
  record.method = method();
  record.set_domain(domain_);
  record.iterations = options_.iterations > 0 ? std::to_string(options_.iterations) : "stationary";
  record.options = {{"shift_probability", core::describe(options_.shift_probability)},
                    {"shift_radius", core::describe(shift_radius())}};
  if (tables_->near_births && options_.near_birth_share > 0)
    record.options.emplace_back("near_birth_share", core::describe(options_.near_birth_share));
  record.steps = sampled.iterations;
  record.stationary = sampled.stationary;
  const MoveCounts& m = sampled.moves;
  auto ratio = [](long long a, long long b) { return std::to_string(a) + "/" + std::to_string(b); };
  out.counters = {{"births accepted", ratio(m.births_accepted, m.births_proposed)},
                  {"deaths", ratio(m.deaths_accepted, m.deaths_proposed)},
                  {"shifts", ratio(m.shifts_accepted, m.shifts_proposed)}};
  if (options_.iterations <= 0 && sampled.trend.first > 0) {
    const CountTrend& t = sampled.trend;
    record.options.emplace_back("stationarity", "mean counts " + core::format_general(t.first, 6) +
                                                    " then " + core::format_general(t.second, 6) +
                                                    ", standard error of the change " +
                                                    core::format_general(t.standard_error, 3));
  }
  if (options_.iterations <= 0 && sampled.spacing_trend.first > 0) {
    const CountTrend& t = sampled.spacing_trend;
    record.options.emplace_back("spacing stationarity",
                                "mean nearest distances " + core::format_general(t.first, 6) +
                                    " then " + core::format_general(t.second, 6) +
                                    ", standard error of the change " +
                                    core::format_general(t.standard_error, 3));
  }
  if (options_.compression.enabled()) {
    record.options.emplace_back("burn_in", crystal_ ? "crystal" : "compressing");
    out.counters.emplace_back("compressing burn-in steps",
                              std::to_string(sampled.compression_steps));
    out.counters.emplace_back("elements after compression",
                              std::to_string(sampled.compressed_count));
    const MoveCounts& g = sampled.growth_moves;
    out.counters.emplace_back("growth births accepted",
                              ratio(g.births_accepted, g.births_proposed));
    out.counters.emplace_back("growth deaths", ratio(g.deaths_accepted, g.deaths_proposed));
  }
  if (sampled.cells > 0) {
    out.counters.emplace_back("cells", std::to_string(sampled.cells));
    out.counters.emplace_back("sweeps", std::to_string(sampled.sweeps));
    out.counters.emplace_back("pilot density", core::describe(sampled.pilot_density));
    record.options.emplace_back("decomposition", "cells");
  }
  if (!options_.start.empty()) {
    out.counters.emplace_back("start elements kept", std::to_string(sampled.start_kept));
    out.counters.emplace_back("start elements left out", std::to_string(sampled.start_left_out));
  }
  return out;
}

SampleResult sample_shape_process(const model::ShapeProcessModel& model,
                                  const geometry::Domain& domain, const SamplerOptions& options,
                                  core::Random& random) {
  return ShapeProcessSampler(model, domain, options).sample(random);
}

}  // namespace shapeproc::sample
