#include "libshapeproc/fit/line_quadrature.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "libshapeproc/core/constants.hpp"

namespace shapeproc::fit {

using geometry::Element;
using geometry::Vec3;
using model::Interaction;

namespace {

// What a neighbour does at one place on the line: its band under the axis of that place (the
// axis kept only while it matters), and how far along the line that cannot change.
struct State {
  int band = Interaction::kBeyond;
  int axis = -1;       // -1 beyond the pair's range
  bool exact = false;  // `distance` is exact (else a lower bound beyond the range)
  double distance = 0.0;
  double gap = 0.0;         // the distance cannot cross a threshold of `axis` within this length
  double axis_reach = 0.0;  // the axis cannot change within this length
  // Within the range a change of axis may bring a band of the new axis even when the old one's
  // is beyond: the axis is part of the key there.
  bool same_key(const State& o) const { return band == o.band && axis == o.axis; }
};

struct Transition {
  double x;
  int neighbour;
  int band, axis;
};

class NeighbourMarch {
 public:
  NeighbourMarch(const LineContext& context, int category, int shape, const Element& neighbour,
                 const Vec3& image, const Vec3& start)
      : c_(context),
        category_(category),
        shape_(shape),
        other_(neighbour),
        image_(image),
        start_(start) {
    reach_ = c_.interaction->max_range(category, neighbour.category);
    const int d = c_.measurer->bins().directions();
    sector_angle_ =
        c_.dimension == 2 ? (d > 1 ? 2 * core::kPi / d : 0.0) : (d > 1 ? core::kPi / 3 : 0.0);
  }

  double distance_at(double x) const {
    return c_.measurer->distance(shape_, other_.shape, image_ - (start_ + x * Vec3::UnitX()),
                                 2 * reach_);
  }

  State at(double x) const {
    State s;
    const Vec3 offset = image_ - (start_ + x * Vec3::UnitX());
    const geometry::PairMeasurer& m = *c_.measurer;
    const double lo = m.distance_bounds(shape_, other_.shape, offset).first;
    if (lo >= 1.05 * reach_) {
      s.distance = lo;
      s.gap = lo - reach_;
      s.axis_reach = s.gap;
      return s;
    }
    s.exact = true;
    s.distance = m.distance(shape_, other_.shape, offset, 2 * reach_);
    if (s.distance >= reach_) {
      s.gap = s.distance - reach_;
      s.axis_reach = s.gap;
      return s;
    }
    if (sector_angle_ <= 0.0) {
      s.axis = 0;
      s.axis_reach = std::numeric_limits<double>::infinity();
    } else {
      // The relative direction turns at about 1/|offset| radians per unit length along the
      // line (exactly so for centroid directions): half the angle to the nearest sector boundary,
      // times |offset|, is taken as safe, and never more than a quarter of a sector.
      const double length = offset.norm();
      const double quarter = 0.25 * sector_angle_ * length;
      s.axis = m.axis_from_boxes(shape_, other_.shape, offset, quarter);
      if (s.axis >= 0) {
        s.axis_reach = quarter;
      } else {
        const Vec3 direction = m.direction(shape_, other_.shape, offset);
        s.axis = m.bins().axis_of(direction);
        if (c_.dimension == 2) {
          const double angle = std::atan2(direction.y(), direction.x());
          const double margin =
              0.5 * sector_angle_ - std::abs(std::remainder(angle, sector_angle_));
          s.axis_reach = std::min(quarter, 0.5 * margin * length);
        } else {
          s.axis_reach = 0.5 * quarter;
        }
      }
    }
    s.band = c_.interaction->band(category_, other_.category, s.axis, s.distance);
    const std::vector<double>& t = c_.interaction->thresholds(category_, other_.category, s.axis);
    const auto above = std::upper_bound(t.begin(), t.end(), s.distance);
    s.gap = std::numeric_limits<double>::infinity();
    if (above != t.end()) s.gap = *above - s.distance;
    if (above != t.begin()) s.gap = std::min(s.gap, s.distance - *(above - 1));
    return s;
  }

  // Where d(x) = level in [a, b], given d − level changes sign there: Illinois false position
  // with a bisection every third step, to `tolerance`.
  double crossing(double a, double b, double level) const {
    double fa = distance_at(a) - level, fb = distance_at(b) - level;
    int side = 0;
    for (int it = 0; it < 100 && b - a > c_.tolerance; ++it) {
      double x = it % 3 == 2 ? 0.5 * (a + b) : (a * fb - b * fa) / (fb - fa);
      if (!(x > a && x < b)) x = 0.5 * (a + b);
      const double fx = distance_at(x) - level;
      if (std::abs(fx) < 1e-3 * c_.tolerance) return x;
      if ((fx < 0) == (fa < 0)) {
        a = x;
        fa = fx;
        if (side == -1) fb *= 0.5;
        side = -1;
      } else {
        b = x;
        fb = fx;
        if (side == 1) fa *= 0.5;
        side = 1;
      }
    }
    return 0.5 * (a + b);
  }

  int other_category() const { return other_.category; }

  // Appends the transitions of this neighbour on [x0, x1] (its first state at x0).
  void march(double x0, double x1, int index, std::vector<Transition>& out) const {
    const double tolerance = c_.tolerance;
    const double min_step = std::max(tolerance, 1e-3 * reach_);
    double x = x0;
    State s = at(x);
    out.push_back({x, index, s.band, s.axis});
    while (x < x1) {
      const double step = std::max(min_step, std::min(s.gap, s.axis_reach));
      double next = std::min(x1, x + step);
      State t = at(next);
      if (!t.same_key(s)) {
        double where;
        if (s.exact && t.exact && s.axis == t.axis && s.axis >= 0) {
          // A threshold of one axis: the distance crosses it once (the step was chosen so).
          const std::vector<double>& th =
              c_.interaction->thresholds(category_, other_.category, s.axis);
          const double level = s.distance < t.distance
                                   ? *std::upper_bound(th.begin(), th.end(), s.distance)
                                   : *(std::upper_bound(th.begin(), th.end(), s.distance) - 1);
          where = crossing(x, next, level);
          next = std::min(x1, where + 0.5 * tolerance);
          t = at(next);
        } else {
          // Bisection on the state (an axis change, or the range entered from afar).
          double a = x, b = next;
          while (b - a > tolerance) {
            const double mid = 0.5 * (a + b);
            State m = at(mid);
            if (m.same_key(s)) {
              a = mid;
            } else {
              b = mid;
              t = m;
            }
          }
          where = 0.5 * (a + b);
          next = b;
        }
        out.push_back({where, index, t.band, t.axis});
      }
      x = next;
      s = t;
    }
  }

 private:
  const LineContext& c_;
  int category_, shape_;
  const Element& other_;
  Vec3 image_, start_;
  double reach_ = 0.0;
  double sector_angle_ = 0.0;
};

}  // namespace

std::vector<LinePiece> integrate_line(const LineContext& context, int category, int shape,
                                      const Vec3& start, double length) {
  const Interaction& interaction = *context.interaction;
  const geometry::PairMeasurer& measurer = *context.measurer;
  const double own_radius = measurer.radius(shape);
  std::vector<Transition> transitions;
  std::vector<const Element*> neighbours;
  std::vector<NeighbourMarch> marches;
  marches.reserve(context.data->size() * 9);
  // Every neighbour (each periodic image that is a minimum image somewhere on the line) whose
  // centre comes within the pair's reach plus both radii of the line.
  const int images = context.period.head(context.dimension).maxCoeff() > 0 ? 1 : 0;
  for (const Element& other : *context.data) {
    if (!interaction.sees(category, other.category)) continue;
    const double reach =
        interaction.max_range(category, other.category) + own_radius + measurer.radius(other.shape);
    for (int iz = -images; iz <= images; ++iz)
      for (int iy = -images; iy <= images; ++iy)
        for (int ix = -images; ix <= images; ++ix) {
          if (context.dimension == 2 && iz != 0) continue;
          const Vec3 shift(ix * context.period.x(), iy * context.period.y(),
                           iz * context.period.z());
          const Vec3 image = other.position + shift;
          // Across the line: the image must be the minimum image there.
          double across = 0.0;
          bool minimum = true;
          for (int axis = 1; axis < context.dimension; ++axis) {
            const double delta = image[axis] - start[axis];
            if (context.period[axis] > 0 && std::abs(delta) > 0.5 * context.period[axis])
              minimum = false;
            across += delta * delta;
          }
          if (!minimum || across >= reach * reach) continue;
          const double half = std::sqrt(reach * reach - across);
          double x0 = std::max(0.0, image.x() - start.x() - half);
          double x1 = std::min(length, image.x() - start.x() + half);
          if (context.period.x() > 0) {
            x0 = std::max(x0, image.x() - start.x() - 0.5 * context.period.x());
            x1 = std::min(x1, image.x() - start.x() + 0.5 * context.period.x());
          }
          if (!(x1 > x0)) continue;
          const int index = static_cast<int>(marches.size());
          marches.emplace_back(context, category, shape, other, image, start);
          marches.back().march(x0, x1, index, transitions);
          transitions.push_back({x1, index, Interaction::kBeyond, -1});
        }
  }
  // Sweep: the statistics are constant between consecutive transitions.
  std::stable_sort(transitions.begin(), transitions.end(),
                   [](const Transition& a, const Transition& b) { return a.x < b.x; });
  struct Current {
    int band = Interaction::kBeyond, axis = -1;
  };
  std::vector<Current> current(marches.size());
  std::map<std::vector<std::pair<int, int>>, double> measure;
  double x = 0.0;
  std::size_t t = 0;
  auto close_interval = [&](double end) {
    if (!(end > x)) return;
    model::InteractionCounts counts;
    for (std::size_t k = 0; k < current.size(); ++k) {
      if (current[k].band == Interaction::kHardCore) return;
      if (current[k].band >= 0) {
        counts.add(interaction.parameter(category, marches[k].other_category(), current[k].axis,
                                         current[k].band));
      }
    }
    measure[counts.counts] += end - x;
  };
  while (t < transitions.size()) {
    const double at = std::clamp(transitions[t].x, 0.0, length);
    close_interval(at);
    x = std::max(x, at);
    for (; t < transitions.size() && std::clamp(transitions[t].x, 0.0, length) <= x; ++t) {
      current[static_cast<std::size_t>(transitions[t].neighbour)] = {transitions[t].band,
                                                                     transitions[t].axis};
    }
  }
  close_interval(length);
  std::vector<LinePiece> pieces;
  pieces.reserve(measure.size());
  for (auto& [counts, l] : measure) pieces.push_back({l, counts});
  return pieces;
}

}  // namespace shapeproc::fit
