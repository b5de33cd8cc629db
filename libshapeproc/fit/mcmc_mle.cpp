#include "libshapeproc/fit/mcmc_mle.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "libshapeproc/core/check.hpp"
#include "libshapeproc/core/format.hpp"
#include "libshapeproc/fit/detail/newton_steps.hpp"
#include "libshapeproc/fit/fit_defaults.hpp"
#include "libshapeproc/model/interaction.hpp"
#include "libshapeproc/sample/birth_death_chain.hpp"

namespace shapeproc::fit {

namespace {

// The model's θ in the numbering of its sufficient statistics (Interaction::statistic_count):
// log β per category, log γ per band, then log w per shape class.
std::vector<double> theta_of(const model::ShapeProcessModel& model) {
  const model::Interaction interaction(model);
  std::vector<double> theta(static_cast<std::size_t>(interaction.statistic_count()));
  for (std::size_t c = 0; c < model.categories.size(); ++c)
    theta[c] = std::log(model.categories[c].beta);
  for (int p = static_cast<int>(model.categories.size()); p < interaction.parameter_count(); ++p) {
    theta[static_cast<std::size_t>(p)] = interaction.log_gamma_of(p);
  }
  for (std::size_t k = 0; k < model.shape_classes.size(); ++k)
    theta[static_cast<std::size_t>(interaction.parameter_count()) + k] =
        std::log(model.shape_classes[k].weight);
  return theta;
}

// `model` with θ written into it (class weights as they are, not normalised).
void set_theta(model::ShapeProcessModel& model, const std::vector<double>& theta) {
  const model::Interaction interaction(model);
  for (int p = 0; p < interaction.parameter_count(); ++p) {
    const model::Interaction::Location where = interaction.locate(p);
    const double value = std::exp(theta[static_cast<std::size_t>(p)]);
    if (where.pair < 0) {
      model.categories[static_cast<std::size_t>(where.axis)].beta = value;
    } else {
      model.interactions[static_cast<std::size_t>(where.pair)]
          .axes[static_cast<std::size_t>(where.axis)]
          .gammas[static_cast<std::size_t>(where.band)] = value;
    }
  }
  for (std::size_t k = 0; k < model.shape_classes.size(); ++k)
    model.shape_classes[k].weight =
        std::exp(theta[static_cast<std::size_t>(interaction.parameter_count()) + k]);
}

}  // namespace

namespace {

using detail::Gap;
using detail::kMinEffectiveShare;
using detail::kNoInformation;
using detail::Newton;

constexpr long long kRoughDivisor = 4;  // first simulations: a quarter of the steps
constexpr double kNotablyMoved = 0.5;   // the prior moved a band by half a pair or more
constexpr int kUnreachableAfter = 4;    // simulations without variance: unreachable
// Compressed chains short of the exemplar's count (unreached below).
constexpr std::size_t kUnreachedAfter = 8, kStallWindow = 4;
constexpr double kReachedShare = 0.9, kStalledGain = 0.02;
constexpr std::size_t kAveraged = 8;  // estimates averaged in the final phase
constexpr int kStalledAfter = 2;      // rough simulations without progress end that phase…
constexpr double kNearTolerance = 2;  // …when the gap is within this many tolerances
constexpr double kDiverged = 10;      // a gap this many times the best one undoes the step
// Chains that disagree more than this (R-hat) are not at one stationary state: a model that
// holds a packed exemplar in some chains and loses it in others, or chains still drifting. Their
// errors are then inflated by the disagreement, and small z would be no evidence.
constexpr double kMaxRHat = kFitDefaults.max_r_hat;
// A gap within the tolerance counts only when every free statistic's sample is worth this many
// independent observations (effective_sample_size.hpp): chains at a packed exemplar's density
// that mix slowly give errors as large as the gaps
// themselves, and a test passed with them says nothing. Such a sample gets more chains at the same
// θ (more_chains), pooled with its own, up to kMostChainFactor times the setting's; the
// simulations after it run that many, half of them first (first_round).
// A statistic whose mean is known to within kNegligibleGap (mcmc_mle.hpp) is trusted whatever its
// effective size: a packed lattice's count that the chains leave once in a long while has almost
// no variance and almost no effective observations.
constexpr double kMinEffectiveSize = kFitDefaults.min_effective_size;
constexpr int kMostChainFactor = 16;
// A crystal's search stops untested (MleResult::held_crystal) only where every category's
// expected count is within this share of the exemplar's: its few effective observations give
// errors too wide to judge the gap, so it is judged against the count. cutout's chains held 20.3
// of 18 elements (z 1.8, within the tolerance) and its outputs came out ×1.5; tested further, the
// search found ×0.99.
constexpr double kHeldCrystalShare = kFitDefaults.held_crystal_share;

using Clock = std::chrono::steady_clock;

// The chains a sample of `have` chains worth `effective` independent observations grows to, to be
// worth kMinEffectiveSize at the observations it is worth per chain, but at most doubled at a
// time (at most `most`), in pairs for two cores: a few chains held at different states
// understate what each is worth (dashes-rows: 4 chains worth 2.6, 32 worth 32), and a jump to
// the estimate overshot by up to ten times (two-kinds at seed 3: 4 chains worth 4.5 grew to 20
// worth 49–209).
int more_chains(int have, double effective, int most) {
  const double per_chain = std::max(effective, 0.5) / have;
  const int wanted = static_cast<int>(std::ceil((kMinEffectiveSize - effective) / per_chain));
  int add = std::clamp(wanted, 2, have);
  add += add % 2;
  return std::min(most, have + add);
}

// The chains of the first simulation at a new θ: half of `chains` (in pairs, at least the
// setting's) once a sample has grown to more. The chains' worth changes with θ near a phase
// transition (rings at seed 1: 24 chains worth 24 observations at one θ, 247 at the next), and
// where half are worth kMinEffectiveSize the rest are not run; otherwise they follow at the
// same θ, pooled, before anything is decided.
int first_round(int chains, const MleOptions& options) {
  const int setting = options.sampling.chains;
  if (chains <= setting) return chains;
  const int half = (chains + 1) / 2;
  return std::max(setting, half + half % 2);
}

// Why a start is condensed: some category's mean count over `ratio` times the exemplar's, as
// "its start condensed (68.2 elements against 19)"; empty when none is.
std::string condensed_start(const StatisticsMoments& m, const std::vector<double>& observed,
                            std::size_t categories, double ratio) {
  for (std::size_t c = 0; c < categories; ++c) {
    if (m.mean[c] > ratio * observed[c])
      return "its start condensed (" + core::format_general(m.mean[c], 3) + " elements against " +
             core::format_general(observed[c], 3) + ")";
  }
  return {};
}

// Compressed chains that stay short of the exemplar's count: "" while they may still reach it,
// else the reason to give up. `reached` holds, per simulation so far, the smallest share of a
// category's observed count the chains' mean reached. Given up after at least kUnreachedAfter
// simulations when no share reached kReachedShare and the last kStallWindow gained under
// kStalledGain on the best before them (a jammed exemplar: pushing β on does not add elements).
std::string unreached(const std::vector<double>& reached, const StatisticsMoments& m,
                      const std::vector<double>& observed, std::size_t categories) {
  if (reached.size() < kUnreachedAfter) return {};
  const auto window = reached.end() - static_cast<std::ptrdiff_t>(kStallWindow);
  const double before = *std::max_element(reached.begin(), window);
  const double after = *std::max_element(window, reached.end());
  if (std::max(before, after) >= kReachedShare || after > before + kStalledGain) return {};
  std::string counts;
  for (std::size_t c = 0; c < categories; ++c)
    counts += (c ? ", " : "") + core::format_general(m.mean[c], 3) + " elements against " +
              core::format_general(observed[c], 3);
  return "its chains, from empty through the compressing burn-in, stay short of the exemplar's "
         "count (" +
         counts + ") however large β grows";
}

}  // namespace

double convergence_tolerance(double significance, std::size_t components) {
  core::check_in_range("mle", "the significance level", significance, 0.0, 1.0, false);
  const double tail = significance / static_cast<double>(std::max<std::size_t>(1, components));
  double low = 0.0, high = 40.0;  // P(|Z| > z) = erfc(z / √2) falls from 1 to 0
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (low + high);
    (std::erfc(mid / std::sqrt(2.0)) > tail ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

namespace {

// Every category and shape class must hold an element of the exemplar.
void check_observed(const model::ShapeProcessModel& start, const std::vector<double>& observed,
                    std::size_t p, std::size_t parameters) {
  core::check(observed.size() == p, "mle", "the observed statistics have the wrong size");
  for (std::size_t c = 0; c < start.categories.size(); ++c) {
    core::check(observed[c] > 0, "mle",
                "category '" + start.categories[c].name + "' has no element");
  }
  for (std::size_t k = parameters; k < p; ++k)
    core::check(observed[k] > 0, "mle",
                "shape class " + std::to_string(k - parameters) + " has no element");
}

// No interaction parameter: the Poisson MLE in closed form, β_c = n_c / |W|, w_k = n_k / n_c
// (without border correction: with it the fixed elements would have to be set apart).
void poisson_closed_form(const model::ShapeProcessModel& start, const geometry::Domain& window,
                         const MleOptions& options, MleResult& r) {
  const std::vector<double>& observed = r.observed;
  const std::size_t categories = start.categories.size(), p = observed.size();
  const std::size_t parameters = categories;
  const double measure =
      options.sampling.observe_region.isEmpty()
          ? window.measure()
          : geometry::measure(options.sampling.observe_region, window.dimension());
  for (std::size_t c = 0; c < categories; ++c) {
    r.theta[c] = std::log(observed[c] / measure);
    r.standard_errors[c] = 1.0 / std::sqrt(observed[c]);
    r.status[c] = model::ParameterStatus::free;
  }
  for (std::size_t k = parameters; k < p; ++k) {
    const std::size_t c = static_cast<std::size_t>(start.shape_classes[k - parameters].category);
    r.theta[k] = std::log(observed[k] / observed[c]);
    r.standard_errors[k] = std::sqrt(1.0 / observed[k] - 1.0 / observed[c]);
  }
  r.expected = observed;
  r.expected_error.assign(p, 0.0);
  r.converged = true;
}

// A statistic every observation of the last simulation held at the exemplar's value: the
// likelihood still grows beyond θ_k, so the MLE is infinite; θ_k is the value at which the
// chains held it, with no error.
void mark_unbounded(const std::vector<std::size_t>& free, MleResult& r) {
  for (std::size_t k : free) {
    if (r.expected_error[k] == 0 &&
        std::abs(r.expected[k] - r.observed[k]) <= 1e-9 * std::max(1.0, r.observed[k])) {
      r.status[k] = model::ParameterStatus::unbounded;
      r.standard_errors[k] = std::numeric_limits<double>::quiet_NaN();
    }
  }
}

}  // namespace

namespace {

// One iterate of the search: its θ, the expectations simulated there and how close they came.
struct Iterate {
  std::vector<double> theta, expected, expected_error;
  int chains = 0;
  double worst_z = std::numeric_limits<double>::infinity();
  double worst_r_hat = std::numeric_limits<double>::infinity();
  double ranking_z = std::numeric_limits<double>::infinity();
};

// The Monte Carlo search for the maximum likelihood: simulations at θ, Newton steps on their
// moments (reweighted between simulations), the rough and final phases and their stopping rules.
class LikelihoodSearch {
 public:
  // `r` holds the observed statistics, the start θ and the statuses; `free` the free components.
  LikelihoodSearch(const model::ShapeProcessModel& start, const geometry::Domain& window,
                   const MleOptions& options, std::size_t categories, std::size_t parameters,
                   std::vector<std::size_t> free, MleResult& r);
  // Iterates until convergence, a cap or a reason to give up.
  void run();
  // The result's θ, expectations and statuses once the loop has ended.
  void finish();

 private:
  enum class Next { again, stop, decide };
  // The simulation of an iteration; false when it only grew a sample that needs more chains.
  bool simulate(StatisticsMoments& m, double& effective);
  Next drop_unreachable(const StatisticsMoments& m);
  // What a simulation's moments decide: give up, undo the step, converge, or step on.
  Next decide(StatisticsMoments& m, double effective);
  void converge(const StatisticsMoments& m, const Gap& g);
  std::vector<double> mean_of_estimates() const;
  double ranking_z(const StatisticsMoments& m, const Gap& g) const;
  double worst_r_hat(const StatisticsMoments& m) const;
  // Whether every category's expected count is within kHeldCrystalShare of the exemplar's.
  bool counts_held(const StatisticsMoments& m) const;
  double least_effective(const StatisticsMoments& m) const;
  double seconds() const { return std::chrono::duration<double>(Clock::now() - clock_).count(); }

  const Clock::time_point clock_ = Clock::now();
  const geometry::Domain& window_;
  const MleOptions& options_;
  MleResult& r_;
  const std::vector<double>& observed_;
  const std::size_t categories_, parameters_, p_;
  std::vector<std::size_t> free_;
  std::optional<Newton> newton_;
  const std::vector<double> start_theta_;
  std::vector<int> unvaried_;  // consecutive simulations in which t_k never varied
  model::ShapeProcessModel model_;
  bool rough_ = true;
  int stalled_ = 0;              // simulations since the gap last shrank
  int diverged_ = 0;             // steps undone by the step control
  std::vector<double> reached_;  // per simulation: the least share of a count reached (unreached)
  // Final phase: each simulation gives one estimate of the MLE (the maximum of its reweighted
  // likelihood), whose Monte Carlo error is as large as the gap's; the next simulation runs at
  // the mean of the last kAveraged estimates, so that the error of θ shrinks below the test's.
  std::vector<std::vector<double>> estimates_;
  // By the gap: ranking iterates whose chains agree first picked, on crescents-grid, an early
  // one where every chain had lost the exemplar alike (|z| 538).
  Iterate best_;
  double last_r_hat_ = 1.0;
  // More chains where the sample is worth too few independent observations: the chains of each
  // simulation from then on, and the sample at the current θ that chains are added to.
  int chains_;
  const int most_chains_;
  std::optional<StatisticsMoments> added_to_;
  // Every simulation samples the same shapes on the same window: one set of proxies for all.
  std::shared_ptr<const sample::ChainGeometry> geometry_;
  int rests_ = 0;  // simulations that ran the rest of a first round's chains (not iterations)
};

LikelihoodSearch::LikelihoodSearch(const model::ShapeProcessModel& start,
                                   const geometry::Domain& window, const MleOptions& options,
                                   std::size_t categories, std::size_t parameters,
                                   std::vector<std::size_t> free, MleResult& r)
    : window_(window),
      options_(options),
      r_(r),
      observed_(r.observed),
      categories_(categories),
      parameters_(parameters),
      p_(r.observed.size()),
      free_(std::move(free)),
      start_theta_(r.theta),
      unvaried_(r.observed.size(), 0),
      model_(start),
      chains_(options.sampling.chains),
      most_chains_(kMostChainFactor * options.sampling.chains) {
  newton_.emplace(observed_, free_, categories_, parameters_, options_);
  r_.tolerance = convergence_tolerance(options_.significance, free_.size());
  geometry_ = options_.sampling.geometry ? options_.sampling.geometry
                                         : std::make_shared<const sample::ChainGeometry>(
                                               model_, model::Interaction(model_), window_);
}

std::vector<double> LikelihoodSearch::mean_of_estimates() const {
  const std::size_t first = estimates_.size() > kAveraged ? estimates_.size() - kAveraged : 0;
  std::vector<double> mean = estimates_.back();
  for (std::size_t k : free_) {
    double sum = 0.0;
    for (std::size_t e = first; e < estimates_.size(); ++e) sum += estimates_[e][k];
    mean[k] = sum / static_cast<double>(estimates_.size() - first);
  }
  return mean;
}

// The largest |z| with each error no larger than a sample worth kMinEffectiveSize independent
// observations would give: a sample of too few has large errors, and every gap looks small in
// them; ranked this way it still competes, on the precision it should have had. The spread is
// capped at a Poisson count's of the exemplar's size: chains split between a sparse and a
// condensed state have a spread as large as their gap (two-kinds on its torus: 34.8 ± 14 red
// discs against 17, ranked best and returned), and the gap is measured against the count.
double LikelihoodSearch::ranking_z(const StatisticsMoments& m, const Gap& g) const {
  double worst = 0.0;
  for (std::size_t i = 0; i < free_.size(); ++i) {
    const std::size_t k = free_[i];
    const double spread =
        std::sqrt(std::min(std::max(0.0, m.covariance[k * p_ + k]), std::max(observed_[k], 1.0)) /
                  kMinEffectiveSize);
    const double se =
        std::max(std::min(m.standard_error[k], std::max(spread, kNegligibleGap)), 1e-9);
    worst = std::max(worst, std::abs(g.gap[static_cast<Eigen::Index>(i)]) / se);
  }
  return worst;
}

bool LikelihoodSearch::counts_held(const StatisticsMoments& m) const {
  for (std::size_t c = 0; c < categories_; ++c)
    if (std::abs(m.mean[c] - observed_[c]) > kHeldCrystalShare * observed_[c]) return false;
  return true;
}

double LikelihoodSearch::worst_r_hat(const StatisticsMoments& m) const {
  double worst = 1.0;
  for (std::size_t k : free_)
    if (k < m.r_hat.size()) worst = std::max(worst, m.r_hat[k]);
  return worst;
}

double LikelihoodSearch::least_effective(const StatisticsMoments& m) const {
  double least = std::numeric_limits<double>::infinity();
  for (std::size_t k : free_)
    if (k < m.effective_size.size() && m.standard_error[k] > kNegligibleGap)
      least = std::min(least, m.effective_size[k]);
  return least;
}

bool LikelihoodSearch::simulate(StatisticsMoments& m, double& effective) {
  set_theta(model_, r_.theta);
  ChainsSetting setting = options_.sampling;
  setting.geometry = geometry_;
  const int simulation = r_.iterations + rests_;
  setting.seed = options_.sampling.seed + static_cast<std::uint64_t>(simulation) * 1000003ULL;
  setting.chains = added_to_ ? chains_ - added_to_->chains() : first_round(chains_, options_);
  if (rough_) setting.steps = std::max(setting.observe_every * 2, setting.steps / kRoughDivisor);
  m = statistics_moments(model_, window_, setting, added_to_ ? &*added_to_ : nullptr);
  added_to_.reset();
  effective = least_effective(m);
  if (m.chains() < chains_ && effective < kMinEffectiveSize) {
    added_to_ = std::move(m);  // the rest of the chains, at the same θ, before any decision
    ++rests_;
    --r_.iterations;  // one iteration, in two simulations
    return false;
  }
  r_.expected = m.mean;
  r_.expected_error = m.standard_error;
  return true;
}

// Statistics the chains never vary, simulation after simulation, while their parameter is
// pushed towards the exemplar's count: unreachable (a jammed exemplar). They leave the free set
// at their start value, and the next simulation runs without them.
LikelihoodSearch::Next LikelihoodSearch::drop_unreachable(const StatisticsMoments& m) {
  bool dropped = false;
  for (std::size_t k : free_) {
    const bool never = m.covariance[k * p_ + k] <= kNoInformation && observed_[k] != m.mean[k];
    unvaried_[k] = never ? unvaried_[k] + 1 : 0;
    if (unvaried_[k] >= kUnreachableAfter) {
      r_.status[k] = model::ParameterStatus::unreachable;
      r_.theta[k] = start_theta_[k];
      dropped = true;
    }
  }
  if (!dropped) return Next::decide;
  free_.erase(std::remove_if(free_.begin(), free_.end(),
                             [&](std::size_t k) {
                               return r_.status[k] == model::ParameterStatus::unreachable;
                             }),
              free_.end());
  newton_.emplace(observed_, free_, categories_, parameters_, options_);
  r_.tolerance = convergence_tolerance(options_.significance, free_.size());
  return free_.empty() ? Next::stop : Next::again;
}

LikelihoodSearch::Next LikelihoodSearch::decide(StatisticsMoments& m, double effective) {
  const Gap g = newton_->gap(m, r_.theta);
  if (options_.progress)
    options_.progress({r_.iterations, g.worst_z, effective, m.chains(), seconds()});
  const Iterate here{r_.theta,  m.mean,         m.standard_error, m.chains(),
                     g.worst_z, worst_r_hat(m), ranking_z(m, g)};
  const bool improved = here.ranking_z < best_.ranking_z;
  last_r_hat_ = here.worst_r_hat;
  r_.chains = here.chains;
  if (improved) best_ = here;
  if (options_.sampling.burn_in_kind != model::BurnIn::plain) {
    double share = std::numeric_limits<double>::infinity();
    for (std::size_t c = 0; c < categories_; ++c)
      if (observed_[c] > 0) share = std::min(share, m.mean[c] / observed_[c]);
    reached_.push_back(share);
    r_.abandoned = unreached(reached_, m, observed_, categories_);
    if (!r_.abandoned.empty()) return Next::stop;
  }
  if (r_.iterations == 1 && options_.abandon_condensed_start > 0) {
    r_.abandoned = condensed_start(m, observed_, categories_, options_.abandon_condensed_start);
    if (!r_.abandoned.empty()) return Next::stop;
  }
  // Step control: a step that made the gap much worse than the best iterate's is undone, and
  // the steps from there are halved (a jammed exemplar's chains can otherwise be thrown to
  // parameters where they hold almost nothing and the gaps explode).
  if (here.ranking_z > kDiverged * best_.ranking_z && g.worst_z > r_.tolerance) {
    if (++diverged_ == options_.abandon_after_diverged) {
      r_.abandoned = "its steps diverging";
      return Next::stop;
    }
    r_.theta = best_.theta;
    newton_->shorten_steps();
    return Next::again;
  }
  // The rough phase ends at the tolerance, or where the gap stops shrinking near it (its noise
  // floor); far from it (a sampler that cannot mix), the simulations stay short.
  stalled_ = improved ? 0 : stalled_ + 1;
  if (rough_ && g.worst_z > r_.tolerance && g.worst_z < kNearTolerance * r_.tolerance &&
      stalled_ >= kStalledAfter) {
    rough_ = false;
  }
  if (g.worst_z <= r_.tolerance) {
    if (rough_) {
      rough_ = false;  // within tolerance at a quarter of the precision: check at full length
      return Next::again;
    }
    if (effective < kMinEffectiveSize && options_.sampling.burn_in_kind == model::BurnIn::crystal &&
        counts_held(m)) {
      r_.held_crystal = true;
      return Next::stop;
    }
    if (effective < kMinEffectiveSize && chains_ < most_chains_) {
      chains_ = more_chains(m.chains(), effective, most_chains_);
      added_to_ = std::move(m);  // the same θ again, with a sample whose test means something
      estimates_.clear();        // those of the smaller samples would hold the average back
      return Next::again;
    }
  }
  // R-hat is asked of the setting's chains only. R-hat² is about 1 + 1 / (what one chain is
  // worth), so R-hat ≤ 1.1 asks every chain to be worth about 5 observations, which more chains
  // cannot give; a sample grown to more chains has its disagreement in its errors (the
  // multi-chain effective size, from 7 or more degrees of freedom) and its test passes on 20
  // effective observations.
  const bool chains_agree = here.worst_r_hat <= kMaxRHat || m.chains() > options_.sampling.chains;
  if (g.worst_z <= r_.tolerance && chains_agree && effective >= kMinEffectiveSize) {
    converge(m, g);
    return Next::stop;
  }
  const bool last = r_.iterations == options_.max_iterations || seconds() > options_.max_seconds;
  if (last) return Next::stop;  // θ stays where the reported expectations were estimated
  if (rough_ || g.worst_z > kNearTolerance * r_.tolerance) {
    // Far from the tolerance the steps are not noise to be averaged away: a larger sample
    // (more chains) that finds a gap the smaller ones hid moves θ at full steps again.
    estimates_.clear();
    r_.theta = newton_->reweighted_steps(m, g, r_.theta);
  } else {
    estimates_.push_back(newton_->reweighted_steps(m, g, r_.theta));
    r_.theta = mean_of_estimates();
  }
  return Next::again;
}

// The estimate: the maximum of the likelihood as the final sample approximates it (Geyer &
// Thompson), averaged with the final phase's earlier estimates, where the sample's reweighting
// stays valid; otherwise the converged θ.
void LikelihoodSearch::converge(const StatisticsMoments& m, const Gap& g) {
  r_.converged = true;
  estimates_.push_back(newton_->reweighted_steps(m, g, r_.theta));
  const std::vector<double> polished = mean_of_estimates();
  std::vector<double> delta(p_, 0.0);
  for (std::size_t k : free_) delta[k] = polished[k] - r_.theta[k];
  double share = 1.0;
  const StatisticsMoments at = reweighted(m, delta, share);
  if (share >= kMinEffectiveShare) {
    r_.theta = polished;
    r_.expected = at.mean;
    newton_->standard_errors(newton_->gap(at, r_.theta), m, r_.standard_errors);
  } else {
    newton_->standard_errors(g, m, r_.standard_errors);
  }
}

void LikelihoodSearch::run() {
  for (r_.iterations = 1; r_.iterations <= options_.max_iterations; ++r_.iterations) {
    StatisticsMoments m;
    double effective = 0.0;
    if (!simulate(m, effective)) continue;
    Next next = drop_unreachable(m);
    if (next == Next::decide) next = decide(m, effective);
    if (next == Next::stop) break;
  }
}

void LikelihoodSearch::finish() {
  r_.iterations = std::min(r_.iterations, options_.max_iterations);
  if (!r_.converged) {  // the iterate closest to the exemplar, not the last one
    r_.theta = best_.theta;
    r_.expected = best_.expected;
    r_.expected_error = best_.expected_error;
    r_.chains = best_.chains;
  }
  r_.worst_r_hat = r_.converged ? last_r_hat_ : best_.worst_r_hat;
  for (std::size_t k : free_) r_.penalised[k] = newton_->pairs_moved(k, r_.theta) >= kNotablyMoved;
  if (r_.converged) mark_unbounded(free_, r_);
  r_.seconds = seconds();
}

}  // namespace

MleResult maximise_likelihood(const model::ShapeProcessModel& start, const geometry::Domain& window,
                              const std::vector<double>& observed, const MleOptions& options) {
  model::validate(start);
  const model::Interaction interaction(start);
  const std::size_t p = static_cast<std::size_t>(interaction.statistic_count());
  const std::size_t parameters = static_cast<std::size_t>(interaction.parameter_count());
  const std::size_t categories = start.categories.size();
  const bool classes = p > parameters;
  check_observed(start, observed, p, parameters);
  MleResult r;
  r.observed = observed;
  r.theta = theta_of(start);
  r.status.assign(p, model::ParameterStatus::free);
  r.standard_errors.assign(p, std::numeric_limits<double>::quiet_NaN());
  r.penalised.assign(p, false);
  // Free: the class weights instead of the β where there are classes (β_c fixed: the classes'
  // intensities β_c w_k carry the category's). Bands without an observed pair: γ = 0 (the
  // likelihood increases without bound as γ → 0).
  std::vector<std::size_t> free;
  for (std::size_t k = 0; k < p; ++k) {
    if (k < categories && classes) {
      r.status[k] = model::ParameterStatus::fixed;
    } else if (k >= categories && k < parameters && observed[k] <= 0) {
      r.theta[k] = -std::numeric_limits<double>::infinity();
      r.status[k] = model::ParameterStatus::boundary;
    } else {
      free.push_back(k);
    }
  }
  // No interaction parameter: the closed form.
  if (parameters == categories && options.sampling.fixed.empty()) {
    poisson_closed_form(start, window, options, r);
    return r;
  }
  LikelihoodSearch search(start, window, options, categories, parameters, std::move(free), r);
  search.run();
  search.finish();
  return r;
}

model::ShapeProcessModel with_estimates(model::ShapeProcessModel model, const MleResult& mle) {
  set_theta(model, mle.theta);
  const model::Interaction interaction(model);
  for (int p = 0; p < interaction.parameter_count(); ++p) {
    const model::Interaction::Location where = interaction.locate(p);
    const std::size_t k = static_cast<std::size_t>(p);
    if (where.pair < 0) {
      model::CategoryParameters& c = model.categories[static_cast<std::size_t>(where.axis)];
      c.beta_status = mle.status[k];
      c.beta_standard_error = c.beta * mle.standard_errors[k];
    } else {
      model::AxisParameters& a = model.interactions[static_cast<std::size_t>(where.pair)]
                                     .axes[static_cast<std::size_t>(where.axis)];
      const std::size_t band = static_cast<std::size_t>(where.band);
      a.status[band] = mle.status[k];
      a.gamma_standard_errors[band] = a.gammas[band] * mle.standard_errors[k];
    }
  }
  // With shape classes: β_c ← β_c Σ w, w ← w / Σ w over the category's classes; the standard
  // error of log β_c from the classes' (their covariances neglected).
  const std::size_t parameters = static_cast<std::size_t>(interaction.parameter_count());
  for (std::size_t c = 0; c < model.categories.size(); ++c) {
    double total = 0.0, variance = 0.0;
    for (const model::ShapeClass& k : model.shape_classes)
      if (k.category == static_cast<int>(c)) total += k.weight;
    if (total <= 0) continue;
    for (std::size_t k = 0; k < model.shape_classes.size(); ++k) {
      model::ShapeClass& shape_class = model.shape_classes[k];
      if (shape_class.category != static_cast<int>(c)) continue;
      const double share = shape_class.weight / total;
      const double se = mle.standard_errors[parameters + k];
      variance += share * share * se * se;
      shape_class.weight = share;
    }
    model::CategoryParameters& category = model.categories[c];
    category.beta *= total;
    category.beta_status = mle.converged ? model::ParameterStatus::free : category.beta_status;
    category.beta_standard_error = category.beta * std::sqrt(variance);
  }
  return model;
}

}  // namespace shapeproc::fit
