#include "libshapeproc/metrics/scene_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "libshapeproc/core/check.hpp"
#include "libshapeproc/core/random.hpp"
#include "libshapeproc/core/stopwatch.hpp"

namespace shapeproc::metrics {

using geometry::Vec3;

namespace {

// #{j : borders[j] >= t} from the sorted borders.
class AtRisk {
 public:
  explicit AtRisk(std::vector<double> borders) : sorted_(std::move(borders)) {
    std::sort(sorted_.begin(), sorted_.end());
  }
  double operator()(double t) const {
    return static_cast<double>(sorted_.end() - std::lower_bound(sorted_.begin(), sorted_.end(), t));
  }

 private:
  std::vector<double> sorted_;
};

// Distance from an element's proxy box to the window's boundary (0 when it reaches outside).
double border_distance(const geometry::Box3& window, const geometry::Box3& box, int dimension) {
  double b = std::numeric_limits<double>::infinity();
  for (int k = 0; k < dimension; ++k) {
    b = std::min({b, box.min()[k] - window.min()[k], window.max()[k] - box.max()[k]});
  }
  return std::max(0.0, b);
}

geometry::Box3 proxy_box(const geometry::PairMeasurer& measurer, int shape) {
  if (measurer.dimension() == 2)
    return geometry::lift(measurer.proxies2().at(static_cast<std::size_t>(shape)).box);
  return measurer.proxies3().at(static_cast<std::size_t>(shape)).box;
}

// Reference measure of the g(r) estimator: per distance bin, the mean over ordered pairs of
// distinct elements (i, j) of the measure of offsets u with d(s_i, s_j, u) in the bin. Exact for
// points; Monte Carlo otherwise (offsets uniform in the ball where d < R is possible).
std::vector<double> offset_measure(const geometry::Scene& scene,
                                   const geometry::PairMeasurer& measurer, double range, int bins,
                                   const StatisticsOptions& options, core::Random& random) {
  const int dim = scene.dimension;
  const double width = range / bins;
  std::vector<double> measure(static_cast<std::size_t>(bins), 0.0);
  bool points = true;
  for (std::size_t s = 0; s < scene.shapes.size(); ++s)
    points = points && measurer.radius(static_cast<int>(s)) == 0.0;
  if (points) {
    for (int k = 0; k < bins; ++k)
      measure[k] =
          geometry::ball_measure((k + 1) * width, dim) - geometry::ball_measure(k * width, dim);
    return measure;
  }
  const std::size_t n = scene.elements.size();
  const int samples =
      options.offset_samples > 0 ? options.offset_samples : (dim == 2 ? 1 << 16 : 1 << 13);
  for (int m = 0; m < samples; ++m) {
    const std::size_t i = random.index(n);
    std::size_t j = random.index(n - 1);
    if (j >= i) ++j;
    const int a = scene.elements[i].shape, b = scene.elements[j].shape;
    const double reach = measurer.radius(a) + measurer.radius(b) + range;
    // Uniform in the ball of radius `reach` by rejection from its cube.
    Vec3 u = Vec3::Zero();
    do {
      for (int k = 0; k < dim; ++k) u[k] = reach * (2.0 * random.uniform() - 1.0);
    } while (u.squaredNorm() > reach * reach);
    // The boxes' bounds often settle the bin without the exact distance.
    const auto [low, high] = measurer.distance_bounds(a, b, u);
    if (low >= range) continue;
    int k = std::min(bins - 1, static_cast<int>(low / width));
    if (high >= range || std::min(bins - 1, static_cast<int>(high / width)) != k) {
      const double d = measurer.distance(a, b, u, range);
      if (d >= range) continue;
      k = std::min(bins - 1, static_cast<int>(std::max(0.0, d) / width));  // overlaps: 0
    }
    measure[k] += geometry::ball_measure(reach, dim) / samples;
  }
  return measure;
}

}  // namespace

Distribution make_distribution(std::vector<std::pair<double, double>> samples, int count) {
  Distribution d;
  d.samples = count;
  std::sort(samples.begin(), samples.end());
  double total = 0.0;
  for (const auto& s : samples) total += s.second;
  if (!(total > 0)) return d;
  for (const auto& s : samples) {
    if (!d.values.empty() && d.values.back() == s.first) {
      d.weights.back() += s.second / total;
    } else {
      d.values.push_back(s.first);
      d.weights.push_back(s.second / total);
    }
  }
  return d;
}

double Distribution::mean() const {
  double m = 0.0;
  for (std::size_t i = 0; i < values.size(); ++i) m += values[i] * weights[i];
  return values.empty() ? std::numeric_limits<double>::quiet_NaN() : m;
}

double Distribution::cdf(double r) const {
  double c = 0.0;
  for (std::size_t i = 0; i < values.size() && values[i] <= r; ++i) c += weights[i];
  return std::min(1.0, c);
}

double wasserstein1(const Distribution& a, const Distribution& b) {
  if (a.empty() || b.empty()) return std::numeric_limits<double>::quiet_NaN();
  // Walk the merged breakpoints; between two of them both CDFs are constant.
  std::size_t i = 0, j = 0;
  double fa = 0.0, fb = 0.0, last = std::min(a.values.front(), b.values.front()), area = 0.0;
  while (i < a.values.size() || j < b.values.size()) {
    const double next =
        std::min(i < a.values.size() ? a.values[i] : std::numeric_limits<double>::infinity(),
                 j < b.values.size() ? b.values[j] : std::numeric_limits<double>::infinity());
    area += std::abs(fa - fb) * (next - last);
    last = next;
    while (i < a.values.size() && a.values[i] == next) fa += a.weights[i++];
    while (j < b.values.size() && b.values[j] == next) fb += b.weights[j++];
  }
  return area;
}

Distribution censored_distribution(const std::vector<double>& values,
                                   const std::vector<double>& borders, double range) {
  const AtRisk at_risk(borders);
  std::vector<std::pair<double, double>> samples;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double t = std::min(values[i], range);
    if (t > borders[i]) continue;  // censored: an unseen element could be nearer
    samples.emplace_back(t, 1.0 / at_risk(t));
  }
  const int count = static_cast<int>(samples.size());
  return make_distribution(std::move(samples), count);
}

int SceneStatistics::elements() const { return std::accumulate(counts.begin(), counts.end(), 0); }

namespace {

// Shape distances within this share of the range of 0 are a contact, not an overlap or a gap:
// the rounding of outlines that meet, in floating point and in a drawing's coordinates (about 7
// significant digits: flipped-diamonds grown at its own offsets measured −2.2e-8 apart).
constexpr double kContactRounding = 1e-6;

// The statistics that need no measurement: counts, intensities, the mean spacing and the range.
SceneStatistics counted(const geometry::Scene& scene, const StatisticsOptions& options) {
  const std::size_t n = scene.elements.size();
  SceneStatistics stats;
  stats.dimension = scene.dimension;
  stats.boundary =
      options.measurement.periodic ? geometry::Boundary::torus : geometry::Boundary::open;
  stats.window_measure = scene.window_measure();
  core::check_positive("statistics", "the window's measure", stats.window_measure);
  stats.mean_spacing =
      std::pow(stats.window_measure / static_cast<double>(n), 1.0 / scene.dimension);
  stats.range = options.range > 0 ? options.range : stats.mean_spacing;
  for (const geometry::Category& c : scene.categories) stats.categories.push_back(c.name);
  stats.counts.assign(stats.categories.size(), 0);
  for (const geometry::Element& e : scene.elements)
    ++stats.counts.at(static_cast<std::size_t>(e.category));
  for (int c : stats.counts) stats.intensity.push_back(c / stats.window_measure);
  return stats;
}

// Each element's distance to the window's edge, infinite on a torus or without border
// correction; decides stats.edge where it is automatic (border when at least half the elements
// see their nearest neighbour, within the range, before the edge).
std::vector<double> edge_distances(const geometry::Scene& scene,
                                   const geometry::PairMeasurer& measurer,
                                   const std::vector<double>& nearest,
                                   const StatisticsOptions& options, SceneStatistics& stats) {
  const std::size_t n = scene.elements.size();
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> borders(n, inf);
  if (stats.periodic()) return borders;
  for (std::size_t i = 0; i < n; ++i) {
    const geometry::Element& e = scene.elements[i];
    geometry::Box3 box = proxy_box(measurer, e.shape);
    box.translate(e.position);
    borders[i] = border_distance(scene.window, box, scene.dimension);
  }
  stats.edge = options.edge;
  if (options.edge == EdgeTreatment::automatic) {
    std::size_t observed = 0;
    for (std::size_t i = 0; i < n; ++i)
      observed += std::min(nearest[i], stats.range) <= borders[i] ? 1 : 0;
    stats.edge = 2 * observed >= n ? EdgeTreatment::border : EdgeTreatment::none;
  }
  if (stats.edge == EdgeTreatment::none) borders.assign(n, inf);
  return borders;
}

// The pairs' contributions: nearest distances per axis, weighted distance samples (all and per
// axis) and neighbour counts per correlation bin, each end of a pair counted where it sees all
// its neighbours at that distance; collisions and contacts go to `collisions`.
struct PairTally {
  std::vector<std::vector<double>> nearest_axis;
  std::vector<std::pair<double, double>> all;
  std::vector<std::vector<std::pair<double, double>>> by_axis;
  std::vector<double> correlation_counts;
};

PairTally tally_pairs(const std::vector<geometry::PairRecord>& pairs,
                      const std::vector<double>& borders, int axes, double range, int bins,
                      Collisions& collisions) {
  const std::size_t n = borders.size();
  const AtRisk at_risk(borders);
  PairTally t;
  t.nearest_axis.assign(static_cast<std::size_t>(axes),
                        std::vector<double>(n, std::numeric_limits<double>::infinity()));
  t.by_axis.resize(static_cast<std::size_t>(axes));
  t.correlation_counts.assign(static_cast<std::size_t>(bins), 0.0);
  collisions.colliding.assign(n, false);
  const double width = range / bins;
  for (const geometry::PairRecord& p : pairs) {
    // Signed shape distance: below 0 the shapes overlap, at 0 they touch; the distributions
    // take the gap, 0 for both. Within rounding of 0 (kContactRounding of the range) they touch.
    const double signed_distance = p.measurement.distance;
    const double d = std::max(0.0, signed_distance);
    const int axis = p.measurement.axis;
    const double rounding = kContactRounding * range;
    if (signed_distance < -rounding) {
      collisions.pairs.emplace_back(p.i, p.j);
      collisions.colliding[p.i] = collisions.colliding[p.j] = true;
    } else if (signed_distance <= rounding) {
      collisions.touching.emplace_back(p.i, p.j);
    }
    for (const int e : {p.i, p.j}) {
      t.nearest_axis[axis][e] = std::min(t.nearest_axis[axis][e], d);
      if (d > borders[e]) continue;  // this end is too close to the edge to see all neighbours at d
      const double w = 1.0 / at_risk(d);
      t.all.emplace_back(d, w);
      t.by_axis[axis].emplace_back(d, w);
      t.correlation_counts[std::min(bins - 1, static_cast<int>(d / width))] += w;
    }
  }
  collisions.elements =
      static_cast<int>(std::count(collisions.colliding.begin(), collisions.colliding.end(), true));
  return t;
}

// The weighted pair distances' distribution and their total weight (the mean neighbour count).
void pair_statistics(DirectionalStatistics& out, std::vector<std::pair<double, double>> samples) {
  double total = 0.0;
  for (const auto& s : samples) total += s.second;
  out.neighbours = total;
  const int count = static_cast<int>(samples.size());
  out.pairs = make_distribution(std::move(samples), count);
}

}  // namespace

SceneStatistics compute_statistics(const geometry::Scene& scene, const StatisticsOptions& options,
                                   core::Random random) {
  const core::Stopwatch watch;
  core::check(!scene.elements.empty(), "statistics", "the scene has no elements");
  core::check_non_negative("statistics", "the range", options.range);
  core::check(options.correlation_bins >= 1, "statistics",
              "at least one correlation bin is needed");
  const std::size_t n = scene.elements.size();
  SceneStatistics stats = counted(scene, options);
  const double range = stats.range;

  geometry::MeasurementOptions measurement = options.measurement;
  measurement.distance = geometry::DistanceKind::shape;
  const geometry::PairMeasurer measurer(scene, measurement);
  const std::vector<geometry::PairRecord> pairs = measurer.all_pairs(scene.elements, range);
  const int axes = measurer.bins().axis_count();
  stats.relations = category_relations(scene, measurer);

  std::vector<double> nearest(n, std::numeric_limits<double>::infinity());
  for (const geometry::PairRecord& p : pairs) {
    const double gap = std::max(0.0, p.measurement.distance);
    nearest[p.i] = std::min(nearest[p.i], gap);
    nearest[p.j] = std::min(nearest[p.j], gap);
  }
  const std::vector<double> borders = edge_distances(scene, measurer, nearest, options, stats);
  PairTally tally =
      tally_pairs(pairs, borders, axes, range, options.correlation_bins, stats.collisions);

  stats.all.nearest = censored_distribution(nearest, borders, range);
  pair_statistics(stats.all, std::move(tally.all));
  for (int k = 0; k < axes; ++k) {
    DirectionalStatistics a;
    a.direction = measurer.bins().axis_direction(k);
    a.nearest = censored_distribution(tally.nearest_axis[k], borders, range);
    pair_statistics(a, std::move(tally.by_axis[k]));
    stats.axes.push_back(std::move(a));
  }

  // g(r): the edge-corrected mean number of neighbours per distance bin over the number a
  // binomial pattern of the same elements would give, (n - 1) / |W| times the offset measure.
  const std::vector<double> reference =
      n > 1 ? offset_measure(scene, measurer, range, options.correlation_bins, options, random)
            : std::vector<double>(static_cast<std::size_t>(options.correlation_bins), 0.0);
  const double density = static_cast<double>(n - 1) / stats.window_measure;
  const double width = range / options.correlation_bins;
  for (int k = 0; k < options.correlation_bins; ++k) {
    stats.correlation_r.push_back((k + 0.5) * width);
    const double expected = density * reference[k];
    stats.correlation.push_back(expected > 0 ? tally.correlation_counts[k] / expected
                                             : std::numeric_limits<double>::quiet_NaN());
  }
  stats.seconds = watch.seconds();
  return stats;
}

Comparison compare(const SceneStatistics& scene, const SceneStatistics& reference) {
  if (scene.axes.size() != reference.axes.size() ||
      std::abs(scene.range - reference.range) > 1e-9 * reference.range) {
    throw core::ArgumentError(
        "compare",
        "statistics computed with different ranges or direction bins cannot be compared");
  }
  Comparison c;
  c.scale = reference.mean_nearest();
  // Packed exemplars (touching elements) have a mean nearest distance near 0; fall back on the
  // spacing so that the ratio stays meaningful.
  if (!(c.scale > 1e-3 * reference.mean_spacing)) c.scale = reference.mean_spacing;
  auto distances = [&](const DirectionalStatistics& a, const DirectionalStatistics& b) {
    return DistributionDistances{wasserstein1(a.nearest, b.nearest) / c.scale,
                                 wasserstein1(a.pairs, b.pairs) / c.scale};
  };
  c.all = distances(scene.all, reference.all);
  for (std::size_t k = 0; k < scene.axes.size(); ++k)
    c.axes.push_back(distances(scene.axes[k], reference.axes[k]));
  for (std::size_t k = 0; k < scene.categories.size(); ++k) {
    double ratio = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t r = 0; r < reference.categories.size(); ++r) {
      if (reference.categories[r] == scene.categories[k] && reference.intensity[r] > 0) {
        ratio = scene.intensity[k] / reference.intensity[r];
      }
    }
    c.intensity_ratio.push_back(ratio);
  }
  return c;
}

}  // namespace shapeproc::metrics
