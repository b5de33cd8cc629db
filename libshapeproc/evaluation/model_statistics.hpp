// The fitted model's own sufficient statistics, counted on any output (docs/metrics.md,
// "Verdicts"): pairs per category pair, axis and distance band, per element, against the
// exemplar's. Pairs are measured on the scenes' own shapes (whatever method placed and turned
// them) with the model's distance, directions and bands; categories are matched by name. Each
// band's gap is in standard errors of the two rates, counts taken as Poisson (a documented
// approximation: regular patterns vary less, clustered ones more), and the check passes when the
// largest |z| is within the Bonferroni bound of a 1% test over all bands.
#pragma once

#include <string>
#include <vector>

#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/model/shape_process_model.hpp"

namespace shapeproc::evaluation {

struct ModelStatistics {
  std::vector<std::string> names;                    // per pair band (model::statistic_names)
  std::vector<double> exemplar, output;              // pairs per element
  std::vector<double> z;                             // (output − exemplar) / se
  int worst = -1;                                    // index of the largest |z|; -1 without bands
  double critical = 0.0;                             // Bonferroni bound of a 1% test
  int exemplar_hard_core = 0, output_hard_core = 0;  // pairs closer than the hard core
};

// A scene's elements in the model's categories (by name; others left out) and their pairs per
// interaction parameter (the category entries unused), pairs inside the hard core apart.
struct PairCounts {
  std::vector<double> pairs;
  int elements = 0, hard_core = 0;
};
PairCounts pair_counts(const geometry::Scene& scene, geometry::Boundary boundary,
                       const model::ShapeProcessModel& model);

// The check from both scenes' counts (the exemplar's counted once for any number of outputs).
ModelStatistics model_statistics(const PairCounts& exemplar, const PairCounts& output,
                                 const model::ShapeProcessModel& model);
// One-off: counts on both scenes; boundaries say which windows are tori.
ModelStatistics model_statistics(const geometry::Scene& exemplar,
                                 geometry::Boundary exemplar_boundary,
                                 const geometry::Scene& output, geometry::Boundary output_boundary,
                                 const model::ShapeProcessModel& model);

}  // namespace shapeproc::evaluation
