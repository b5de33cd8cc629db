#include "libshapeproc/metrics/novelty.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include "libshapeproc/core/check.hpp"
#include "libshapeproc/core/random.hpp"
#include "libshapeproc/geometry/neighbour_grid.hpp"
#include "libshapeproc/geometry/shape_size.hpp"

namespace shapeproc::metrics {

namespace {

using geometry::Vec3;

// A lattice exemplar holds at most this many elements per primitive cell (its basis).
constexpr int kLatticeBasis = 2;
// Two shapes are the same as drawn when their boxes' sides also agree within this (side_distance).
constexpr double kSideTolerance = 0.2;
// Candidate translations scored on every output element after the screening.
constexpr std::size_t kFinalists = 8;

double mean_spacing(const geometry::Scene& scene) {
  const double measure = scene.window_measure();
  return std::pow(measure / static_cast<double>(scene.elements.size()), 1.0 / scene.dimension);
}

// Size classes over the shapes of both scenes: a shape joins the first class whose first shape is
// within the size tolerance, else starts one.
struct SizeClasses {
  std::vector<int> exemplar, output;  // per element
};

// A shape's size and the sides of its bounding box as drawn: the box tells a turned shape from
// the same shape unturned (a segment across from one along).
struct ShapeKey {
  geometry::ShapeSize size;
  Vec3 sides = Vec3::Zero();
};

ShapeKey shape_key(const geometry::Shape& shape) {
  ShapeKey key{geometry::shape_size(shape), Vec3::Zero()};
  const geometry::Box3 box = geometry::bounding_box(shape);
  if (!box.isEmpty()) key.sides = box.sizes();
  return key;
}

// Σ |log ratio| of the box's sides, each side counted from a quarter of the radius up, so that a
// thin shape's near-zero side does not tell apart turns of a few degrees.
double side_distance(const ShapeKey& a, const ShapeKey& b) {
  const double floor = 0.25 * std::max({a.size.radius, b.size.radius, 1e-12});
  double d = 0.0;
  for (int axis = 0; axis < 3; ++axis)
    d += std::abs(std::log((a.sides[axis] + floor) / (b.sides[axis] + floor)));
  return d;
}

SizeClasses size_classes(const geometry::Scene& exemplar, const geometry::Scene& output,
                         double tolerance) {
  std::vector<ShapeKey> representatives;
  auto classify = [&](const geometry::Scene& scene) {
    std::vector<int> of_shape(scene.shapes.size(), -1);
    for (std::size_t s = 0; s < scene.shapes.size(); ++s) {
      const ShapeKey key = shape_key(scene.shapes[s]);
      int found = -1;
      for (std::size_t k = 0; k < representatives.size() && found < 0; ++k)
        if (geometry::size_distance(key.size, representatives[k].size) <= tolerance &&
            side_distance(key, representatives[k]) <= kSideTolerance)
          found = static_cast<int>(k);
      if (found < 0) {
        found = static_cast<int>(representatives.size());
        representatives.push_back(key);
      }
      of_shape[s] = found;
    }
    std::vector<int> of_element;
    for (const geometry::Element& e : scene.elements)
      of_element.push_back(of_shape.empty() ? 0 : of_shape[static_cast<std::size_t>(e.shape)]);
    return of_element;
  };
  SizeClasses classes;
  classes.exemplar = classify(exemplar);
  classes.output = classify(output);
  return classes;
}

// The exemplar tiled over all space with its window as the period: is there an element of a
// size class within τ of a position?
class Tiling {
 public:
  Tiling(const geometry::Scene& exemplar, const std::vector<int>& classes, double tolerance)
      : exemplar_(exemplar),
        classes_(classes),
        tolerance_(tolerance),
        period_(exemplar.window.sizes()),
        grid_(exemplar.window, exemplar.dimension, tolerance, true) {
    if (exemplar.dimension == 2) period_.z() = 0.0;
    for (std::size_t j = 0; j < exemplar.elements.size(); ++j)
      grid_.insert(static_cast<int>(j), wrap(exemplar.elements[j].position));
  }

  Vec3 wrap(Vec3 p) const {
    for (int axis = 0; axis < exemplar_.dimension; ++axis) {
      const double low = exemplar_.window.min()[axis];
      p[axis] =
          low + std::fmod(std::fmod(p[axis] - low, period_[axis]) + period_[axis], period_[axis]);
    }
    return p;
  }
  const Vec3& period() const { return period_; }

  bool matches(const Vec3& position, int size_class) const {
    const Vec3 p = wrap(position);
    bool found = false;
    grid_.for_each_candidate(p, [&](int j) {
      if (found || classes_[static_cast<std::size_t>(j)] != size_class) return;
      const Vec3 d = geometry::minimum_image(
          p - exemplar_.elements[static_cast<std::size_t>(j)].position, period_);
      if (d.norm() <= tolerance_) found = true;
    });
    return found;
  }

 private:
  const geometry::Scene& exemplar_;
  const std::vector<int>& classes_;
  double tolerance_;
  Vec3 period_;
  geometry::NeighbourGrid grid_;
};

// The output's positions with their k nearest neighbours (offsets, minimum image on a torus) and a
// grid for queries within τ.
struct OutputIndex {
  std::vector<Vec3> positions;
  std::vector<int> classes;
  std::vector<std::vector<std::pair<int, Vec3>>> nearest;  // neighbour and offset, nearest first
  geometry::Domain domain;
  double cell = 0.0;
  geometry::NeighbourGrid grid;

  OutputIndex(std::vector<Vec3> p, std::vector<int> c, const geometry::Domain& d, double cell_size,
              int k)
      : positions(std::move(p)),
        classes(std::move(c)),
        domain(d),
        cell(cell_size),
        grid(d.box(), d.dimension(), cell_size, d.periodic()) {
    for (std::size_t i = 0; i < positions.size(); ++i)
      grid.insert(static_cast<int>(i), positions[i]);
    nearest.resize(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) find_nearest(i, k);
  }

  void find_nearest(std::size_t i, int k) {
    std::vector<std::pair<double, std::pair<int, Vec3>>> found;
    auto consider = [&](int j) {
      if (j == static_cast<int>(i)) return;
      const Vec3 d = domain.minimum_image(positions[static_cast<std::size_t>(j)] - positions[i]);
      found.push_back({d.norm(), {j, d}});
    };
    grid.for_each_candidate(positions[i], consider);
    // The cells around hold every neighbour within one cell; fewer than k there: look at all.
    const auto within =
        std::count_if(found.begin(), found.end(), [&](const auto& f) { return f.first <= cell; });
    if (within < k) {
      found.clear();
      for (std::size_t j = 0; j < positions.size(); ++j) consider(static_cast<int>(j));
    }
    const std::size_t keep = std::min(found.size(), static_cast<std::size_t>(k));
    std::partial_sort(found.begin(), found.begin() + static_cast<std::ptrdiff_t>(keep), found.end(),
                      [](const auto& a, const auto& b) { return a.first < b.first; });
    for (std::size_t n = 0; n < keep; ++n) nearest[i].push_back(found[n].second);
  }

  // An element of `size_class` other than `self` within `radius` of `position` (which must lie
  // in the box).
  bool occupied(const Vec3& position, int size_class, double radius, int self) const {
    bool found = false;
    grid.for_each_candidate(position, [&](int j) {
      if (found || j == self || classes[static_cast<std::size_t>(j)] != size_class) return;
      if (domain.minimum_image(positions[static_cast<std::size_t>(j)] - position).norm() <= radius)
        found = true;
    });
    return found;
  }
};

int count_copies(const OutputIndex& out, const Tiling& tiling, const Vec3& t,
                 const std::vector<std::size_t>& among) {
  int n = 0;
  for (std::size_t i : among)
    if (tiling.matches(out.positions[i] - t, out.classes[i])) ++n;
  return n;
}

std::vector<std::size_t> spread_indices(std::size_t n, int wanted) {
  std::vector<std::size_t> out;
  const std::size_t count = wanted <= 0 ? n : std::min(n, static_cast<std::size_t>(wanted));
  for (std::size_t k = 0; k < count; ++k) out.push_back(k * n / count);
  return out;
}

// t*: the translation under which the most output elements are copies.
Vec3 best_translation(const OutputIndex& out, const geometry::Scene& exemplar,
                      const std::vector<int>& exemplar_classes, const Tiling& tiling,
                      const NoveltyOptions& options) {
  const std::size_t n = out.positions.size();
  const std::vector<std::size_t> screening = spread_indices(n, options.screening);
  std::vector<std::pair<int, Vec3>> scored;
  for (std::size_t a : spread_indices(n, options.anchors)) {
    for (std::size_t j = 0; j < exemplar.elements.size(); ++j) {
      if (exemplar_classes[j] != out.classes[a]) continue;
      const Vec3 t = out.positions[a] - exemplar.elements[j].position;
      scored.push_back({count_copies(out, tiling, t, screening), t});
    }
  }
  if (scored.empty()) return Vec3::Zero();
  const std::size_t keep = std::min(scored.size(), kFinalists);
  std::partial_sort(scored.begin(), scored.begin() + static_cast<std::ptrdiff_t>(keep),
                    scored.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<std::size_t> all(n);
  std::iota(all.begin(), all.end(), std::size_t{0});
  Vec3 best = scored[0].second;
  int best_count = -1;
  for (std::size_t f = 0; f < keep; ++f) {
    const int count = count_copies(out, tiling, scored[f].second, all);
    if (count > best_count) {
      best_count = count;
      best = scored[f].second;
    }
  }
  return best;
}

// Whether element i and its nearest neighbours are all copies under translation t.
bool copied_neighbourhood(const OutputIndex& out, const Tiling& tiling, std::size_t i,
                          const Vec3& t) {
  if (!tiling.matches(out.positions[i] - t, out.classes[i])) return false;
  for (const auto& [j, offset] : out.nearest[i])
    if (!tiling.matches(out.positions[i] + offset - t, out.classes[static_cast<std::size_t>(j)]))
      return false;
  return true;
}

int find_root(std::vector<int>& parent, int i) {
  while (parent[static_cast<std::size_t>(i)] != i) {
    parent[static_cast<std::size_t>(i)] =
        parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(i)])];
    i = parent[static_cast<std::size_t>(i)];
  }
  return i;
}

// The largest set of copied neighbourhoods joined by nearest-neighbour links whose translations
// agree within τ (modulo the exemplar's period), as a share of the output.
double largest_patch(const OutputIndex& out, const geometry::Scene& exemplar,
                     const std::vector<int>& exemplar_classes, const Tiling& tiling,
                     double tolerance) {
  const std::size_t n = out.positions.size();
  std::vector<std::vector<Vec3>> translations(n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < exemplar.elements.size(); ++j) {
      if (exemplar_classes[j] != out.classes[i]) continue;
      const Vec3 t = out.positions[i] - exemplar.elements[j].position;
      if (copied_neighbourhood(out, tiling, i, t)) translations[i].push_back(t);
    }
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  for (std::size_t i = 0; i < n; ++i) {
    if (translations[i].empty()) continue;
    for (const auto& [k, offset] : out.nearest[i]) {
      const std::size_t kk = static_cast<std::size_t>(k);
      if (translations[kk].empty()) continue;
      // k's translation seen from i's side of a torus seam.
      const Vec3 shift = out.positions[i] + offset - out.positions[kk];
      bool agree = false;
      for (const Vec3& a : translations[i])
        for (const Vec3& b : translations[kk])
          agree = agree ||
                  geometry::minimum_image(a - (b + shift), tiling.period()).norm() <= tolerance;
      if (agree)
        parent[static_cast<std::size_t>(find_root(parent, static_cast<int>(i)))] =
            find_root(parent, k);
    }
  }
  std::vector<int> size(n, 0);
  int largest = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (!translations[i].empty())
      largest = std::max(largest,
                         ++size[static_cast<std::size_t>(find_root(parent, static_cast<int>(i)))]);
  return static_cast<double>(largest) / static_cast<double>(n);
}

// The share of elements repeated by a same-size element at each of the exemplar's period vectors
// (those shorter than the output along their axis: a torus's own period says nothing).
double repetition(const OutputIndex& out, const Vec3& period, int dimension, double tolerance) {
  long long eligible = 0, repeated = 0;
  for (int axis = 0; axis < dimension; ++axis) {
    if (!(period[axis] < out.domain.sizes()[axis] - tolerance)) continue;
    Vec3 step = Vec3::Zero();
    step[axis] = period[axis];
    for (std::size_t i = 0; i < out.positions.size(); ++i) {
      Vec3 target = out.positions[i] + step;
      if (out.domain.periodic())
        target = out.domain.wrap(target);
      else if (!out.domain.contains(target))
        continue;
      ++eligible;
      if (out.occupied(target, out.classes[i], tolerance, static_cast<int>(i))) ++repeated;
    }
  }
  return eligible > 0 ? static_cast<double>(repeated) / static_cast<double>(eligible) : 0.0;
}

CopyMeasures copy_measures(const OutputIndex& out, const geometry::Scene& exemplar,
                           const std::vector<int>& exemplar_classes, const Tiling& tiling,
                           double tolerance, const NoveltyOptions& options, Vec3* translation) {
  const std::size_t n = out.positions.size();
  const Vec3 t = best_translation(out, exemplar, exemplar_classes, tiling, options);
  if (translation) *translation = t;
  CopyMeasures m;
  int copies = 0, patches = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (tiling.matches(out.positions[i] - t, out.classes[i])) ++copies;
    if (copied_neighbourhood(out, tiling, i, t)) ++patches;
  }
  m.copy = static_cast<double>(copies) / static_cast<double>(n);
  m.patch = static_cast<double>(patches) / static_cast<double>(n);
  m.largest_patch = largest_patch(out, exemplar, exemplar_classes, tiling, tolerance);
  m.repetition = repetition(out, tiling.period(), exemplar.dimension, tolerance);
  return m;
}

void check_scenes(const geometry::Scene& exemplar, const geometry::Scene& output) {
  core::check(!exemplar.elements.empty() && !output.elements.empty(), "novelty",
              "both scenes need elements");
  core::check(exemplar.dimension == output.dimension, "novelty",
              "the exemplar is " + std::to_string(exemplar.dimension) + "D but the output " +
                  std::to_string(output.dimension) + "D");
  core::check(exemplar.window_measure() > 0 && output.window_measure() > 0, "novelty",
              "both scenes need a window of positive size");
}

bool lattice_of_classes(const geometry::Scene& exemplar, const std::vector<int>& classes,
                        const Tiling& tiling) {
  const std::size_t n = exemplar.elements.size();
  const int class_count = *std::max_element(classes.begin(), classes.end()) + 1;
  std::vector<int> members(static_cast<std::size_t>(class_count), 0);
  for (int c : classes) ++members[static_cast<std::size_t>(c)];
  const int cells = *std::min_element(members.begin(), members.end());
  if (static_cast<int>(n) > kLatticeBasis * std::max(1, cells)) return false;
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = 0; b < n; ++b) {
      if (a == b || classes[a] != classes[b]) continue;
      const Vec3 t = exemplar.elements[b].position - exemplar.elements[a].position;
      for (std::size_t e = 0; e < n; ++e)
        if (!tiling.matches(exemplar.elements[e].position + t, classes[e])) return false;
    }
  return true;
}

}  // namespace

bool is_lattice_exemplar(const geometry::Scene& exemplar, double tolerance, double size_tolerance) {
  check_scenes(exemplar, exemplar);
  const double tau = tolerance > 0 ? tolerance : 0.25 * mean_spacing(exemplar);
  const SizeClasses classes = size_classes(exemplar, exemplar, size_tolerance);
  const Tiling tiling(exemplar, classes.exemplar, tau);
  return lattice_of_classes(exemplar, classes.exemplar, tiling);
}

Novelty measure_novelty(const geometry::Scene& exemplar, const geometry::Scene& output,
                        geometry::Boundary output_boundary, const NoveltyOptions& options) {
  check_scenes(exemplar, output);
  core::check(options.neighbours >= 1 && options.chance_draws >= 0, "novelty",
              "the patch needs at least one neighbour and the chance draws must be >= 0");
  Novelty result;
  result.elements = static_cast<int>(output.elements.size());
  result.tolerance = options.tolerance > 0 ? options.tolerance : 0.25 * mean_spacing(exemplar);
  const SizeClasses classes = size_classes(exemplar, output, options.size_tolerance);
  const Tiling tiling(exemplar, classes.exemplar, result.tolerance);
  const geometry::Domain domain(output.window, output.dimension, output_boundary);
  const double cell = std::max(result.tolerance, 2.0 * mean_spacing(output));
  std::vector<Vec3> positions;
  for (const geometry::Element& e : output.elements) positions.push_back(domain.wrap(e.position));
  const OutputIndex out(positions, classes.output, domain, cell, options.neighbours);
  result.output = copy_measures(out, exemplar, classes.exemplar, tiling, result.tolerance, options,
                                &result.translation);
  core::Random random(options.seed);
  for (int draw = 0; draw < options.chance_draws; ++draw) {
    for (Vec3& p : positions)
      for (int axis = 0; axis < output.dimension; ++axis)
        p[axis] = random.uniform(output.window.min()[axis], output.window.max()[axis]);
    const OutputIndex placed(positions, classes.output, domain, cell, options.neighbours);
    const CopyMeasures m = copy_measures(placed, exemplar, classes.exemplar, tiling,
                                         result.tolerance, options, nullptr);
    const double w = 1.0 / options.chance_draws;
    result.chance.copy += w * m.copy;
    result.chance.patch += w * m.patch;
    result.chance.largest_patch += w * m.largest_patch;
    result.chance.repetition += w * m.repetition;
  }
  result.lattice_exemplar = lattice_of_classes(exemplar, classes.exemplar, tiling);
  result.repeats_exemplar =
      !result.lattice_exemplar && (result.output.patch - result.chance.patch > kPatchExcess ||
                                   result.output.largest_patch > kLargestPatch);
  return result;
}

}  // namespace shapeproc::metrics
