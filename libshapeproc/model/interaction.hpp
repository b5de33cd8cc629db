// The interaction function compiled for evaluation, and the conditional intensity
//   log λ(ξ | x) = log β_c + Σ_m log Γ(ξ, x_m) = θ · t(ξ, x)
// with θ = (log β_c, log γ_{pair, axis, band}) and t the counts of x's elements that ξ interacts
// with per (pair, axis, band). One implementation for fitting, sampling and metrics.
#pragma once

#include <limits>
#include <utility>
#include <vector>

#include "libshapeproc/geometry/pair_measurements.hpp"
#include "libshapeproc/model/shape_process_model.hpp"

namespace shapeproc::model {

class Interaction {
 public:
  static constexpr int kHardCore = -1;  // d < δ_0
  static constexpr int kBeyond = -2;    // d ≥ δ_K, or categories that do not interact

  explicit Interaction(const ShapeProcessModel& model);

  int category_count() const { return categories_; }
  int parameter_count() const { return parameters_; }
  // The sufficient statistics t(x): one per θ parameter (elements per category, pairs per band),
  // then the element count of each shape class (none when the model has no classes).
  int shape_class_count() const { return static_cast<int>(class_of_shape_.empty() ? 0 : classes_); }
  int statistic_count() const { return parameters_ + shape_class_count(); }
  // Index in t(x) of the class count a shape adds to, or -1 when the model has no classes.
  int class_statistic(int shape) const {
    return class_of_shape_.empty() ? -1
                                   : parameters_ + class_of_shape_[static_cast<std::size_t>(shape)];
  }
  // Largest δ_K of any pair (0 when nothing interacts).
  double range() const { return range_; }
  bool interacts(int ca, int cb) const { return pair_of(ca, cb) >= 0; }
  // Whether the conditional intensity of an element of `category` counts a neighbour of
  // `neighbour`: the two interact and the neighbour's layer is not later than the category's.
  // A later layer is placed given the earlier ones, which never see it (docs/fit.md, "Layers"):
  // a pair of layers' γ acts on the later one's intensity only.
  bool sees(int category, int neighbour) const {
    return interacts(category, neighbour) && layer_[static_cast<std::size_t>(neighbour)] <=
                                                 layer_[static_cast<std::size_t>(category)];
  }
  int layer(int category) const { return layer_[static_cast<std::size_t>(category)]; }
  // The category an element of `category` must lie closer than anchor_reach to an element of
  // (-1: none).
  int anchor(int category) const { return anchor_[static_cast<std::size_t>(category)]; }
  double anchor_reach(int category) const {
    return anchor_reach_[static_cast<std::size_t>(category)];
  }
  // Whether an element of `category` with these interaction counts t(ξ, x) may be there: its
  // category has no anchor, or some count is of a band of the anchor pair below the reach.
  bool anchored(int category, const std::vector<std::pair<int, int>>& counts) const;
  // Whether θ index `parameter` is a band of an anchor pair that ends at or below the reach.
  bool anchor_band(int parameter) const {
    return anchor_band_[static_cast<std::size_t>(parameter)] != 0;
  }
  // The saturation s of a θ index's band (model::AxisParameters::saturations); 0: pairwise.
  int saturation(int parameter) const { return saturation_[static_cast<std::size_t>(parameter)]; }
  // Whether some band is saturated (a Geyer term: the conditional intensity also depends on the
  // neighbours' own counts, docs/mathematics.md "Saturation").
  bool saturated() const { return saturated_; }
  // Below this distance the pair is a hard-core violation whatever the axis; at or beyond
  // max_range it does not interact. Between, the axis decides.
  double min_hard_core(int ca, int cb) const { return pairs_[pair_of(ca, cb)].min_hard_core; }
  double max_range(int ca, int cb) const { return pairs_[pair_of(ca, cb)].max_range; }
  // At or beyond this distance no axis makes the pair a hard-core violation.
  double max_hard_core(int ca, int cb) const { return pairs_[pair_of(ca, cb)].max_hard_core; }
  // Every threshold of every axis of a pair, ascending and distinct: a distance's band in every
  // axis depends only on which interval between them holds it.
  const std::vector<double>& breakpoints(int ca, int cb) const {
    return pairs_[pair_of(ca, cb)].breakpoints;
  }

  // δ_0 … δ_K of a pair's axis (the pair must interact).
  const std::vector<double>& thresholds(int ca, int cb, int axis) const {
    return axis_of(pair_of(ca, cb), axis).thresholds;
  }
  // Whether the pair's interaction is the same along every axis: its axis need not be measured.
  bool isotropic(int ca, int cb) const { return pairs_[pair_of(ca, cb)].axes.size() == 1; }
  // Band of a pair at `distance` along `axis`: kHardCore, kBeyond or k in 0..K-1 (γ_{k+1}).
  int band(int ca, int cb, int axis, double distance) const;
  // θ index of a band (betas come first: θ[c] = log β_c).
  int parameter(int ca, int cb, int axis, int band) const;
  double log_gamma(int ca, int cb, int axis, int band) const;
  // log γ of an interaction parameter (θ index ≥ category_count()).
  double log_gamma_of(int parameter) const { return theta_[static_cast<std::size_t>(parameter)]; }

  // Location of a θ index: (pair, axis, band), or (-1, category, -1) for a β.
  struct Location {
    int pair, axis, band;
  };
  Location locate(int parameter) const {
    return locations_.at(static_cast<std::size_t>(parameter));
  }

 private:
  struct Axis {
    std::vector<double> thresholds;
    std::vector<double> log_gammas;
    int first_parameter = 0;
  };
  struct Pair {
    std::vector<Axis> axes;
    double min_hard_core = 0.0, max_hard_core = 0.0, max_range = 0.0;
    std::vector<double> breakpoints;
  };
  // An isotropic pair has one axis, which serves every axis bin.
  const Axis& axis_of(int pair, int axis) const {
    const std::vector<Axis>& axes = pairs_[static_cast<std::size_t>(pair)].axes;
    return axes[axes.size() == 1 ? 0 : static_cast<std::size_t>(axis)];
  }
  // The reach of the pair (a, b) when one anchors the other; −∞ otherwise.
  double anchor_reach_of(int a, int b) const;
  int pair_of(int ca, int cb) const {
    return pair_index_[static_cast<std::size_t>(ca) * static_cast<std::size_t>(categories_) +
                       static_cast<std::size_t>(cb)];
  }

  int categories_ = 0;
  int parameters_ = 0;
  int classes_ = 0;
  std::vector<int> class_of_shape_;  // by model shape; empty without shape classes
  double range_ = 0.0;
  std::vector<int> pair_index_;       // categories x categories -> index into pairs_ or -1
  std::vector<int> layer_;            // per category
  std::vector<int> anchor_;           // per category
  std::vector<double> anchor_reach_;  // per category
  std::vector<char> anchor_band_;     // per θ index
  std::vector<int> saturation_;       // per θ index
  bool saturated_ = false;
  std::vector<Pair> pairs_;
  std::vector<Location> locations_;
  std::vector<double> theta_;  // θ: log β (betas, from the model) then log γ, by θ index
};

// What one neighbour does to ξ. `distance` is a value of the interval between the pair's
// breakpoints that holds the shape distance (the distance itself for other kinds): enough for
// every band.
struct PairEffect {
  int band = Interaction::kBeyond;
  int axis = 0;
  double distance = std::numeric_limits<double>::infinity();
  geometry::Vec3 offset = geometry::Vec3::Zero();  // the neighbour's image relative to ξ
  bool axis_pending = false;  // in range: the axis (and band) are still to decide
};

// Measures ξ against one neighbour, lazily: the direction is computed only when the distance
// leaves the axis to decide. The same in two stages, for callers that want every distance before
// any direction (the sampler rejects on a hard core first): pair_distance_effect decides beyond
// range and hard core below the pair's smallest δ_0 and otherwise leaves `axis_pending`, which
// decide_axis then settles.
PairEffect pair_effect(const Interaction& interaction, const geometry::PairMeasurer& measurer,
                       const geometry::Element& xi, const geometry::Element& neighbour);
PairEffect pair_distance_effect(const Interaction& interaction,
                                const geometry::PairMeasurer& measurer, const geometry::Element& xi,
                                const geometry::Element& neighbour);
void decide_axis(const Interaction& interaction, const geometry::PairMeasurer& measurer,
                 const geometry::Element& xi, const geometry::Element& neighbour,
                 PairEffect& effect);

// t(ξ, x) restricted to interactions: sorted (θ index, count) pairs and the hard-core flag.
struct InteractionCounts {
  bool hard_core = false;
  std::vector<std::pair<int, int>> counts;

  void add(int parameter, int count = 1);
  int count_of(int parameter) const;
  // θ · t for the interaction part (−∞ on a hard core).
  double dot(const std::vector<double>& theta) const;
};

}  // namespace shapeproc::model
