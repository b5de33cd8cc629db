// Fitting the shape process to an exemplar (paper §6.1–6.2): thresholds from quantiles of the
// directional distance distributions, then β and γ by maximum log pseudo-likelihood.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "libshapeproc/fit/parameter_budget.hpp"
#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/model/shape_process_model.hpp"

namespace shapeproc::fit {

// FitOptions::near_birth_share chosen by the fit: FitDefaults::crystal_near_birth_share where the
// maximum-likelihood chains grow the exemplar's lattice as a crystal, else 0. A proposal: the
// stationary law does not depend on it. Births near neighbours refill a crystal's vacancies,
// which uniform births almost never hit, so that its chains reach the model's own equilibrium
// (docs/fit.md, "Packed exemplars").
inline constexpr double kAutomaticNearBirths = -1.0;

struct FitOptions {
  // How pairs are measured, as the model records it; directions 0 = the default for the
  // exemplar's dimension (geometry::default_directions).
  model::MeasurementSettings measurement = {geometry::DistanceKind::shape,
                                            geometry::DirectionKind::gravitation, 0,
                                            geometry::ProxyOptions{}.tolerance};
  // Quantile orders q_0 < q_1 < … of the thresholds, or explicit thresholds (then the same for
  // every pair and axis; quantiles are ignored).
  std::vector<double> quantiles = {0.0, 0.1, 0.2};
  std::vector<double> thresholds;
  // The exemplar's window: a torus (`periodic` in the model file and on the command line) or open,
  // with an edge treatment (none or border; geometry/domain.hpp).
  geometry::Boundary boundary = geometry::Boundary::open;
  geometry::EdgeTreatment edge = geometry::EdgeTreatment::none;
  // Quadrature: dummy locations on a grid of this many cells along the window's longest side
  // (0: the default, see docs/fit.md), each crossed with `shapes_per_location` shapes of every
  // category taken in rotation (0: all shapes of the category).
  int quadrature = 0;
  int shapes_per_location = 0;
  // Levels of adaptive refinement of cells that a boundary may cross (each halves the cell;
  // costly: most cells of an anisotropic model are crossed by some sector boundary).
  int refinement = 0;
  // 2D only: integrate each row of cells as a line, exactly along the row (line_quadrature.hpp);
  // costlier than cells at the same resolution, see docs/fit.md.
  bool lines = false;
  // The data points join the quadrature with this fraction of |W| per category (each κ|W|/n_c,
  // the dummies the rest): every observed configuration then has some exposure, so the maximum
  // is finite even where the continuum LPL has none (packed exemplars, docs/fit.md).
  double data_weight = 1e-6;
  // Axis bins with fewer exemplar pairs than this take the thresholds of the category pair's
  // pairs pooled over all axes.
  int min_pairs_per_axis = 10;
  // How many γ each pair of categories may have, and how far it may reach, from the exemplar's
  // element counts (parameter_budget.hpp). Not applied to explicit thresholds.
  ParameterBudget budget;
  // Categories of which at least this share of elements overlap or lie inside a larger
  // category's are placed after it, given its elements (category_layers.hpp); above 1: one
  // layer, every pair symmetric.
  double layer_share = kFitDefaults.layer_share;
  // Whether attractive bands of a point pattern may be saturated where the profile
  // pseudo-likelihood prefers it (saturation_choice.hpp). A tile's fit does without: its
  // attraction is a lattice's contact.
  bool saturation = true;
  // The share of the maximum-likelihood chains' birth proposals drawn near a neighbour, recorded
  // in the model for every later chain (model::NeighbourOffsets::share; docs/mathematics.md,
  // "Births near neighbours"); in [0, 1), or kAutomaticNearBirths.
  double near_birth_share = kAutomaticNearBirths;
  // Threads that integrate the quadrature (0: one per core); the fit does not depend on them.
  int threads = 0;
  // Called at each stage ("proxies", "measurements", "quadrature", "optimisation") with the work
  // done and its total (0: not known); during the quadrature, with blocks of rows done, from the
  // integrating threads (calls may come from several threads at once). May be empty.
  std::function<void(const char* stage, long long done, long long total)> progress;
};

// Quadrature cells along the window's longest side when FitOptions::quadrature is 0.
int default_quadrature_cells(int dimension);

struct FitResult {
  model::ShapeProcessModel model;
  double log_pseudo_likelihood = 0.0;
  int data_points = 0;        // data points in the LPL's sum
  int quadrature_points = 0;  // dummy and data points in the quadrature (λ > 0)
  int quadrature_cells = 0;
  bool quadrature_lines = false;   // 2D: rows of cells integrated as exact lines
  std::vector<std::string> notes;  // fallbacks and special cases, one sentence each
  struct {
    double proxies = 0, measurements = 0, quadrature = 0, optimisation = 0;
  } seconds;
};

// Fits the model to `exemplar`. The model's shape space is the exemplar's shapes (empty for
// point patterns). Throws std::invalid_argument on bad options, and on exemplars that cannot be
// fitted (no element, thresholds below an observed distance, a border edge that leaves no
// window), with a message for the user.
FitResult fit_shape_process(const geometry::Scene& exemplar, const FitOptions& options);

// The fit's edge treatment as the model file and the command line name it: "periodic" (a torus),
// "border" or "none".
const char* edge_name(const FitOptions& options);

}  // namespace shapeproc::fit
