#include "libshapeproc/fit/fit_thresholds.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

#include "libshapeproc/core/check.hpp"
#include "libshapeproc/fit/fit_defaults.hpp"
#include "libshapeproc/fit/parameter_budget.hpp"
#include "libshapeproc/fit/quantile.hpp"
#include "libshapeproc/geometry/directions.hpp"

namespace shapeproc::fit {

using geometry::Element;

namespace {

// The tuning constants (fit_defaults.hpp has what each does and why).
constexpr double kCoincide = kFitDefaults.coincide;
constexpr double kNestedDepth = kFitDefaults.nested_depth;
constexpr double kShellJitter = kFitDefaults.shell_jitter;
constexpr double kShellShare = kFitDefaults.shell_share;
constexpr std::size_t kShellPairs = kFitDefaults.shell_pairs;
constexpr double kHardCoreLevel = kFitDefaults.hard_core_level;
// A hair, as a share of the shell half-width.
constexpr double kDegenerate = 1e-6;

// A hair below the smallest distance d: at 0 for touching pairs, below 0 for overlapping ones.
double hard_core_below(double d, double w) {
  return d >= 0.0 ? std::max(0.0, d - kDegenerate * w) : d - kDegenerate * w;
}

// Overlap and separation are distinct relations (disjoint, touching, overlapping, nested): where
// an axis's bands run from overlapping pairs (d < 0) to separate ones, a threshold at 0 puts them
// in bands of their own. An axis whose range ends at or below 0 (every banded pair overlaps) gets
// a last band up to a hair above 0, so that its range covers contact and every measurement has a
// positive cut-off.
void split_at_contact(std::vector<double>& thresholds, double w) {
  if (thresholds.empty() || thresholds.front() >= 0.0) return;
  const double hair = kDegenerate * w;
  if (thresholds.back() <= 0.0) {
    thresholds.push_back(std::max(hair, thresholds.back() + hair));
    return;
  }
  const auto above = std::upper_bound(thresholds.begin(), thresholds.end(), 0.0);
  if (std::abs(*(above - 1)) > hair && std::abs(*above) > hair) thresholds.insert(above, 0.0);
}

// Quantile thresholds. Where several quantiles coincide, the distance d they share is a shell of
// a lattice (hexagons gave [2.0155443424633040, 2.0155443424633073) for three quantiles): its
// pairs repeat one distance, and a band narrower than a shift's rounding could neither keep them
// nor regain them. The shell gets the band [d − w, d + w) of half-width `w` instead: its γ holds
// elements near the lattice distance, grains and defects allowed, and where the shell is the
// closest one the hard core sits at d − w, so that a chain from empty has room to order.
std::vector<double> thresholds_from(std::vector<double> distances,
                                    const std::vector<double>& quantiles, double w,
                                    std::size_t elements) {
  std::sort(distances.begin(), distances.end());
  std::vector<double> values;  // distinct quantile values, with how many quantiles share each
  std::vector<int> shared;
  for (double q : quantiles) {
    const double d = quantile(distances, q);
    if (!values.empty() && d - values.back() < kCoincide * w) {
      ++shared.back();
    } else {
      values.push_back(d);
      shared.push_back(1);
    }
  }
  // The smallest distance is a shell too when many pairs repeat it, though only the quantile 0
  // falls on it: a lattice's nearest neighbours along an axis whose farther pairs are many
  // (autumn, 72 elements fitted: 72 of the 1,656 pairs along its rows at the closest distance).
  if (!values.empty() && shared.front() == 1 && distances.size() >= kShellPairs) {
    const auto repeated =
        std::lower_bound(distances.begin(), distances.end(), distances.front() + kCoincide * w) -
        distances.begin();
    if (static_cast<double>(repeated) >= kShellShare * static_cast<double>(elements) &&
        repeated >= static_cast<std::ptrdiff_t>(kShellPairs))
      shared.front() = 2;
  }
  std::vector<double> thresholds;
  for (std::size_t k = 0; k < values.size(); ++k) {
    const double d = values[k];
    const double floor = thresholds.empty() ? -std::numeric_limits<double>::infinity()
                                            : thresholds.back() + kDegenerate * w;
    if (shared[k] == 1) {
      // The hard core sits a hair below the smallest distance, so that the exemplar's closest
      // pairs, measured again after a translation, do not fall below it by rounding; a hard core
      // at 0 (touching) stays at 0. A negative one (the exemplar overlaps or nests the pair) sits
      // a hair below its deepest overlap.
      thresholds.push_back(k == 0 ? hard_core_below(d, w) : std::max(floor, d));
      continue;
    }
    const double next = k + 1 < values.size() ? values[k + 1] : d + 2 * w;
    // (A shell of separate pairs keeps its hard core at 0 at least: it never allows overlaps.)
    thresholds.push_back(std::max(floor, d >= 0.0 ? std::max(0.0, d - w) : d - w));
    thresholds.push_back(
        std::max(thresholds.back() + kDegenerate * w, std::min(d + w, 0.5 * (d + next))));
  }
  // A band that holds no pair (above a shell, up to a quantile that falls on the next shell's
  // distance, which its half-open band leaves out) would get γ = 0: a forbidden ring where the
  // exemplar merely has no pair. It joins the band above it, or the range ends below it.
  const auto pairs_in = [&](double lo, double hi) {
    return std::lower_bound(distances.begin(), distances.end(), hi) -
           std::lower_bound(distances.begin(), distances.end(), lo);
  };
  for (std::size_t k = thresholds.size(); k-- > 2;)
    if (pairs_in(thresholds[k - 1], thresholds[k]) == 0)
      thresholds.erase(thresholds.begin() + static_cast<std::ptrdiff_t>(k));
  split_at_contact(thresholds, w);
  return thresholds;
}

// The distances the quantiles are taken of: all of them, or where the highest quantile lies at or
// beyond the range cap (an exemplar of many elements: its quantiles of every pair in the window
// lie far past its spacing), those below the cap, so that the bands divide the range the pair
// may have rather than collapse into one band up to the cap (amacrine: one band from its hard
// core to 2.5 spacings, where its cells' inhibition acts within one).
std::vector<double> within_range(const std::vector<double>& distances,
                                 const std::vector<double>& quantiles, double cap) {
  if (quantiles.empty() || distances.size() < 2 || !(cap > 0)) return distances;
  std::vector<double> sorted = distances;
  std::sort(sorted.begin(), sorted.end());
  const double top = *std::max_element(quantiles.begin(), quantiles.end());
  if (quantile(sorted, top) < cap) return distances;
  std::vector<double> below;
  for (double d : distances)
    if (d < cap) below.push_back(d);
  return below.size() >= 2 ? below : distances;
}

// The hard core of an axis (its first threshold, a hair below its closest pair) comes down to the
// pair's closest distance over all axes where the axis's own minimum is what chance gives: the
// minimum of m distances lies well above the true lower end when m is small (two-kinds: 18.9 px
// on one axis, 6.2 on the others, for one hard core of about 5), and a hard core set there bars
// close pairs the exemplar merely did not show along that axis. Under "the axis's distances are
// m draws from the pair's pooled ones", all m lie at or above the axis's minimum with probability
// (1 − F(min))^m, F the pooled share below it; below kHardCoreLevel the axis keeps its own hard
// core (rows, whose gap across is wider than along: tens of pairs that all keep clear).
void pool_hard_core(std::vector<double>& thresholds, const std::vector<double>& axis_distances,
                    const std::vector<double>& pooled, double w) {
  if (thresholds.empty() || axis_distances.empty() || pooled.empty()) return;
  const double own = *std::min_element(axis_distances.begin(), axis_distances.end());
  const double lowest = *std::min_element(pooled.begin(), pooled.end());
  // Only a plain hard core (a hair below the closest pair), not a shell's band.
  if (!(lowest < own) || thresholds.front() < own - 2 * kDegenerate * w) return;
  const auto below = std::count_if(pooled.begin(), pooled.end(), [&](double d) { return d < own; });
  const double share = static_cast<double>(below) / static_cast<double>(pooled.size());
  const double chance = std::pow(1.0 - share, static_cast<double>(axis_distances.size()));
  if (chance < kHardCoreLevel) return;
  thresholds.front() = hard_core_below(lowest, w);
}

// Overlap and nesting are relations of a pair of categories, not of a direction: where the
// exemplar overlaps a pair at all, every axis's hard core comes down to a hair below its deepest
// overlap (an axis that merely showed no overlap along it would otherwise forbid any), and its
// bands split at contact.
void share_overlap(std::vector<std::vector<double>>& per_axis, const std::vector<double>& pooled,
                   double w) {
  if (pooled.empty()) return;
  const double lowest = *std::min_element(pooled.begin(), pooled.end());
  if (!(lowest < 0)) return;
  const double hard_core = hard_core_below(lowest, w);
  for (std::vector<double>& t : per_axis) {
    if (t.empty() || t.front() <= hard_core) continue;
    t.front() = hard_core;
    split_at_contact(t, w);
  }
}

// Nesting and overlap are distinct relations: one shape inside another overlaps it by at least
// its own width (a disc of radius r inside a larger one: by 2r at least), one that only crosses
// the other's outline by less. Where an axis's bands reach below minus `width` (the narrower
// category's median width), a threshold there splits the nested pairs from those that straddle.
void split_at_nesting(std::vector<double>& thresholds, double width, double w) {
  // (Only where the nested range is a tenth of the width deep at least: no sliver of a band.)
  if (!(width > 0) || thresholds.empty() || !(thresholds.front() < -kNestedDepth * width)) return;
  const auto above = std::upper_bound(thresholds.begin(), thresholds.end(), -width);
  if (above == thresholds.end()) return;
  const double hair = kDegenerate * w;
  if (std::abs(*(above - 1) + width) > hair && std::abs(*above + width) > hair)
    thresholds.insert(above, -width);
}

// The median over a category's elements of its shape's narrower side (0 for points).
std::vector<double> category_widths(const geometry::Scene& exemplar) {
  return category_medians(exemplar, [&](const Element& e) {
    return geometry::bounding_box(exemplar.shapes[static_cast<std::size_t>(e.shape)])
        .sizes()
        .head(exemplar.dimension)
        .minCoeff();
  });
}

}  // namespace

void check_fit_options(const FitOptions& o) {
  if (o.thresholds.empty()) {
    core::check(!o.quantiles.empty(), "fit", "give at least one quantile order (q0)");
    for (std::size_t k = 0; k < o.quantiles.size(); ++k) {
      const double q = o.quantiles[k];
      core::check_in_range("fit", "quantile orders", q, 0.0, 1.0);
      if (k > 0 && !(q > o.quantiles[k - 1])) {
        std::ostringstream text;
        text << "quantile orders must increase, got " << q << " after " << o.quantiles[k - 1];
        throw core::ArgumentError("fit", text.str());
      }
    }
  } else {
    for (std::size_t k = 0; k < o.thresholds.size(); ++k) {
      const double d = o.thresholds[k];
      core::check(std::isfinite(d), "fit", "thresholds must be finite numbers");
      if (k > 0 && d < o.thresholds[k - 1]) {
        std::ostringstream text;
        text << "thresholds must not decrease, got " << d << " after " << o.thresholds[k - 1];
        throw core::ArgumentError("fit", text.str());
      }
    }
  }
  core::check(!(o.lines && o.refinement > 0), "fit",
              "refinement applies to cells, not to quadrature lines");
  core::check_in_range("fit", "the data points' weight", o.data_weight, 0.0, 1.0, true);
  core::check(o.edge != geometry::EdgeTreatment::automatic, "fit",
              "the edge treatment is none or border");
  core::check(
      !(o.boundary == geometry::Boundary::torus && o.edge == geometry::EdgeTreatment::border),
      "fit", "a periodic window needs no border correction");
  core::check(o.quadrature >= 0 && o.shapes_per_location >= 0 && o.min_pairs_per_axis >= 1, "fit",
              "quadrature, shapes per location and minimum pairs must be positive");
}

model::ShapeProcessModel model_skeleton(const geometry::Scene& exemplar,
                                        const FitOptions& options) {
  core::check(!exemplar.elements.empty(), "fit", "the exemplar has no element");
  const int dimension = exemplar.dimension;
  core::check(!options.lines || dimension == 2, "fit", "quadrature lines are for 2D exemplars");
  model::ShapeProcessModel model;
  model.dimension = dimension;
  model.units = exemplar.units;
  model.measurement = options.measurement;
  model.measurement.directions =
      geometry::directions_or_default(options.measurement.directions, dimension);
  const std::vector<std::size_t> per_category = geometry::category_counts(exemplar);
  for (std::size_t c = 0; c < exemplar.categories.size(); ++c) {
    core::check(per_category[c] > 0, "fit",
                "category '" + exemplar.categories[c].name + "' has no element");
    model.categories.push_back({exemplar.categories[c].name, 1.0});
  }
  // A shape may serve several categories (the single point shape of a point pattern): it takes
  // the category of its first element.
  std::vector<int> shape_category(exemplar.shapes.size(), -1);
  for (const Element& e : exemplar.elements) {
    if (shape_category[static_cast<std::size_t>(e.shape)] < 0)
      shape_category[static_cast<std::size_t>(e.shape)] = e.category;
  }
  bool points_only = true;
  for (const auto& shape : exemplar.shapes)
    points_only = points_only && geometry::dimension(shape) == 0;
  if (!points_only) {
    for (std::size_t s = 0; s < exemplar.shapes.size(); ++s) {
      model.shapes.push_back({exemplar.shapes[s], std::max(0, shape_category[s])});
    }
  }
  return model;
}

std::vector<std::vector<int>> shapes_by_category(const geometry::Scene& exemplar) {
  std::vector<std::vector<int>> shapes_of(exemplar.categories.size());
  for (const Element& e : exemplar.elements) {
    std::vector<int>& own = shapes_of[static_cast<std::size_t>(e.category)];
    if (std::find(own.begin(), own.end(), e.shape) == own.end()) own.push_back(e.shape);
  }
  return shapes_of;
}

void add_thresholds(model::ShapeProcessModel& model, const geometry::Scene& exemplar,
                    const std::vector<geometry::PairRecord>& pairs,
                    const geometry::DirectionBins& bins, const FitOptions& options,
                    std::vector<std::string>& notes) {
  const int categories = static_cast<int>(model.categories.size());
  const int axes = bins.axis_count();
  std::vector<double> all_distances;
  std::map<std::pair<int, int>, std::vector<std::vector<double>>> by_pair;  // (a, b) -> per axis
  for (const geometry::PairRecord& p : pairs) {
    int a = exemplar.elements[static_cast<std::size_t>(p.i)].category;
    int b = exemplar.elements[static_cast<std::size_t>(p.j)].category;
    if (a > b) std::swap(a, b);
    auto& per_axis = by_pair[{a, b}];
    per_axis.resize(static_cast<std::size_t>(axes));
    per_axis[static_cast<std::size_t>(p.measurement.axis)].push_back(p.measurement.distance);
    all_distances.push_back(p.measurement.distance);
  }
  const bool fixed_thresholds = !options.thresholds.empty();
  const double shell_jitter =
      kShellJitter *
      std::pow(exemplar.window_measure() / static_cast<double>(exemplar.elements.size()),
               1.0 / exemplar.dimension);
  if (!fixed_thresholds && all_distances.size() < 2) {
    notes.push_back("the exemplar has " + std::to_string(all_distances.size()) +
                    " pair(s) of elements: too few for thresholds, so the model is a Poisson "
                    "process (no interaction)");
    return;
  }
  const std::vector<std::size_t> counts = geometry::category_counts(exemplar);
  const std::vector<double> widths = category_widths(exemplar);
  for (int a = 0; a < categories; ++a) {
    for (int b = a; b < categories; ++b) {
      model::PairInteraction pair;
      pair.first = a;
      pair.second = b;
      const auto found = by_pair.find({a, b});
      std::vector<double> pooled;
      if (found != by_pair.end())
        for (const auto& d : found->second) pooled.insert(pooled.end(), d.begin(), d.end());
      const std::string names = "'" + model.categories[static_cast<std::size_t>(a)].name + "'-'" +
                                model.categories[static_cast<std::size_t>(b)].name + "'";
      bool noted_pool = false;
      std::vector<std::vector<double>> per_axis;
      const double cap =
          range_cap(options.budget, exemplar.window_measure(), exemplar.dimension,
                    static_cast<double>(std::max(counts[static_cast<std::size_t>(a)],
                                                 counts[static_cast<std::size_t>(b)])));
      for (int i = 0; i < axes; ++i) {
        if (fixed_thresholds) {
          per_axis.push_back(options.thresholds);
        } else {
          const std::vector<double>* source = nullptr;
          if (found != by_pair.end() &&
              static_cast<int>(found->second[static_cast<std::size_t>(i)].size()) >=
                  std::max(options.min_pairs_per_axis, 2)) {
            source = &found->second[static_cast<std::size_t>(i)];
          } else if (pooled.size() >= 2) {
            source = &pooled;
            if (!noted_pool) {
              notes.push_back("pair " + names + ": axes with fewer than " +
                              std::to_string(options.min_pairs_per_axis) +
                              " pairs take thresholds from the pair's " +
                              std::to_string(pooled.size()) + " pairs pooled over all axes");
              noted_pool = true;
            }
          } else {
            source = &all_distances;
            if (!noted_pool) {
              notes.push_back("pair " + names + ": fewer than 2 pairs, thresholds from all " +
                              std::to_string(all_distances.size()) + " pairs of the exemplar");
              noted_pool = true;
            }
          }
          per_axis.push_back(thresholds_from(within_range(*source, options.quantiles, cap),
                                             options.quantiles, shell_jitter,
                                             exemplar.elements.size()));
          if (source != &pooled && source != &all_distances)
            pool_hard_core(per_axis.back(), *source, pooled, shell_jitter);
        }
      }
      if (!fixed_thresholds) share_overlap(per_axis, pooled, shell_jitter);
      const double nest_width =
          std::min(widths[static_cast<std::size_t>(a)], widths[static_cast<std::size_t>(b)]);
      if (!fixed_thresholds)
        for (std::vector<double>& t : per_axis) split_at_nesting(t, nest_width, shell_jitter);
      if (!fixed_thresholds) {
        std::vector<double> isotropic = thresholds_from(
            within_range(pooled.size() >= 2 ? pooled : all_distances, options.quantiles, cap),
            options.quantiles, shell_jitter, exemplar.elements.size());
        split_at_nesting(isotropic, nest_width, shell_jitter);
        cap_range(isotropic, cap);
        for (std::vector<double>& t : per_axis) cap_range(t, cap);
        double range = isotropic.back();
        for (const std::vector<double>& t : per_axis) range = std::max(range, t.back());
        const auto within =
            std::count_if(pooled.begin(), pooled.end(), [&](double d) { return d < range; });
        const int parameters =
            static_cast<int>(within) / std::max(1, options.budget.pairs_per_parameter);
        PairThresholds chosen =
            apply_budget(std::move(per_axis), std::move(isotropic), parameters,
                         std::to_string(within) + " exemplar pairs within its range");
        per_axis = std::move(chosen.axes);
        pair.choice = std::move(chosen.choice);
        if (!pair.choice.empty()) notes.push_back("pair " + names + ": " + pair.choice);
      }
      for (std::size_t i = 0; i < per_axis.size(); ++i) {
        model::AxisParameters axis;
        axis.direction = bins.axis_direction(static_cast<int>(i));
        axis.thresholds = std::move(per_axis[i]);
        const std::size_t bands = axis.thresholds.size() - 1;
        axis.gammas.assign(bands, 1.0);
        axis.gamma_standard_errors.assign(bands, std::numeric_limits<double>::quiet_NaN());
        axis.status.assign(bands, model::ParameterStatus::free);
        axis.observed_pairs.assign(bands, 0);
        pair.axes.push_back(std::move(axis));
      }
      model.interactions.push_back(std::move(pair));
    }
  }
}

}  // namespace shapeproc::fit
