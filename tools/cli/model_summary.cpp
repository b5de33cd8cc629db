#include "tools/cli/model_summary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "libshapeproc/core/constants.hpp"
#include "libshapeproc/core/format.hpp"

namespace shapeproc::cli {

namespace {

std::string g(double v, int digits = 4) { return core::format_general(v, digits); }

// An axis as `show` names it: its angle in 2D, its components in 3D.
std::string direction_degrees(const geometry::Vec3& d, int dimension) {
  if (dimension == 2) return g(std::atan2(d.y(), d.x()) * 180 / core::kPi, 3) + " deg";
  return "(" + g(d.x(), 2) + ", " + g(d.y(), 2) + ", " + g(d.z(), 2) + ")";
}

std::string gamma_value_text(const model::AxisParameters& a, std::size_t k) {
  const model::ParameterStatus status =
      k < a.status.size() ? a.status[k] : model::ParameterStatus::fixed;
  switch (status) {
    case model::ParameterStatus::boundary:
      return "0 (boundary: no pair)";
    case model::ParameterStatus::unidentifiable:
      return "1 (no information)";
    case model::ParameterStatus::unbounded:
      return g(a.gammas[k], 3) + " (unbounded)";
    case model::ParameterStatus::unreachable:
      return g(a.gammas[k], 3) + " (unreachable)";
    default:
      break;
  }
  std::string text = g(a.gammas[k], 3);
  if (k < a.gamma_standard_errors.size() && std::isfinite(a.gamma_standard_errors[k]))
    text += " ± " + g(a.gamma_standard_errors[k], 2);
  if (k < a.observed_pairs.size()) text += " (" + std::to_string(a.observed_pairs[k]) + ")";
  return text;
}

// A band's γ, and its saturation when it has one (docs/mathematics.md, "Saturation").
std::string gamma_text(const model::AxisParameters& a, std::size_t k) {
  const int s = a.saturation(k);
  return gamma_value_text(a, k) +
         (s > 0 ? ", saturated at " + std::to_string(s) + " neighbours per element" : "");
}

// The maximum-likelihood fit's goodness of fit, as spatstat prints a fit: per statistic the
// exemplar's value, the model's expectation ± its Monte Carlo standard error, and z.
void print_goodness_of_fit(const model::ShapeProcessModel& model, const model::LikelihoodRecord& e,
                           std::ostream& out) {
  const std::vector<std::string> names = model::statistic_names(model);
  const std::vector<double>& observed = e.observed;
  const std::vector<double>& expected = e.expected;
  const std::vector<double>& error = e.expected_standard_error;
  const std::vector<double>& z = e.z;
  const std::vector<int>& penalised = e.penalised;
  const std::vector<int>& unreached = e.unreachable;
  out << "\nmaximum likelihood (MCMC): " << (e.converged ? "converged" : "did not converge")
      << " in " << e.iterations << " iteration(s), " << g(e.seconds, 3)
      << " s; largest |z| accepted " << g(e.tolerance, 3) << "\n";
  if (e.stationary_window)
    out << "  window: stationary (the exemplar as a piece of a larger drawing: its own torus, "
           "its pairs across the seam left out; --edge none fits it as drawn)\n";
  out << "  " << std::left << std::setw(34) << "statistic" << std::right << std::setw(10)
      << "exemplar" << std::setw(22) << "model (mean ± se)" << std::setw(8) << "z" << '\n';
  const std::size_t rows =
      std::min({observed.size(), names.size(), expected.size(), error.size(), z.size()});
  for (std::size_t k = 0; k < rows; ++k) {
    if (observed[k] == 0 && expected[k] == 0) continue;  // bands held at γ = 0
    const bool moved =
        std::find(penalised.begin(), penalised.end(), static_cast<int>(k)) != penalised.end();
    const bool unreachable =
        std::find(unreached.begin(), unreached.end(), static_cast<int>(k)) != unreached.end();
    out << "  " << std::left << std::setw(34) << names[k] << std::right << std::setw(10)
        << g(observed[k]) << std::setw(22) << (g(expected[k]) + " ± " + g(error[k], 2))
        << std::setw(8) << g(z[k], 2)
        << (unreachable ? "  (unreachable)"
            : moved     ? "  (attraction prior)"
                        : "")
        << '\n';
  }
  if (!penalised.empty())
    out << "  (attraction prior: the half-normal prior on log γ > 0 holds the band's expected "
           "pairs half a pair or more below the exemplar's; docs/fit.md)\n";
}

}  // namespace

void print_model_summary(const model::ShapeProcessModel& model, std::ostream& out) {
  const char* measure = model.dimension == 2 ? "area" : "volume";
  out << "model: " << model.dimension << "D, " << model.categories.size() << " categor"
      << (model.categories.size() == 1 ? "y" : "ies") << ", " << model.measurement.directions
      << " direction(s), distance "
      << (model.measurement.distance == geometry::DistanceKind::shape      ? "shape"
          : model.measurement.distance == geometry::DistanceKind::centroid ? "centroid"
                                                                           : "hausdorff")
      << ", direction "
      << (model.measurement.direction == geometry::DirectionKind::gravitation ? "gravitation"
                                                                              : "centroid")
      << ", "
      << (model.shapes.empty() ? std::string("points")
                               : std::to_string(model.shapes.size()) + " shapes")
      << "\n";
  out << "\nintensity beta (per unit " << measure << ", " << model.units << "):\n";
  for (const model::CategoryParameters& c : model.categories) {
    out << "  " << std::left << std::setw(16) << c.name << std::right << " " << g(c.beta);
    if (std::isfinite(c.beta_standard_error)) out << " ± " << g(c.beta_standard_error, 2);
    if (c.beta_status == model::ParameterStatus::unbounded) out << " (unbounded)";
    if (c.layer > 0) out << "  layer " << c.layer;
    if (c.anchor >= 0)
      out << ", on '" << model.categories[static_cast<std::size_t>(c.anchor)].name << "' (within "
          << g(c.anchor_reach, 3) << ")";
    if (c.hidden) out << "  (hidden: placed, not drawn)";
    out << '\n';
  }
  if (!model.shape_classes.empty()) {
    out << "\nshape classes (share of the category's intensity):\n";
    for (std::size_t k = 0; k < model.shape_classes.size(); ++k) {
      const model::ShapeClass& c = model.shape_classes[k];
      int shapes = 0;
      for (const model::ModelShape& s : model.shapes)
        shapes += s.shape_class == static_cast<int>(k);
      out << "  " << k << "  " << std::left << std::setw(16)
          << model.categories[static_cast<std::size_t>(c.category)].name << std::right << " "
          << std::setw(8) << g(c.weight, 3) << "  " << c.label << ", " << shapes << " shape(s)\n";
    }
  }
  if (model.interactions.empty()) out << "\nno interaction: a Poisson process\n";
  for (std::size_t index = 0; index < model.interactions.size(); ++index) {
    const model::PairInteraction& pair = model.interactions[index];
    out << "\npair " << index << ": interaction "
        << model.categories[static_cast<std::size_t>(pair.first)].name << " - "
        << model.categories[static_cast<std::size_t>(pair.second)].name
        << "  (gamma ± se (exemplar pairs in the band); hard core below d0)\n";
    if (!pair.choice.empty()) out << "  chosen: " << pair.choice << '\n';
    for (std::size_t i = 0; i < pair.axes.size(); ++i) {
      const model::AxisParameters& a = pair.axes[i];
      out << "  axis " << i << "  " << std::setw(9)
          << (pair.isotropic() && model.measurement.directions > 1
                  ? std::string("all")
                  : direction_degrees(a.direction, model.dimension))
          << "  d0 " << std::setw(8) << g(a.thresholds.front());
      for (std::size_t k = 0; k < a.gammas.size(); ++k) {
        out << "  | " << k + 1 << " [" << g(a.thresholds[k]) << ", " << g(a.thresholds[k + 1])
            << "): " << gamma_text(a, k);
      }
      out << '\n';
    }
  }
  if (!model.fit) return;
  const model::FitRecord& fit = *model.fit;
  out << "\npath: " << model::fit_path_name(fit.path);
  if (fit.likelihood) out << "; burn-in " << model::burn_in_name(fit.likelihood->burn_in_kind);
  if (fit.tile_repeats > 1)
    out << "; tile repeated " << fit.tile_repeats << " x " << fit.tile_repeats;
  out << '\n';
  if (fit.data_points > 0) {
    out << "\nlog pseudo-likelihood"
        << (fit.likelihood ? " (of the MPL fit the maximum likelihood started from)" : "") << ": "
        << g(fit.log_pseudo_likelihood, 8) << '\n';
  }
  if (fit.likelihood) print_goodness_of_fit(model, *fit.likelihood, out);
  if (fit.quadrature.cells > 0 || fit.quadrature.lines) {
    out << "quadrature: " << fit.quadrature.cells << " cells, " << fit.quadrature.points
        << " points; edge " << (fit.edge.empty() ? "none" : fit.edge) << '\n';
  }
  for (const std::string& note : fit.notes) out << "note: " << note << '\n';
}

void print_model_brief(const model::ShapeProcessModel& model, std::ostream& out) {
  out << "fitted: " << model.dimension << "D";
  for (const model::CategoryParameters& c : model.categories) {
    out << ", " << c.name << " beta " << g(c.beta)
        << (c.beta_status == model::ParameterStatus::unbounded ? " (unbounded)" : "");
  }
  std::size_t bands = 0, unbounded = 0;
  double range = 0.0;
  for (const model::PairInteraction& pair : model.interactions) {
    for (const model::AxisParameters& a : pair.axes) {
      bands += a.gammas.size();
      range = std::max(range, a.thresholds.back());
      for (model::ParameterStatus st : a.status)
        unbounded += st == model::ParameterStatus::unbounded;
    }
  }
  out << "; " << model.interactions.size() << " interacting pair(s), " << bands
      << " gamma(s), range " << g(range) << (model.units == "1" ? "" : " " + model.units);
  if (unbounded > 0)
    out << " (" << unbounded << " unbounded: the fit has no finite maximum, docs/fit.md)";
  out << '\n';
}

}  // namespace shapeproc::cli
