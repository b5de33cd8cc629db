// Pair measurements between elements (paper §4; docs/mathematics.md, "Pair measurements"): the
// shortest distance d(a, b) between proxy geometries and the relative orientation o(a, b), with
// their comparison variants and periodic (minimum-image) forms. Built once for a scene's shape
// space, queried many times by fitting, sampling and metrics.
#pragma once

#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <utility>
#include <vector>

#include "libshapeproc/geometry/directions.hpp"
#include "libshapeproc/geometry/force_table.hpp"
#include "libshapeproc/geometry/proxy.hpp"
#include "libshapeproc/geometry/scene.hpp"

namespace shapeproc::geometry {

enum class DistanceKind {
  shape,      // shortest distance between proxies; 0 when they touch, cross or one holds the other
  centroid,   // distance between reference positions (the centroidal baseline)
  hausdorff,  // symmetric Hausdorff distance between the proxies' outlines (sampled)
};
enum class DirectionKind {
  gravitation,  // direction of the gravitation force between the shapes' masses
  centroid,     // direction between reference positions
};

struct MeasurementOptions {
  DistanceKind distance = DistanceKind::shape;
  DirectionKind direction = DirectionKind::gravitation;
  int directions = 8;     // canonical directions: 2D any even number or 1; 3D 12 or 1
  bool periodic = false;  // the window is a torus: minimum-image offsets
  ProxyOptions proxy;
  double gravitation_theta = 0.2;  // Barnes–Hut opening parameter (3D point cubature)
};

struct Measurement {
  double distance = 0.0;
  Vec3 direction = Vec3::UnitX();  // unit vector from the first element towards the second
  int axis = 0;
  Vec3 offset = Vec3::Zero();  // position of the second relative to the first (the image used)
};

struct PairRecord {
  int i = 0, j = 0;  // element indices, i < j
  Measurement measurement;
};

struct ProxyStatistics {
  double source_per_element = 0.0;  // mean segments (2D) or triangles (3D) per element, as drawn
  double proxy_per_element = 0.0;   // the same for the proxies
  double mass_per_element = 0.0;    // mass boundary edges (2D) or cubature points (3D)
};

class PairMeasurer {
 public:
  static constexpr double kNoCutoff = std::numeric_limits<double>::infinity();

  // Builds the proxies of every shape of `scene` (its shapes and window are used; elements only
  // for the statistics). Throws std::invalid_argument on bad options.
  PairMeasurer(const Scene& scene, const MeasurementOptions& options);

  // d between shape `a` at the origin and shape `b` at `offset` (no periodic images), or `cutoff`
  // when d >= cutoff.
  //
  // With `breakpoints` (ascending distances, the cut-off among them), callers say that only the
  // interval [b_k, b_k+1) holding d matters (a model's thresholds): the result is then a value of
  // that interval, not necessarily d itself, and the closest-pair search stops as soon as the
  // interval is decided. Shape distances (2D and 3D) use them; other kinds return d.
  double distance(int a, int b, const Vec3& offset, double cutoff = kNoCutoff,
                  const std::vector<double>* breakpoints = nullptr) const;
  // Unit direction of the relative orientation, exactly antisymmetric:
  // direction(b, a, -offset) == -direction(a, b, offset).
  Vec3 direction(int a, int b, const Vec3& offset) const;
  // bins().axis_of(direction(a, b, offset)), read for detailed pairs queried many times from a
  // table of their forces on a grid of offsets where it vouches for the axis (force_table.hpp).
  int axis(int a, int b, const Vec3& offset) const;

  // Measures two elements; periodic windows use the image of `second` nearest to `first` in the
  // distance being measured. With a cutoff, returns distance = cutoff (and no direction) when
  // d >= cutoff.
  Measurement measure(const Element& first, const Element& second, double cutoff = kNoCutoff) const;
  // The distance part of measure(): distance and the image offset, no direction (direction and
  // axis left at their defaults). Callers that need the direction only for some distances use
  // this, then direction(first.shape, second.shape, offset).
  // With `breakpoints`, as for distance(), the distance is a value of the interval holding d
  // (when several periodic images come within the cut-off, they are measured exactly).
  Measurement measure_distance(const Element& first, const Element& second,
                               double cutoff = kNoCutoff,
                               const std::vector<double>* breakpoints = nullptr) const;

  // Cheap bounds lo <= d(a, b, offset) <= hi for the shape distance (no periodic images): lo from
  // the proxies' boxes, hi between the two proxies' extreme vertices along the offset.
  std::pair<double, double> distance_bounds(int a, int b, const Vec3& offset) const;
  // The squared gap between the proxies' boxes (b's moved by `offset`), 0 where they meet: the
  // cheapest lower bound of the shape distance.
  double box_gap_squared(int a, int b, const Vec3& offset) const {
    if (dimension_ == 2) {
      return proxies2_[static_cast<std::size_t>(a)].box.squaredExteriorDistance(
          proxies2_[static_cast<std::size_t>(b)].box.translated(offset.head<2>()));
    }
    return proxies3_[static_cast<std::size_t>(a)].box.squaredExteriorDistance(
        proxies3_[static_cast<std::size_t>(b)].box.translated(offset));
  }

  // The axis bin of direction(a, b, offset) when the shapes' boxes alone decide it, else -1.
  // Both direction kinds lie in the cone of vectors y − x from a point x of a's proxy box to a
  // point y of b's (moved by `offset`); when that cone fits in one direction sector (2D), the
  // axis is known without computing the direction. With `slack`, the answer holds for every
  // offset within `slack` of the given one (the difference box is grown by it). 3D always
  // returns -1.
  int axis_from_boxes(int a, int b, const Vec3& offset, double slack = 0.0) const;
  // The axis bin of direction(a, b, o) for every o within `slack` of `offset`, when it is
  // certain, else -1 (2D): axis_from_boxes, or, for gravitation between regions whose circles
  // stay well apart, the pair's multipole bound on how far the direction strays from the line of
  // centroids (monopole_deviation), widened by the angle `slack` subtends there.
  int certain_axis(int a, int b, const Vec3& offset, double slack) const;

  // Whether shapes a and b have the same proxy (equal segments, or triangles, to 1e-9 of their
  // size, in the same order): then every measurement of one equals that of the other.
  bool same_proxy(int a, int b) const;

  // Every unordered pair with d < range (all pairs for an infinite range), ordered by (i, j).
  std::vector<PairRecord> all_pairs(const std::vector<Element>& elements,
                                    double range = kNoCutoff) const;

  const DirectionBins& bins() const { return bins_; }
  // The table axis() reads detailed pairs from (nullptr for centroid directions).
  const ForceTable* force_table() const { return forces_.get(); }
  const MeasurementOptions& options() const { return options_; }
  const ProxyStatistics& statistics() const { return statistics_; }
  int dimension() const { return dimension_; }
  const std::vector<Proxy2>& proxies2() const { return proxies2_; }
  const std::vector<Proxy3>& proxies3() const { return proxies3_; }
  // Radius of a shape's proxy around its reference position.
  double radius(int shape) const { return radii_.at(static_cast<std::size_t>(shape)); }

 private:
  double shape_distance(int a, int b, const Vec3& offset, double cutoff,
                        const std::vector<double>* breakpoints) const;
  // A value of the interval between `breakpoints` (or the cut-off) that holds the 2D shape
  // distance, when the shapes' circles (outline_out_, outline_in_) alone decide it; else NaN.
  double outline_bracket(int a, int b, const Vec2& offset, double cutoff,
                         const std::vector<double>& breakpoints) const;
  double hausdorff_distance(int a, int b, const Vec3& offset) const;
  Vec3 gravitation_direction(int a, int b, const Vec3& offset) const;
  // 2D: both shapes round and their outer circles apart, so that they pull along the line of
  // their centres (round_shape.hpp).
  bool round_apart(int a, int b, const Vec3& offset) const;
  // The exact gravitation force between shape a at the origin and b at `offset`, and the norm
  // below which it has no direction (a force that cancels, such as a dot's centred in a ring).
  Vec3 gravitation_force_between(int a, int b, const Vec3& offset) const;
  double negligible_force(int a, int b, const Vec3& offset) const;
  // The axis from the force table, when the pair has one and it vouches for the axis.
  std::optional<int> table_axis(int a, int b, const Vec3& offset) const;
  // The mutual-potential table of shapes a ≤ b (2D regions), built on first use; nullptr when
  // the shape space is too large to keep one per pair.
  const PairExpansion* expansion(int a, int b) const;

  struct ExpansionCache {
    std::vector<PairExpansion> tables;       // a * shapes + b, a ≤ b
    std::unique_ptr<std::once_flag[]> once;  // one per table
  };

  int dimension_;
  MeasurementOptions options_;
  DirectionBins bins_;
  Vec3 period_ = Vec3::Zero();
  std::vector<Proxy2> proxies2_;
  std::vector<Proxy3> proxies3_;
  std::vector<double> radii_;
  std::vector<double> round_;  // 2D: round_radius of each shape, −1 if not round (round_shape.hpp)
  // 2D, per shape: every point of the proxy's outline lies within outline_out_ of the reference
  // position, and a closed polyline of it encloses the reference position at outline_in_ or
  // farther (−1 when none does). Two shapes whose outer circles are apart then lie between
  // |offset| − out_a − out_b and |offset| − in_a − in_b of each other (outline_bracket).
  std::vector<double> outline_out_, outline_in_;
  ProxyStatistics statistics_;
  std::shared_ptr<ExpansionCache> expansions_;  // shared by copies; empty in 3D
  // Axes of the gravitation directions of detailed pairs (force_table.hpp), shared by copies:
  // pairs whose product of mass sizes (2D boundary edges, 3D triangles or cubature points)
  // reaches kForceTableCost, on a grid of pitch kForceTablePitch times the sum of their radii.
  static constexpr std::size_t kForceTableCost = 256;
  static constexpr double kForceTablePitch = 1.0 / 64;
  std::vector<std::size_t> mass_size_;
  std::vector<int> table_shape_;  // per shape, the first shape with the same proxy
  std::shared_ptr<ForceTable> forces_;
};

}  // namespace shapeproc::geometry
