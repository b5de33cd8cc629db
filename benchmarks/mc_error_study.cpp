// Are the Monte Carlo standard errors of the maximum-likelihood fit honest? (run
// ./build/benchmarks/mc_error_study EXEMPLAR MODEL [replicates] [reader] [chains]; reader: none,
// fill (--category-by fill) or split (--split-subpaths); chains: fit (the fit's simulation, 4
// chains of 20,000 steps of burn-in and 50,000 observed) or fidelity (`shapeproc fidelity`'s, 50
// chains of 20,000 and 20,000); minutes.) Repeats that simulation (fit::statistics_moments,
// started where the fit starts its chains) at the model's θ with `replicates` seeds, and
// prints per statistic the spread of the replicates' means against the mean of their reported
// standard errors (effective_sample_size.hpp) and against batch means with five batches per
// chain (the estimator before): a ratio near 1 is an honest error, above 1 one that is too
// small. docs/fit.md, "Monte Carlo standard errors", holds the figures.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/evaluation/fidelity.hpp"
#include "libshapeproc/fit/fit_maximum_likelihood.hpp"
#include "libshapeproc/fit/monte_carlo_moments.hpp"
#include "libshapeproc/io/model_io.hpp"
#include "libshapeproc/io/scene_io.hpp"

namespace {

using namespace shapeproc;

constexpr int kBatchesPerChain = 5;

// The batch-means standard error of column k's mean: kBatchesPerChain consecutive batches of
// each chain of `per_chain` rows.
double batch_means_error(const fit::StatisticsMoments& m, int chains, std::size_t k) {
  const std::size_t p = static_cast<std::size_t>(m.parameters);
  const int per_chain = m.observations / chains, per_batch = per_chain / kBatchesPerChain;
  std::vector<double> means;
  for (int c = 0; c < chains; ++c)
    for (int b = 0; b < kBatchesPerChain; ++b) {
      double sum = 0.0;
      for (int i = 0; i < per_batch; ++i)
        sum += m.samples[static_cast<std::size_t>(c * per_chain + b * per_batch + i) * p + k];
      means.push_back(sum / per_batch);
    }
  double mean = 0.0, variance = 0.0;
  for (double x : means) mean += x / static_cast<double>(means.size());
  for (double x : means)
    variance += (x - mean) * (x - mean) / static_cast<double>(means.size() - 1);
  return std::sqrt(variance / static_cast<double>(means.size()));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr,
                 "usage: mc_error_study EXEMPLAR MODEL.json [replicates, default 20] "
                 "[reader: none|fill|split] [chains: fit|fidelity]\n");
    return 2;
  }
  try {
    io::ReaderOptions reader;
    const std::string how = argc > 4 ? argv[4] : "none";
    if (how == "fill") reader.category_by = io::CategoryRule::parse("fill");
    if (how == "split") reader.split_subpaths = true;
    const geometry::Scene exemplar = io::read_scene(argv[1], reader);
    const model::ShapeProcessModel model = io::read_model(argv[2]);
    const int replicates = argc > 3 ? std::max(2, std::atoi(argv[3])) : 20;
    const std::vector<double> observed = fit::observed_statistics(exemplar, model);
    // As the fit sampled: a model fitted on the stationary window on the window's torus.
    const bool stationary = fit::fitted_on_stationary_window(model);
    const geometry::Domain window =
        stationary
            ? fit::stationary_domain(exemplar)
            : geometry::Domain(exemplar.window, exemplar.dimension, geometry::Boundary::open);
    const std::string chains = argc > 5 ? argv[5] : "fit";
    fit::ChainsSetting setting =
        chains == "fidelity" ? evaluation::fidelity_chains() : fit::ChainsSetting{};
    if (stationary) setting.observe_region = exemplar.window;
    setting.burn_in_kind = model::output_burn_in(model);
    const std::size_t p = observed.size();
    std::vector<double> sum(p), squares(p), error(p), batch_error(p), effective(p);
    for (int r = 0; r < replicates; ++r) {
      setting.seed = 1000 + static_cast<std::uint64_t>(r);
      const fit::StatisticsMoments m = fit::statistics_moments(model, window, setting);
      for (std::size_t k = 0; k < p; ++k) {
        sum[k] += m.mean[k];
        squares[k] += m.mean[k] * m.mean[k];
        error[k] += m.standard_error[k] / replicates;
        effective[k] += m.effective_size[k] / replicates;
        batch_error[k] += batch_means_error(m, setting.chains, k) / replicates;
      }
    }
    std::printf("%d replicates of %d chains, %lld steps observed\n", replicates, setting.chains,
                setting.steps);
    std::printf("%-30s %8s %8s %8s %8s %6s %8s %6s %9s\n", "statistic", "exemplar", "mean",
                "spread", "se", "ratio", "batch se", "ratio", "effective");
    const std::vector<std::string> names = model::statistic_names(model);
    for (std::size_t k = 0; k < p; ++k) {
      const double mean = sum[k] / replicates;
      const double spread = std::sqrt(std::max(0.0, squares[k] / replicates - mean * mean) *
                                      replicates / (replicates - 1));
      std::printf("%-30s %8.2f %8.3f %8.3f %8.3f %6.2f %8.3f %6.2f %9.0f\n", names[k].c_str(),
                  observed[k], mean, spread, error[k], spread / error[k], batch_error[k],
                  spread / batch_error[k], effective[k]);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mc_error_study: %s\n", e.what());
    return 2;
  }
  return 0;
}
