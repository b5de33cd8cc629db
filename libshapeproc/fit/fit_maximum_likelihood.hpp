// The maximum-likelihood fit of the shape process (mcmc_mle.hpp), started from the maximum
// pseudo-likelihood fit: the thresholds, shapes and categories of `mple` are kept, β and γ are
// re-estimated so that the model's expected counts match the exemplar's, on the exemplar's own
// window (open for the edge treatment none, a torus for periodic, the inner window given the
// elements of its border band for border).
#pragma once

#include "libshapeproc/fit/fit_shape_process.hpp"
#include "libshapeproc/fit/mcmc_mle.hpp"

namespace shapeproc::fit {

// The exemplar's sufficient statistics t(z) in the model's θ numbering: elements per category,
// then its pairs per interaction band (FitResult's observed pairs), then elements per shape class
// (the exemplar's element e has the model's shape e.shape).
std::vector<double> observed_statistics(const geometry::Scene& exemplar,
                                        const model::ShapeProcessModel& model);

// The border correction of the maximum-likelihood fit: the exemplar's elements outside the
// window eroded by the interaction range, held fixed, and that eroded window, where the chains
// sample (the likelihood of the inner elements given the outer ones, as the pseudo-likelihood's
// border treatment).
struct BorderCondition {
  std::vector<geometry::Element> fixed;
  geometry::Box3 region;
};
BorderCondition border_condition(const geometry::Scene& exemplar,
                                 const model::ShapeProcessModel& model);

// The exemplar's elements whose reference positions lie in `region` (all of them when it is
// empty): where a packed exemplar's chains start, given the border condition's free region.
std::vector<geometry::Element> elements_in(const geometry::Scene& exemplar,
                                           const geometry::Box3& region);

// Whether the chains of the fit start at the exemplar: where the pseudo-likelihood found a
// parameter without a finite maximum (a packed exemplar, whose states a chain from the empty
// configuration never reaches). Elsewhere they start empty, so that the fit only converges where
// the model reaches the exemplar's counts by itself.
bool packed_exemplar(const model::ShapeProcessModel& mple);

// Whether samples of a fitted model start from its exemplar, as its maximum-likelihood chains
// did (its fit record's `estimator.chains_start`); false for other models.
bool starts_at_exemplar(const model::ShapeProcessModel& model);

// The steps per element at which such a model's fit matched its exemplar: its chains start at the
// exemplar's n elements and observe t from the burn-in b to b + s steps, so their mean is that of
// the state near the middle, (b + s/2) / n steps per element. A packed exemplar's chains do not
// reach the model's stationary state in that time (it is what they are fitted not to need), so a
// sample from the exemplar repeated stops at this many steps per element it starts from
// (sample::SamplerOptions::held_steps_per_element), not at the stationarity rule's horizon:
// bubbles-3x3's largest bubbles, 12% of the exemplar, fall to 8% at 1,000 steps per element
// (docs/sample.md). 0 for other models and for fits recorded without it.
double held_steps_per_element(const model::ShapeProcessModel& model);

// The stationary window (WindowModel::stationary, docs/fit.md): the exemplar's window as a torus.
// Its elements near an edge see neighbours across the seam, as in a larger drawing; the
// statistics t_W leave out the pairs that meet across it, which the exemplar cannot show.
geometry::Domain stationary_domain(const geometry::Scene& exemplar);

// Whether a fitted model's maximum-likelihood chains sampled the stationary window (its fit
// record's `estimator.window`); false for other models.
bool fitted_on_stationary_window(const model::ShapeProcessModel& model);

// The MLE on the exemplar's window: open for the edge treatment none (or, with
// WindowModel::stationary or automatic, the window seen inside stationary_domain), a torus for
// periodic, the border condition for border.
FitResult refine_to_maximum_likelihood(const geometry::Scene& exemplar,
                                       const FitOptions& fit_options, FitResult mple,
                                       const MleOptions& options);

}  // namespace shapeproc::fit
