// Monte Carlo moments of the sufficient statistics t(X) of a shape-process model: chains of the
// project's sampler on a domain, their observations of t after the burn-in, means with their Monte
// Carlo standard errors (effective_sample_size.hpp), and importance reweighting of the same
// observations to a nearby θ (Geyer & Thompson 1992): for θ' = θ + δ the weights w_j ∝ exp(δ · t_j)
// turn the sample at θ into estimates at θ', valid while the effective sample size stays a large
// share of the sample.
#pragma once

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/model/burn_in.hpp"
#include "libshapeproc/model/shape_process_model.hpp"

namespace shapeproc::sample {
struct ChainGeometry;
}  // namespace shapeproc::sample

namespace shapeproc::fit {

struct ChainsSetting {
  int chains = 4;
  int threads = 0;  // 0: one per core
  std::uint64_t seed = 1;
  long long burn_in = 20000;      // steps of each chain before observations count
  long long steps = 50000;        // steps of each chain after the burn-in
  long long observe_every = 100;  // steps between observations of t(x)
  // Border correction: elements held fixed and the region the chains sample
  // (sample::SamplerOptions); empty: none.
  std::vector<geometry::Element> fixed;
  geometry::Box3 free_region;
  // Every chain starts empty; unless plain, the first half of its burn-in is the compressing
  // burn-in (model/burn_in.hpp, sample/compression.hpp: a phase at an annealed β, then its
  // release), so that a packed exemplar's density is reached from no position of the exemplar.
  model::BurnIn burn_in_kind = model::BurnIn::plain;
  // The stationary window (docs/fit.md, "Stationary window"): when set, the chains sample a
  // domain larger than the exemplar's window, and the statistics observed are those of the
  // elements in this region (the window) and their pairs there, t_W, while the model's density
  // is that of the whole domain's t; empty: t of the whole domain.
  geometry::Box3 observe_region;
  // The proxies of the model's shapes on the domain (sample::SamplerOptions::geometry), shared
  // by the simulations of one fit; empty: each builds its own.
  std::shared_ptr<const sample::ChainGeometry> geometry;
};

// Observations of t(X) and their moments.
struct StatisticsMoments {
  int parameters = 0;
  std::vector<double> samples;         // row-major, observations x parameters
  std::vector<double> mean;            // by θ index
  std::vector<double> standard_error;  // of the mean (effective_sample_size.hpp)
  // Per statistic, the observations' worth in independent ones (effective_sample_size.hpp): small
  // where the chains sit in different states and rarely leave them (a packed state reached by
  // some chains and not by others), so that no mean of this sample is yet to be trusted. The
  // number of observations for a constant statistic; empty after reweighting.
  std::vector<double> effective_size;
  std::vector<double> covariance;  // row-major, parameters x parameters
  // ∂E_θ[t_W]/∂θ = Cov(t_W, t), row-major (rows t_W, columns t), t the density's statistic:
  // the covariance itself without an observed region.
  std::vector<double> information;
  // Without an observed region empty; with one, t of the whole domain per observation (the
  // statistic the density exponentiates, for reweighting), row-major like `samples`.
  std::vector<double> density_samples;
  // Per statistic, the potential scale reduction over the chains (Gelman & Rubin 1992): near 1
  // when the chains agree, large when they sit in different states (a model that holds a packed
  // exemplar in some chains and loses it in others), infinite for chains constant at different
  // values; 1 for one chain or a constant statistic. Empty after reweighting.
  std::vector<double> r_hat;
  int observations = 0;
  // Each chain's observations, the row range [first, last) of `samples`; empty after reweighting.
  std::vector<std::pair<int, int>> chain_rows;
  int chains() const { return static_cast<int>(chain_rows.size()); }
};

// The moments of `setting.chains` new chains' observations, pooled with those of `pooled_with`
// when given (a sample of the same model, domain and setting but the seed and the chains): more
// chains for a sample worth too few independent observations, without drawing its first chains
// again.
StatisticsMoments statistics_moments(const model::ShapeProcessModel& model,
                                     const geometry::Domain& domain, const ChainsSetting& setting,
                                     const StatisticsMoments* pooled_with = nullptr);

// Gelman and Rubin's R-hat of each statistic of `sample`, whose chains are the row ranges
// [first, last) of `chains` (statistics_moments fills StatisticsMoments::r_hat with it).
std::vector<double> potential_scale_reduction(const StatisticsMoments& sample,
                                              const std::vector<std::pair<int, int>>& chains);

// The sample's mean and covariance reweighted to θ + δ (δ by θ index, zero where unchanged), and
// the effective sample size as a share of the observations (1 for δ = 0). Standard errors are not
// reweighted: they stay the sample's.
StatisticsMoments reweighted(const StatisticsMoments& sample, const std::vector<double>& delta,
                             double& effective_share);

}  // namespace shapeproc::fit
