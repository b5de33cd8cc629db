// Simulation envelopes (the idea of spatstat's envelope(); Baddeley, Rubak and Turner 2015,
// ch. 10): does the exemplar look like a sample of its fitted model? The model is sampled
// `samples` times on the exemplar's own window and boundary; for each nearest-neighbour
// distribution, over all directions (G) and per axis, and for the pair correlation g(r) on shape
// distance, the pointwise minimum and maximum of the samples' curves form a band, and the
// exemplar's curve is checked against it (CDFs on a grid of distances, g in its bins).
// With 19 samples a curve of the model itself leaves the band at a given distance with
// probability 2/20 (two-sided); an envelope check fails when the exemplar's curve is outside the
// band over more than a quarter of the distances.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/model/shape_process_model.hpp"

namespace shapeproc::evaluation {

inline constexpr double kEnvelopeOutsideLimit = 0.25;

struct EnvelopeCurve {
  std::string label;  // "G, all directions", "G, axis 2 (90°)", "g(r), all directions"
  std::vector<double> r, exemplar, low, high;
  double outside = 0.0;  // share of r where the exemplar's CDF leaves [low, high]
  bool passes() const { return outside <= kEnvelopeOutsideLimit; }
};

struct EnvelopeOptions {
  int samples = 19;
  long long steps = 20000;  // per sample, from the empty configuration
  int points = 32;          // distances on [0, R], R the exemplar's mean spacing
  std::uint64_t seed = 1;
};

// Throws core::ArgumentError when the model does not fit the exemplar's dimension.
std::vector<EnvelopeCurve> nearest_envelopes(const geometry::Scene& exemplar,
                                             geometry::Boundary boundary,
                                             const model::ShapeProcessModel& model,
                                             const EnvelopeOptions& options = {});

}  // namespace shapeproc::evaluation
