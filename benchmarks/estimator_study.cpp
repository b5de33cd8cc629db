// The maximum-likelihood fit against the pseudo-likelihood fit on simulated point patterns
// (run ./build/benchmarks/estimator_study [replicates], default 100; a few minutes on 2 cores).
// For each model of known θ on a unit torus: `replicates` patterns sampled by the project's
// sampler, each fitted by MPLE (the fit's default quadrature, thresholds fixed at the truth) and
// by the MCMC MLE started from it. Prints per parameter the mean estimate, its bias in units of
// the mean reported standard error, the spread (standard deviation) of each estimator and the
// share of replicates whose MLE lies within 2 reported standard errors of the truth; replicates
// with no pair in a band (γ̂ = 0) are counted apart.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "libshapeproc/fit/fit_maximum_likelihood.hpp"
#include "libshapeproc/fit/fit_shape_process.hpp"
#include "libshapeproc/model/interaction.hpp"
#include "libshapeproc/sample/birth_death_sampler.hpp"

namespace {

using namespace shapeproc;

struct Case {
  const char* name;
  double beta;
  std::vector<double> thresholds;
  std::vector<double> gammas;
};

model::ShapeProcessModel truth_model(const Case& c) {
  model::ShapeProcessModel m;
  m.categories.push_back({"points", c.beta});
  m.measurement.directions = 1;
  model::PairInteraction pair;
  model::AxisParameters axis;
  axis.thresholds = c.thresholds;
  axis.gammas = c.gammas;
  pair.axes = {axis};
  m.interactions = {pair};
  return m;
}

geometry::Scene as_scene(const geometry::Scene& sample) {
  geometry::Scene scene = sample;
  scene.categories = {{"points"}};
  scene.shapes = {geometry::Shape{geometry::PointShape{}, "point"}};
  for (geometry::Element& e : scene.elements) {
    e.shape = 0;
    e.category = 0;
  }
  return scene;
}

struct Moments {
  double sum = 0, square = 0, se = 0, covered = 0;
  int n = 0, at_zero = 0;  // at_zero: γ = 0 (no pair in the band), left out of the figures
  void add(double estimate, double standard_error, double truth) {
    if (!std::isfinite(estimate)) {
      ++at_zero;
      return;
    }
    sum += estimate;
    square += estimate * estimate;
    se += standard_error;
    covered += std::abs(estimate - truth) <= 2 * standard_error;
    ++n;
  }
  double mean() const { return sum / n; }
  double spread() const { return std::sqrt(std::max(0.0, square / n - mean() * mean())); }
};

void study(const Case& c, int replicates) {
  const model::ShapeProcessModel truth = truth_model(c);
  const geometry::Domain torus = geometry::Domain::from_sizes({1, 1}, geometry::Boundary::torus);
  std::vector<double> theta = {std::log(c.beta)};
  for (double g : c.gammas) theta.push_back(std::log(g));
  std::vector<Moments> mple(theta.size()), mle(theta.size());
  std::vector<double> difference(theta.size(), 0.0);
  int converged = 0, elements = 0;
  for (int r = 0; r < replicates; ++r) {
    sample::SamplerOptions sampler;
    sampler.iterations = 40000;
    core::Random random(1000 + static_cast<std::uint64_t>(r));
    const geometry::Scene z =
        as_scene(sample::sample_shape_process(truth, torus, sampler, random).scene);
    elements += static_cast<int>(z.elements.size());
    fit::FitOptions options;
    options.measurement.directions = 1;
    options.thresholds = c.thresholds;
    options.boundary = geometry::Boundary::torus;
    const fit::FitResult pseudo = fit::fit_shape_process(z, options);
    fit::MleOptions mle_options;
    mle_options.sampling.seed = 7 + static_cast<std::uint64_t>(r);
    const fit::FitResult likelihood =
        fit::refine_to_maximum_likelihood(z, options, pseudo, mle_options);
    converged += likelihood.model.fit && likelihood.model.fit->likelihood &&
                 likelihood.model.fit->likelihood->converged;
    const auto record = [&](const model::ShapeProcessModel& m, std::vector<Moments>& out) {
      const model::CategoryParameters& b = m.categories[0];
      out[0].add(std::log(b.beta), b.beta_standard_error / b.beta, theta[0]);
      const model::AxisParameters& a = m.interactions[0].axes[0];
      for (std::size_t k = 0; k < a.gammas.size(); ++k)
        out[k + 1].add(std::log(a.gammas[k]), a.gamma_standard_errors[k] / a.gammas[k],
                       theta[k + 1]);
    };
    record(pseudo.model, mple);
    for (std::size_t k = 0; k < theta.size(); ++k) {
      const double a = k == 0 ? std::log(pseudo.model.categories[0].beta)
                              : std::log(pseudo.model.interactions[0].axes[0].gammas[k - 1]);
      const double b = k == 0 ? std::log(likelihood.model.categories[0].beta)
                              : std::log(likelihood.model.interactions[0].axes[0].gammas[k - 1]);
      if (std::isfinite(a) && std::isfinite(b)) difference[k] += std::abs(a - b) / replicates;
    }
    record(likelihood.model, mle);
    std::fprintf(stderr, "\r%s: %d/%d", c.name, r + 1, replicates);
  }
  std::fprintf(stderr, "\n");
  std::printf("\n%s: %d replicates, %.1f elements on average, MLE converged in %d\n", c.name,
              replicates, static_cast<double>(elements) / replicates, converged);
  std::printf(
      "| parameter | truth | MPLE mean | MPLE spread | MLE mean | MLE spread | MLE bias / mean se |"
      " MLE within 2 se | gamma = 0 (no pair) | mean abs(MLE - MPLE) |\n"
      "|---|---|---|---|---|---|---|---|---|---|\n");
  for (std::size_t k = 0; k < theta.size(); ++k) {
    const std::string name = k == 0 ? "log beta" : "log gamma_" + std::to_string(k);
    const double bias = (mle[k].mean() - theta[k]) / (mle[k].se / mle[k].n);
    std::printf("| %s | %.3f | %.3f | %.3f | %.3f | %.3f | %+.2f | %.0f%% | %d | %.4f |\n",
                name.c_str(), theta[k], mple[k].mean(), mple[k].spread(), mle[k].mean(),
                mle[k].spread(), bias, 100.0 * mle[k].covered / mle[k].n, mle[k].at_zero,
                difference[k]);
  }
}

}  // namespace

int main(int argc, char** argv) {
  const int replicates = argc > 1 ? std::max(1, std::atoi(argv[1])) : 100;
  study({"Strauss, r = 0.05, gamma 0.5", 200.0, {0.0, 0.05}, {0.5}}, replicates);
  study({"Strauss, strong inhibition, r = 0.05, gamma 0.1", 200.0, {0.0, 0.05}, {0.1}}, replicates);
  study({"piecewise, bands 0-0.03-0.06, gammas 0.2 and 0.7", 200.0, {0.0, 0.03, 0.06}, {0.2, 0.7}},
        replicates);
  return 0;
}
