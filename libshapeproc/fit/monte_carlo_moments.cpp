#include "libshapeproc/fit/monte_carlo_moments.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "libshapeproc/core/assert.hpp"
#include "libshapeproc/core/check.hpp"
#include "libshapeproc/fit/effective_sample_size.hpp"
#include "libshapeproc/model/interaction.hpp"
#include "libshapeproc/sample/birth_death_sampler.hpp"
#include "libshapeproc/synthesis/run_chains.hpp"

namespace shapeproc::fit {

namespace {

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

Eigen::Map<const RowMatrix> sample_matrix(const StatisticsMoments& m) {
  return {m.samples.data(), m.observations, m.parameters};
}

Eigen::Map<const RowMatrix> density_matrix(const StatisticsMoments& m) {
  return m.density_samples.empty()
             ? sample_matrix(m)
             : Eigen::Map<const RowMatrix>(m.density_samples.data(), m.observations, m.parameters);
}

// Weighted mean and covariance of the rows of `t` (weights summing to 1), and the information
// Cov(t, u) with the density's statistics `u` (the rows of `t` themselves when `u` is null).
void weighted_moments(const Eigen::Map<const RowMatrix>& t, const Eigen::Map<const RowMatrix>* u,
                      const Eigen::VectorXd& weights, StatisticsMoments& m) {
  const Eigen::VectorXd mean = t.transpose() * weights;
  const RowMatrix centred = t.rowwise() - mean.transpose();
  const double correction = 1.0 / std::max(1e-12, 1.0 - weights.squaredNorm());  // unbiased
  const Eigen::MatrixXd covariance =
      correction * (centred.transpose() * weights.asDiagonal() * centred);
  m.mean.assign(mean.data(), mean.data() + mean.size());
  m.covariance.assign(covariance.data(), covariance.data() + covariance.size());  // symmetric
  if (u) {
    const Eigen::VectorXd u_mean = u->transpose() * weights;
    const RowMatrix u_centred = u->rowwise() - u_mean.transpose();
    const RowMatrix cross = correction * (centred.transpose() * weights.asDiagonal() * u_centred);
    m.information.assign(cross.data(), cross.data() + cross.size());  // row-major
  } else {
    m.information = m.covariance;
  }
  // A statistic every observation holds at one value (a packed exemplar's count, never changed)
  // has that mean and no variance exactly, not sums' rounding: the estimator tells it apart.
  const Eigen::Index p = t.cols();
  for (Eigen::Index k = 0; k < p; ++k) {
    if (t.rows() == 0 || t.col(k).minCoeff() != t.col(k).maxCoeff()) continue;
    m.mean[static_cast<std::size_t>(k)] = t(0, k);
    for (Eigen::Index j = 0; j < p; ++j)
      m.covariance[static_cast<std::size_t>(k * p + j)] =
          m.covariance[static_cast<std::size_t>(j * p + k)] =
              m.information[static_cast<std::size_t>(k * p + j)] = 0.0;
  }
}

}  // namespace

StatisticsMoments statistics_moments(const model::ShapeProcessModel& model,
                                     const geometry::Domain& domain, const ChainsSetting& setting,
                                     const StatisticsMoments* pooled_with) {
  core::check(
      setting.chains >= 1 && setting.steps > 0 && setting.observe_every > 0 && setting.burn_in >= 0,
      "mle", "chains, steps and the observation interval must be positive");
  sample::SamplerOptions sampler_options;
  sampler_options.iterations = setting.burn_in + setting.steps;
  sampler_options.observe_every = setting.observe_every;
  sampler_options.fixed = setting.fixed;
  sampler_options.free_region = setting.free_region;
  if (setting.burn_in_kind != model::BurnIn::plain) {
    core::check(setting.burn_in >= 4, "mle", "the compressing burn-in needs a burn-in of 4 steps");
    sampler_options.compression.burn_in_kind = setting.burn_in_kind;
    sampler_options.compression.release_steps = setting.burn_in / 4;
  }
  sampler_options.observe_region = setting.observe_region;
  sampler_options.geometry = setting.geometry;
  const bool windowed = !setting.observe_region.isEmpty();
  const sample::ShapeProcessSampler sampler(model, domain, sampler_options);
  synthesis::ChainOptions chains;
  chains.chains = setting.chains;
  chains.threads = setting.threads;
  chains.seed = setting.seed;
  const std::vector<synthesis::SynthesisResult> results = synthesis::run_chains(sampler, chains);

  const std::size_t p = static_cast<std::size_t>(model::Interaction(model).statistic_count());
  StatisticsMoments m;
  if (pooled_with) {
    core::check(pooled_with->parameters == static_cast<int>(p) &&
                    pooled_with->density_samples.empty() == !windowed &&
                    !pooled_with->chain_rows.empty(),
                "mle", "a pooled sample must be an unweighted sample of the same statistics");
    m.samples = pooled_with->samples;
    m.density_samples = pooled_with->density_samples;
    m.chain_rows = pooled_with->chain_rows;
    m.observations = pooled_with->observations;
  }
  m.parameters = static_cast<int>(p);
  const std::size_t skip = static_cast<std::size_t>(setting.burn_in / setting.observe_every);
  std::vector<std::pair<int, int>>& chain_rows = m.chain_rows;
  for (const synthesis::SynthesisResult& result : results) {
    const int first_row = m.observations;
    for (std::size_t i = skip; i < result.observations.size(); ++i) {
      const std::vector<double>& observation = result.observations[i];
      SHAPEPROC_ASSERT(observation.size() == (windowed ? 2 : 1) * p,
                       "an observation holds t (t_W, then t, with an observed region)");
      const double* t = observation.data();  // t_W first when windowed, then the whole t
      m.samples.insert(m.samples.end(), t, t + p);
      if (windowed) m.density_samples.insert(m.density_samples.end(), t + p, t + 2 * p);
      ++m.observations;
    }
    chain_rows.emplace_back(first_row, m.observations);
  }
  core::check(m.observations >= 2, "mle",
              "too few observations: raise the steps or lower the observation interval");
  const Eigen::VectorXd uniform = Eigen::VectorXd::Constant(m.observations, 1.0 / m.observations);
  const Eigen::Map<const RowMatrix> u = density_matrix(m);
  weighted_moments(sample_matrix(m), windowed ? &u : nullptr, uniform, m);
  m.standard_error.assign(p, 0.0);
  m.effective_size.assign(p, static_cast<double>(m.observations));
  for (std::size_t k = 0; k < p; ++k) {
    if (m.covariance[k * p + k] == 0.0) continue;
    const EffectiveSize e =
        effective_size(m.samples, m.parameters, static_cast<int>(k), chain_rows);
    m.standard_error[k] = e.standard_error;
    m.effective_size[k] = e.effective;
  }
  m.r_hat = potential_scale_reduction(m, chain_rows);
  return m;
}

std::vector<double> potential_scale_reduction(const StatisticsMoments& sample,
                                              const std::vector<std::pair<int, int>>& chains) {
  const Eigen::Map<const RowMatrix> t = sample_matrix(sample);
  const Eigen::Index p = t.cols();
  std::vector<double> r(static_cast<std::size_t>(p), 1.0);
  if (chains.size() < 2) return r;
  double n = std::numeric_limits<double>::infinity();  // the shortest chain's length
  for (const auto& [first, last] : chains) n = std::min(n, static_cast<double>(last - first));
  if (n < 2) return r;
  const double m = static_cast<double>(chains.size());
  for (Eigen::Index k = 0; k < p; ++k) {
    std::vector<double> means;
    double within = 0.0;
    for (const auto& [first, last] : chains) {
      const auto column = t.col(k).segment(first, last - first);
      const double mean = column.mean();
      means.push_back(mean);
      within += (column.array() - mean).square().sum() / (last - first - 1) / m;
    }
    double grand = 0.0;
    for (double x : means) grand += x / m;
    double between = 0.0;  // B / n
    for (double x : means) between += (x - grand) * (x - grand) / (m - 1);
    if (within <= 0.0) {
      r[static_cast<std::size_t>(k)] =
          between > 0.0 ? std::numeric_limits<double>::infinity() : 1.0;
      continue;
    }
    r[static_cast<std::size_t>(k)] = std::sqrt(((n - 1) / n * within + between) / within);
  }
  return r;
}

StatisticsMoments reweighted(const StatisticsMoments& sample, const std::vector<double>& delta,
                             double& effective_share) {
  core::check(delta.size() == static_cast<std::size_t>(sample.parameters), "mle",
              "the parameter change has the wrong size");
  const Eigen::Map<const RowMatrix> t = sample_matrix(sample);
  const Eigen::Map<const RowMatrix> u = density_matrix(sample);
  const Eigen::Map<const Eigen::VectorXd> d(delta.data(), sample.parameters);
  Eigen::VectorXd log_w = u * d;  // the density's ratio exp(δ · t) at each observation
  log_w.array() -= log_w.maxCoeff();
  Eigen::VectorXd w = log_w.array().exp();
  w /= w.sum();
  effective_share = 1.0 / (w.squaredNorm() * sample.observations);
  StatisticsMoments m;
  m.parameters = sample.parameters;
  m.observations = sample.observations;
  m.standard_error = sample.standard_error;
  weighted_moments(t, sample.density_samples.empty() ? nullptr : &u, w, m);
  return m;
}

}  // namespace shapeproc::fit
