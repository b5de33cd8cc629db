#include "libshapeproc/fit/mcmc_mle.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "libshapeproc/core/check.hpp"
#include "libshapeproc/model/interaction.hpp"
#include "libshapeproc/sample/birth_death_sampler.hpp"
#include "libshapeproc/synthesis/run_chains.hpp"

namespace shapeproc::fit {

namespace {

constexpr int kBatchesPerChain = 5;

// The model's θ in the Interaction's numbering.
std::vector<double> theta_of(const model::ShapeProcessModel& model) {
  const model::Interaction interaction(model);
  std::vector<double> theta(static_cast<std::size_t>(interaction.parameter_count()));
  for (std::size_t c = 0; c < model.categories.size(); ++c)
    theta[c] = std::log(model.categories[c].beta);
  for (int p = static_cast<int>(model.categories.size()); p < interaction.parameter_count(); ++p) {
    theta[static_cast<std::size_t>(p)] = interaction.log_gamma_of(p);
  }
  return theta;
}

// `model` with θ written into it.
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
}

}  // namespace

StatisticsMoments statistics_moments(const model::ShapeProcessModel& model,
                                     const geometry::Domain& domain, const MleOptions& options) {
  core::check(
      options.chains >= 1 && options.steps > 0 && options.observe_every > 0 && options.burn_in >= 0,
      "mle", "chains, steps and the observation interval must be positive");
  sample::SamplerOptions sampler_options;
  sampler_options.iterations = options.burn_in + options.steps;
  sampler_options.observe_every = options.observe_every;
  const sample::ShapeProcessSampler sampler(model, domain, sampler_options);

  // The chains' observations after the burn-in, in batches.
  synthesis::ChainOptions chains;
  chains.chains = options.chains;
  chains.threads = options.threads;
  chains.seed = options.seed;
  const std::vector<synthesis::SynthesisResult> results = synthesis::run_chains(sampler, chains);
  const std::size_t p = static_cast<std::size_t>(model::Interaction(model).parameter_count());
  std::vector<std::vector<double>> batch_means;
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(p));
  Eigen::MatrixXd outer =
      Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(p), static_cast<Eigen::Index>(p));
  int count = 0;
  for (const synthesis::SynthesisResult& result : results) {
    const std::size_t skip = static_cast<std::size_t>(options.burn_in / options.observe_every);
    const std::size_t kept =
        result.observations.size() > skip ? result.observations.size() - skip : 0;
    const std::size_t per_batch = std::max<std::size_t>(1, kept / kBatchesPerChain);
    std::vector<double> batch(p, 0.0);
    std::size_t in_batch = 0;
    for (std::size_t i = skip; i < result.observations.size(); ++i) {
      const std::vector<double>& t = result.observations[i];
      const Eigen::Map<const Eigen::VectorXd> v(t.data(), static_cast<Eigen::Index>(p));
      sum += v;
      outer += v * v.transpose();
      ++count;
      for (std::size_t k = 0; k < p; ++k) batch[k] += t[k];
      if (++in_batch == per_batch) {
        for (double& b : batch) b /= static_cast<double>(per_batch);
        batch_means.push_back(batch);
        batch.assign(p, 0.0);
        in_batch = 0;
      }
    }
  }
  core::check(count >= 2, "mle",
              "too few observations: raise the steps or lower the observation interval");
  StatisticsMoments m;
  m.observations = count;
  const Eigen::VectorXd mean = sum / count;
  const Eigen::MatrixXd covariance = (outer - count * mean * mean.transpose()) / (count - 1);
  m.mean.assign(mean.data(), mean.data() + mean.size());
  m.covariance.assign(covariance.data(), covariance.data() + covariance.size());  // symmetric
  const double batches = static_cast<double>(batch_means.size());
  m.standard_error.assign(p, 0.0);
  for (std::size_t k = 0; k < p; ++k) {
    double bm = 0.0, bv = 0.0;
    for (const auto& b : batch_means) bm += b[k] / batches;
    for (const auto& b : batch_means) bv += (b[k] - bm) * (b[k] - bm) / std::max(1.0, batches - 1);
    m.standard_error[k] = std::sqrt(bv / batches);
  }
  return m;
}

MleResult maximise_likelihood(const model::ShapeProcessModel& start, const geometry::Domain& window,
                              const std::vector<double>& observed, const MleOptions& options) {
  model::validate(start);
  const model::Interaction interaction(start);
  const std::size_t p = static_cast<std::size_t>(interaction.parameter_count());
  const std::size_t categories = start.categories.size();
  core::check(observed.size() == p, "mle", "the observed statistics have the wrong size");
  for (std::size_t c = 0; c < categories; ++c) {
    core::check(observed[c] > 0, "mle",
                "category '" + start.categories[c].name + "' has no element");
  }
  MleResult r;
  r.observed = observed;
  r.theta = theta_of(start);
  r.status.assign(p, model::ParameterStatus::free);
  r.standard_errors.assign(p, std::numeric_limits<double>::quiet_NaN());
  // Bands without an observed pair: γ = 0 (the likelihood increases without bound as γ → 0).
  std::vector<std::size_t> free;
  for (std::size_t k = 0; k < p; ++k) {
    if (k >= categories && observed[k] <= 0) {
      r.theta[k] = -std::numeric_limits<double>::infinity();
      r.status[k] = model::ParameterStatus::boundary;
    } else {
      free.push_back(k);
    }
  }
  // No interaction parameter: the Poisson MLE in closed form.
  if (p == categories) {
    for (std::size_t c = 0; c < categories; ++c) {
      r.theta[c] = std::log(observed[c] / window.measure());
      r.standard_errors[c] = 1.0 / std::sqrt(observed[c]);
      r.expected.push_back(observed[c]);
      r.expected_error.push_back(0.0);
    }
    r.converged = true;
    return r;
  }
  model::ShapeProcessModel model = start;
  const Eigen::Index n = static_cast<Eigen::Index>(free.size());
  Eigen::MatrixXd information(n, n);
  for (r.iterations = 1; r.iterations <= options.max_iterations; ++r.iterations) {
    set_theta(model, r.theta);
    MleOptions round = options;
    round.seed = options.seed + static_cast<std::uint64_t>(r.iterations) * 1000003ULL;
    const StatisticsMoments m = statistics_moments(model, window, round);
    r.expected = m.mean;
    r.expected_error = m.standard_error;
    Eigen::VectorXd gap(n);
    double worst = 0.0;
    for (Eigen::Index i = 0; i < n; ++i) {
      const std::size_t k = free[static_cast<std::size_t>(i)];
      gap[i] = observed[k] - m.mean[k];
      const double se = std::max(m.standard_error[k], 1e-9);
      worst = std::max(worst, std::abs(gap[i]) / se);
      for (Eigen::Index j = 0; j < n; ++j) {
        information(i, j) = m.covariance[k * p + free[static_cast<std::size_t>(j)]];
      }
    }
    if (options.progress) options.progress(r.iterations, worst);
    const Eigen::LDLT<Eigen::MatrixXd> solver(information + 1e-9 * Eigen::MatrixXd::Identity(n, n));
    if (worst <= options.tolerance) {
      r.converged = true;
      const Eigen::MatrixXd inverse = solver.solve(Eigen::MatrixXd::Identity(n, n));
      for (Eigen::Index i = 0; i < n; ++i) {
        r.standard_errors[free[static_cast<std::size_t>(i)]] =
            std::sqrt(std::max(0.0, inverse(i, i)));
      }
      break;
    }
    Eigen::VectorXd step = solver.solve(gap);
    const double largest = step.cwiseAbs().maxCoeff();
    if (!(largest <= options.max_step)) step *= options.max_step / largest;  // also NaN: no step
    if (!step.allFinite()) step.setZero();
    for (Eigen::Index i = 0; i < n; ++i) r.theta[free[static_cast<std::size_t>(i)]] += step[i];
  }
  r.iterations = std::min(r.iterations, options.max_iterations);
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
  return model;
}

}  // namespace shapeproc::fit
