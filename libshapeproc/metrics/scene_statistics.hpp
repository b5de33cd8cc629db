// Summary statistics of an arrangement, to judge a synthesis against its exemplar
// (docs/metrics.md): collisions, intensity per category, directional nearest-neighbour and
// pair-distance distributions on shape distance, G(r) and the pair correlation g(r), and the
// Wasserstein-1 distance between two scenes' distributions. Every distance is the shape distance
// between proxies and every direction the measurement's relative orientation, measured by
// geometry::PairMeasurer, so the statistics see the arrangement the way the model does.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "libshapeproc/core/random.hpp"
#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/geometry/pair_measurements.hpp"
#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/metrics/relations.hpp"

namespace shapeproc::metrics {

// Edge treatment of an open window. `border`: Hanisch's border correction (see
// censored_distribution; pair statistics count an element's neighbours only up to its distance to
// the edge). `none`: every element counts as if the window were all there is. `automatic`: border,
// unless it would censor the nearest neighbour of more than half the elements (windows that are
// the elements' bounding box, as for meshes), then none.
using geometry::EdgeTreatment;

struct StatisticsOptions {
  // Distance kind is always the shape distance; direction kind, direction count and proxy
  // tolerance are taken from here. `periodic`: the window is a torus (no edge correction).
  geometry::MeasurementOptions measurement = default_measurement();
  EdgeTreatment edge = EdgeTreatment::automatic;  // open windows only
  double range = 0.0;  // distributions up to R; 0 means the scene's mean spacing (|W|/n)^(1/dim)
  int correlation_bins = 24;  // g(r) histogram bins over [0, R)
  int offset_samples = 0;     // Monte-Carlo offsets for g(r)'s reference measure (shaped elements);
                              // 0: 65,536 in 2D, 8,192 in 3D (mesh distances cost ~50x more)

  static geometry::MeasurementOptions default_measurement() {
    geometry::MeasurementOptions m;
    m.proxy.tolerance = geometry::kOutlineTolerance;  // collisions judged near the drawn outlines
    return m;
  }
};

// A distribution on [0, R] given by weighted samples (sorted by value, weights summing to 1).
// Values at R stand for "R or more" (no neighbour within range).
struct Distribution {
  std::vector<double> values;
  std::vector<double> weights;
  int samples = 0;  // elements or pairs behind it (after edge correction)

  bool empty() const { return values.empty(); }
  double mean() const;
  // P(X <= r).
  double cdf(double r) const;
};

// The distribution of weighted samples (value, weight): sorted by value, equal values merged,
// weights normalised; `count` is recorded as its samples.
Distribution make_distribution(std::vector<std::pair<double, double>> samples, int count);

// Wasserstein-1 distance between two distributions on the line (the area between their CDFs).
double wasserstein1(const Distribution& a, const Distribution& b);

// Edge-corrected distribution of `values` truncated at `range`: value i is observed only when it
// does not exceed `borders[i]`, the distance from element i to the window's edge (an unseen
// element can be no nearer); observed values get weight 1 / #{j : borders[j] >= value}
// (Hanisch's estimator). Pass infinite borders for a torus.
Distribution censored_distribution(const std::vector<double>& values,
                                   const std::vector<double>& borders, double range);

struct DirectionalStatistics {
  geometry::Vec3 direction = geometry::Vec3::UnitX();  // the axis' representative direction
  Distribution nearest;     // distance to the nearest neighbour in this axis bin (truncated at R)
  Distribution pairs;       // distances of all neighbours in this bin below R
  double neighbours = 0.0;  // mean number of neighbours in this bin below R per element
};

// Overlaps (signed shape distance below 0: the shapes' filled regions overlap, or one lies in
// the other's fill) and contacts (distance 0: outlines meet, nothing overlaps), apart.
struct Collisions {
  std::vector<std::pair<int, int>> pairs;     // overlapping element pairs
  std::vector<std::pair<int, int>> touching;  // element pairs that touch without overlapping
  std::vector<bool> colliding;                // per element: in an overlapping pair
  int elements = 0;                           // elements in at least one overlapping pair
};

struct SceneStatistics {
  int dimension = 2;
  geometry::Boundary boundary = geometry::Boundary::open;  // torus: no edge correction
  bool periodic() const { return boundary == geometry::Boundary::torus; }
  EdgeTreatment edge = EdgeTreatment::none;  // the treatment used (none on a torus)
  double window_measure = 0.0;
  double range = 0.0;
  double mean_spacing = 0.0;  // (|W| / n)^(1/dim)
  std::vector<std::string> categories;
  std::vector<int> counts;        // per category
  std::vector<double> intensity;  // per category, per unit area (volume)
  Collisions collisions;
  // Per category, the shares of its elements nested in or overlapping another category's
  // (relations.hpp); empty for one category, points or 3D.
  CategoryRelations relations;
  DirectionalStatistics all;                // every direction: `nearest` is G(r)
  std::vector<DirectionalStatistics> axes;  // per axis bin
  std::vector<double> correlation_r;        // bin centres
  std::vector<double> correlation;          // g(r) on shape distance (NaN where undefined)
  double seconds = 0.0;

  int elements() const;
  // Mean of the nearest-neighbour distance over all directions (truncated at R).
  double mean_nearest() const { return all.nearest.mean(); }
};

// `random` draws the Monte-Carlo offsets of g(r)'s reference measure (shaped elements only); it is
// taken by value, so callers pass a fresh generator (`core::Random(1)`) to get the same figures
// for the same scene. Throws core::ArgumentError for an empty scene or bad options.
SceneStatistics compute_statistics(const geometry::Scene& scene, const StatisticsOptions& options,
                                   core::Random random);

struct DistributionDistances {
  double nearest =
      0.0;  // W1 of nearest-neighbour distributions / the reference's mean nearest distance
  double pairs = 0.0;  // W1 of pair-distance distributions / the same scale
};

struct Comparison {
  double scale = 0.0;  // the divisor: the reference's mean nearest-neighbour distance (or spacing)
  DistributionDistances all;
  std::vector<DistributionDistances> axes;
  std::vector<double>
      intensity_ratio;  // per category of the scene: its intensity / the reference's
};

// `scene` and `reference` must have been computed with the same range and direction bins.
Comparison compare(const SceneStatistics& scene, const SceneStatistics& reference);

}  // namespace shapeproc::metrics
