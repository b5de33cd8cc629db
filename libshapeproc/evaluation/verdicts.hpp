// Verdicts on an output against its exemplar (docs/metrics.md#verdicts): what a person would
// notice, each as a measured figure on a documented scale with a pass/fail rule, computed the
// same way for every synthesis method.
//
//   density        output elements per unit area / the exemplar's, overall and per category:
//                  passes within ×0.8 to ×1.25 ("too dense", "too sparse");
//   shape mix      Pearson's chi-square of the output's shape-class counts against the
//                  exemplar's shares (shape_mix.hpp): passes at p ≥ 0.01;
//   overlaps       share of elements in an overlapping pair (shape-exact): passes at most one
//                  percentage point above the exemplar's;
//   touching       touching pairs per element: passes within ±max(0.1, half the exemplar's);
//   order          (2D) long-range order max(|⟨ψ4⟩|, |⟨ψ6⟩|) (metrics/bond_order.hpp): passes
//   within
//                  ±0.2 of the exemplar's ("loses the exemplar's lattice", "more regular");
//   spacing        W1 of the nearest-neighbour distributions over the exemplar's mean nearest
//                  distance: passes at most 0.15, or at most the W1 two samples of their sizes
//                  from one distribution exceed 1% of the time where that is larger
//                  (metrics/wasserstein_test.hpp);
//   model statistics  with a fitted model, its pairs per band and element against the
//                  exemplar's (model_statistics.hpp): passes within the Bonferroni bound;
//   novelty        copied neighbourhoods (metrics/novelty.hpp): fails ("repeats the exemplar")
//                  where the patch copy share stands more than 0.3 above its chance level or the
//                  largest copied patch holds more than 0.3 of the output; shown without a rule
//                  for a lattice exemplar, whose own repeat is its only faithful arrangement;
//   neighbourhood  Ma's average neighbourhood distance (Davison et al. eq. 5) in a², shown with
//                  no rule: it has no scale that holds across exemplars (0 for a copy).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "libshapeproc/evaluation/model_statistics.hpp"
#include "libshapeproc/evaluation/shape_mix.hpp"
#include "libshapeproc/metrics/bond_order.hpp"
#include "libshapeproc/metrics/neighbourhood_distance.hpp"
#include "libshapeproc/metrics/novelty.hpp"
#include "libshapeproc/metrics/scene_statistics.hpp"

namespace shapeproc::evaluation {

enum class Outcome { pass, fail, shown };
const char* to_string(Outcome outcome);  // "pass", "fail", "shown"

struct Verdict {
  std::string metric;  // "density", "density: red", "shape mix", …
  double value = 0.0;  // the figure the rule reads
  std::string shown;   // the figure as the page shows it ("×1.46", "p = 0.003")
  std::string rule;    // the rule, in words ("×0.8 to ×1.25")
  Outcome outcome = Outcome::shown;
  std::string problem;  // what a failure means, for the summary ("too dense")
  std::string brief;    // the figure alone, for tables ("×1.46", "p 0.003")
};

// What the verdicts read: both scenes' statistics (the output's compared with the exemplar's),
// their long-range order and the shape mix.
struct Judged {
  const metrics::SceneStatistics* exemplar = nullptr;
  std::optional<ModelStatistics> model;  // with a fitted model only
  const metrics::SceneStatistics* output = nullptr;
  const metrics::Comparison* comparison = nullptr;
  const metrics::NeighbourhoodDistance* neighbourhood = nullptr;  // optional
  metrics::BondOrder exemplar_order, output_order;
  ShapeMix mix;
  std::optional<metrics::Novelty> novelty;  // with the exemplar's scene
};

// The exemplar's side of every check, measured once for any number of outputs.
struct ExemplarMeasures {
  const metrics::SceneStatistics* statistics = nullptr;
  metrics::BondOrder order;
  ShapeKinds kinds;
  const model::ShapeProcessModel* model = nullptr;  // optional
  PairCounts pairs;                                 // with a model
  const geometry::Scene* scene = nullptr;           // the exemplar itself, for novelty
};
ExemplarMeasures measure_exemplar(const geometry::Scene& exemplar, geometry::Boundary boundary,
                                  const metrics::SceneStatistics& statistics,
                                  const model::ShapeProcessModel* model = nullptr);

// Measures what the statistics do not hold (order, shape mix, the model's pair counts).
Judged measure_for_verdicts(const ExemplarMeasures& exemplar, const geometry::Scene& output,
                            geometry::Boundary output_boundary,
                            const metrics::SceneStatistics& output_statistics,
                            const metrics::Comparison& comparison,
                            const metrics::NeighbourhoodDistance* neighbourhood);
// One-off: the exemplar measured for this output alone.
Judged measure_for_verdicts(const geometry::Scene& exemplar, geometry::Boundary exemplar_boundary,
                            const metrics::SceneStatistics& exemplar_statistics,
                            const geometry::Scene& output, geometry::Boundary output_boundary,
                            const metrics::SceneStatistics& output_statistics,
                            const metrics::Comparison& comparison,
                            const metrics::NeighbourhoodDistance* neighbourhood,
                            const model::ShapeProcessModel* model = nullptr);

std::vector<Verdict> judge(const Judged& judged);

// One line for the top of a report: the failures, worst first ("density ×1.46 the exemplar's:
// too dense; order 0.12 against 0.96: loses the exemplar's lattice"), or "passes all N checks".
std::string summary(const std::vector<Verdict>& verdicts);

}  // namespace shapeproc::evaluation
