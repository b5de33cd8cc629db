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

// Whether the fit's chains need the compressing burn-in (sample/compression.hpp): where the
// pseudo-likelihood found a parameter without a finite maximum (a packed exemplar, whose density
// a chain at the model's β from the empty configuration does not reach in any useful time).
// Every chain starts empty all the same; the burn-in only brings it to a packed state from none
// of the exemplar's positions.
bool packed_exemplar(const model::ShapeProcessModel& mple);

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
