#include "libshapeproc/sample/birth_death_sampler.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "libshapeproc/core/check.hpp"
#include "libshapeproc/core/error.hpp"
#include "libshapeproc/geometry/pair_measurements.hpp"
#include "libshapeproc/model/interaction.hpp"
#include "libshapeproc/sample/configuration.hpp"
#include "libshapeproc/sample/stationarity.hpp"

namespace shapeproc::sample {

namespace {
constexpr double kMinusInfinity = -std::numeric_limits<double>::infinity();
}  // namespace

namespace {

// Per category, the cumulative probabilities of its shapes under the model's shape classes
// (empty lists without classes), and the sum of its classes' weights in `weight_sum`. Drawing a
// birth's shape from them and using β_c Σ w in the acceptance ratio samples the density with
// class intensities β_c w_k.
std::vector<std::vector<double>> shape_probabilities(const model::ShapeProcessModel& model,
                                                     const std::vector<std::vector<int>>& shapes_of,
                                                     std::vector<double>& weight_sum) {
  weight_sum.assign(shapes_of.size(), 1.0);
  std::vector<std::vector<double>> cumulative(shapes_of.size());
  if (model.shape_classes.empty()) return cumulative;
  std::vector<int> class_size(model.shape_classes.size(), 0);
  for (const model::ModelShape& s : model.shapes)
    ++class_size[static_cast<std::size_t>(s.shape_class)];
  for (std::size_t c = 0; c < shapes_of.size(); ++c) {
    double total = 0.0;
    for (int s : shapes_of[c]) {
      const std::size_t k =
          static_cast<std::size_t>(model.shapes[static_cast<std::size_t>(s)].shape_class);
      total += model.shape_classes[k].weight / class_size[k];
      cumulative[c].push_back(total);
    }
    for (double& p : cumulative[c]) p /= total;
    weight_sum[c] = 0.0;
    for (const model::ShapeClass& k : model.shape_classes)
      if (k.category == static_cast<int>(c)) weight_sum[c] += k.weight;
  }
  return cumulative;
}

}  // namespace

ShapeProcessSampler::ShapeProcessSampler(const model::ShapeProcessModel& model,
                                         geometry::Domain domain, SamplerOptions options)
    : model_(model), domain_(std::move(domain)), options_(options) {
  model::validate(model_);
  const int dimension = model_.dimension;
  core::check(domain_.dimension() == dimension, "sample",
              "the domain is " + std::to_string(domain_.dimension()) + "D but the model " +
                  std::to_string(dimension) + "D");
  core::check_in_range("sample", "the shift probability", options_.shift_probability, 0.0, 1.0,
                       true);
  core::check_non_negative("sample", "the shift radius", options_.shift_radius);
  core::check(options_.trace_every >= 0 && options_.observe_every >= 0, "sample",
              "trace and observation intervals must be >= 0");

  shape_space_ = model_.shape_space();
  shape_space_.window = domain_.box();
  interaction_ = std::make_unique<const model::Interaction>(model_);
  measurer_ = std::make_unique<const geometry::PairMeasurer>(
      shape_space_, model_.measurement_options(domain_.periodic()));
  double max_radius = 0.0;
  for (std::size_t s = 0; s < shape_space_.shapes.size(); ++s) {
    max_radius = std::max(max_radius, measurer_->radius(static_cast<int>(s)));
  }
  reach_ = interaction_->range() + 2 * max_radius;

  const int categories = static_cast<int>(model_.categories.size());
  shapes_of_.resize(static_cast<std::size_t>(categories));
  if (model_.shapes.empty()) {
    for (auto& list : shapes_of_) list.push_back(0);  // the point shape
  } else {
    for (std::size_t s = 0; s < model_.shapes.size(); ++s) {
      shapes_of_[static_cast<std::size_t>(model_.shapes[s].category)].push_back(
          static_cast<int>(s));
    }
  }
  std::vector<double> weight_sum;
  shape_cumulative_ = shape_probabilities(model_, shapes_of_, weight_sum);
  for (std::size_t c = 0; c < model_.categories.size(); ++c)
    log_beta_.push_back(std::log(model_.categories[c].beta * weight_sum[c]));
  free_region_ = options_.free_region.isEmpty() ? domain_.box() : options_.free_region;
  double free_measure = domain_.measure();
  if (!options_.free_region.isEmpty()) {
    core::check(!domain_.periodic() && !domain_.has_local_factor(), "sample",
                "a free region (border correction) needs a plain open domain");
    core::check(domain_.box().contains(free_region_), "sample",
                "the free region must lie inside the domain");
    free_measure = geometry::measure(free_region_, dimension);
    core::check_positive("sample", "the free region's measure", free_measure);
  }
  for (const geometry::Element& e : options_.fixed) {
    core::check(e.category >= 0 && e.category < categories && e.shape >= 0 &&
                    e.shape < static_cast<int>(shape_space_.shapes.size()),
                "sample", "a fixed element has a category or shape the model does not have");
    core::check(domain_.contains(e.position), "sample", "a fixed element lies outside the domain");
  }
  for (const geometry::Element& e : options_.start)
    core::check(e.category >= 0 && e.category < categories && e.shape >= 0 &&
                    e.shape < static_cast<int>(shape_space_.shapes.size()),
                "sample", "a start element has a category or shape the model does not have");
  log_measure_categories_ = std::log(free_measure) + std::log(static_cast<double>(categories));
  shift_radius_ = options_.shift_radius > 0   ? options_.shift_radius
                  : interaction_->range() > 0 ? 0.5 * interaction_->range()
                                              : 0.05 * domain_.sizes().head(dimension).minCoeff();
}

ShapeProcessSampler::~ShapeProcessSampler() = default;

bool ShapeProcessSampler::torus_smaller_than_reach() const {
  return domain_.periodic() && reach_ > 0 &&
         domain_.sizes().head(model_.dimension).minCoeff() < 2.0 * reach_;
}

// One run of the chain: the configuration, the generator, and the three moves.
class ShapeProcessSampler::Chain {
 public:
  Chain(const ShapeProcessSampler& sampler, core::Random& random)
      : s_(sampler),
        random_(random),
        state_(*sampler.interaction_, *sampler.measurer_, sampler.domain_, sampler.reach_) {
    for (const Element& e : s_.options_.fixed) {
      const double term = log_lambda_over_beta(e, -1);
      if (!std::isfinite(term))
        throw core::ArgumentError("sample", "the fixed elements violate the model's hard core");
      state_.add(e, local_term_, links_);
      log_density_ += s_.log_beta_[static_cast<std::size_t>(e.category)] + term;
    }
    fixed_ = state_.size();
    for (const Element& e : s_.options_.start) {
      const bool free_place = s_.free_region_.isEmpty() ? s_.domain_.contains(e.position)
                                                        : s_.free_region_.contains(e.position);
      const double term = free_place ? log_lambda_over_beta(e, -1) : kMinusInfinity;
      if (!std::isfinite(term)) {
        ++start_left_out_;
        continue;
      }
      state_.add(e, local_term_, links_);
      log_density_ += s_.log_beta_[static_cast<std::size_t>(e.category)] + term;
      ++start_kept_;
    }
  }

  int start_kept() const { return start_kept_; }
  int start_left_out() const { return start_left_out_; }

  // One step: with probability p_s a shift, otherwise a birth or a death with equal probability.
  void step() {
    const double move = random_.uniform();
    const double p = s_.options_.shift_probability;
    if (move < p)
      propose_shift();
    else if ((move - p) < 0.5 * (1.0 - p))
      propose_birth();
    else
      propose_death();
  }

  void propose_birth() {
    ++moves_.births_proposed;
    const int n = state_.size() - fixed_;
    Element xi;
    const geometry::Box3& box = s_.free_region_;
    for (int axis = 0; axis < s_.model_.dimension; ++axis)
      xi.position[axis] = random_.uniform(box.min()[axis], box.max()[axis]);
    xi.category = static_cast<int>(random_.index(s_.shapes_of_.size()));
    const auto& shapes = s_.shapes_of_[static_cast<std::size_t>(xi.category)];
    const auto& cumulative = s_.shape_cumulative_[static_cast<std::size_t>(xi.category)];
    if (cumulative.empty()) {
      xi.shape = shapes[random_.index(shapes.size())];
    } else {  // shapes in proportion to their class's weight (the birth ratio is unchanged)
      const auto at = std::upper_bound(cumulative.begin(), cumulative.end(), random_.uniform());
      xi.shape =
          shapes[std::min(shapes.size() - 1, static_cast<std::size_t>(at - cumulative.begin()))];
    }
    const double log_lambda =
        s_.log_beta_[static_cast<std::size_t>(xi.category)] + log_lambda_over_beta(xi, -1);
    const double log_ratio = log_lambda + s_.log_measure_categories_ - std::log(n + 1.0);
    if (std::isfinite(log_lambda) && std::log(random_.uniform()) < log_ratio) {
      state_.add(xi, local_term_, links_);
      log_density_ += log_lambda;
      ++moves_.births_accepted;
    }
  }

  void propose_death() {
    ++moves_.deaths_proposed;
    const int slot = uniform_slot();
    if (slot < 0) return;
    const int n = state_.size() - fixed_;
    const Element& x = state_.at(slot);
    const double log_lambda =
        s_.log_beta_[static_cast<std::size_t>(x.category)] + state_.log_lambda_over_beta(slot);
    const double log_ratio =
        std::log(static_cast<double>(n)) - s_.log_measure_categories_ - log_lambda;
    if (std::log(random_.uniform()) < log_ratio) {
      log_density_ -= log_lambda;
      state_.remove(slot);
      ++moves_.deaths_accepted;
    }
  }

  void propose_shift() {
    ++moves_.shifts_proposed;
    const int slot = uniform_slot();
    if (slot < 0) return;
    Element moved = state_.at(slot);
    moved.position += offset_in_ball();
    moved.position = s_.domain_.wrap(moved.position);
    const bool inside = s_.domain_.periodic() ||
                        (s_.domain_.contains(moved.position) &&
                         (s_.options_.free_region.isEmpty() || in_free_region(moved.position)));
    const double new_term = inside ? log_lambda_over_beta(moved, slot) : kMinusInfinity;
    if (!std::isfinite(new_term)) return;
    const double old_term = state_.log_lambda_over_beta(slot);
    if (std::log(random_.uniform()) < new_term - old_term) {
      state_.move(slot, moved.position, local_term_, links_);
      log_density_ += new_term - old_term;
      ++moves_.shifts_accepted;
    }
  }

  int size() const { return state_.size(); }
  const std::vector<double>& statistics() const { return state_.statistics(); }
  void statistics_in(const geometry::Box3& region, std::vector<double>& out) const {
    state_.statistics_in(region, out);
  }
  double log_density() const { return log_density_; }
  const MoveCounts& moves() const { return moves_; }
  std::vector<Element> elements() const { return state_.elements(); }

 private:
  // A uniformly chosen element's slot, fixed ones aside (they hold the first ranks: removals
  // swap the last rank into the gap); -1 (and no draw) when there is none.
  int uniform_slot() {
    const int n = state_.size() - fixed_;
    return n == 0 ? -1
                  : state_.slot_of_rank(static_cast<std::size_t>(fixed_) +
                                        random_.index(static_cast<std::uint64_t>(n)));
  }

  bool in_free_region(const Vec3& p) const {
    for (int axis = 0; axis < s_.model_.dimension; ++axis)
      if (p[axis] < s_.free_region_.min()[axis] || p[axis] > s_.free_region_.max()[axis])
        return false;
    return true;
  }

  // Uniform in the ball of radius ρ, by rejection from its bounding cube.
  Vec3 offset_in_ball() {
    const double radius = s_.shift_radius_;
    Vec3 offset = Vec3::Zero();
    do {
      for (int axis = 0; axis < s_.model_.dimension; ++axis)
        offset[axis] = radius * (2.0 * random_.uniform() - 1.0);
    } while (offset.squaredNorm() > radius * radius);
    return offset;
  }

  // log of the domain's local factor of β at the element: −∞ outside the mask or where the
  // intensity map is black.
  double log_local_factor(const Element& e) const {
    const geometry::Domain& domain = s_.domain_;
    double factor = 0.0;
    if (domain.intensity()) {
      const double v = domain.intensity_at(e.position.head<2>());
      if (!(v > 0.0)) return kMinusInfinity;
      factor = std::log(v);
    }
    if (domain.mask() &&
        !domain.contains(s_.measurer_->proxies2()[static_cast<std::size_t>(e.shape)],
                         e.position.head<2>())) {
      return kMinusInfinity;
    }
    return factor;
  }

  // log λ(e | x) − log β_c for a proposed element: the local factor, then (when it is finite) the
  // interactions with every element but `skip`, whose links go to links_. −∞ outside the mask or
  // on a hard core. The local part is kept in local_term_.
  double log_lambda_over_beta(const Element& e, int skip) {
    local_term_ = s_.domain_.has_local_factor() ? log_local_factor(e) : 0.0;
    links_.clear();
    return std::isfinite(local_term_) ? local_term_ + state_.log_interaction(e, skip, links_)
                                      : local_term_;
  }

  const ShapeProcessSampler& s_;
  core::Random& random_;
  Configuration state_;
  std::vector<Link> links_;   // of the last proposal
  double local_term_ = 0.0;   // of the last proposal
  double log_density_ = 0.0;  // unnormalised, tracked incrementally
  int fixed_ = 0;             // fixed elements (border correction), at ranks 0 … fixed_ − 1
  int start_kept_ = 0, start_left_out_ = 0;  // of the start configuration
  MoveCounts moves_;
};

SampleResult ShapeProcessSampler::sample(core::Random& random,
                                         const synthesis::ChainControl& control) const {
  Chain chain(*this, random);
  SampleResult result;
  const bool automatic = options_.iterations <= 0;
  const long long total = automatic ? 0 : options_.iterations;
  const long long progress_every =
      automatic ? 10000 : std::max<long long>(1, options_.iterations / 100);
  StationarityRule rule(options_.max_iterations);
  long long step = 1;
  for (;; ++step) {
    chain.step();
    if (options_.observe_every > 0 && step % options_.observe_every == 0) {
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
    if (step % progress_every == 0 || step == options_.iterations) {
      if (control.cancelled()) throw core::Cancelled();
      if (control.progress) control.progress(step, total);
    }
    if (!automatic) {
      if (step >= options_.iterations) break;
      continue;
    }
    const StationarityRule::Verdict verdict = rule.after_step(step, chain.size());
    if (verdict == StationarityRule::Verdict::keep_going) continue;
    result.stationary = verdict == StationarityRule::Verdict::stationary;
    break;
  }
  result.iterations = step;
  if (automatic && control.progress) control.progress(step, step);
  result.moves = chain.moves();
  result.statistics = chain.statistics();
  result.start_kept = chain.start_kept();
  result.start_left_out = chain.start_left_out();
  result.scene = shape_space_;
  result.scene.elements = chain.elements();
  return result;
}

synthesis::SynthesisResult ShapeProcessSampler::synthesize(
    core::Random& random, const synthesis::ChainControl& control) const {
  SampleResult sampled = sample(random, control);
  synthesis::SynthesisResult out;
  out.scene = std::move(sampled.scene);
  out.trace = std::move(sampled.trace);
  out.observations = std::move(sampled.observations);
  synthesis::SynthesisRecord& record = out.record;
  record.method = method();
  record.set_domain(domain_);
  record.iterations = options_.iterations > 0 ? std::to_string(options_.iterations) : "stationary";
  record.options = {{"shift_probability", core::describe(options_.shift_probability)},
                    {"shift_radius", core::describe(shift_radius_)}};
  record.steps = sampled.iterations;
  record.stationary = sampled.stationary;
  const MoveCounts& m = sampled.moves;
  auto ratio = [](long long a, long long b) { return std::to_string(a) + "/" + std::to_string(b); };
  out.counters = {{"births accepted", ratio(m.births_accepted, m.births_proposed)},
                  {"deaths", ratio(m.deaths_accepted, m.deaths_proposed)},
                  {"shifts", ratio(m.shifts_accepted, m.shifts_proposed)}};
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
