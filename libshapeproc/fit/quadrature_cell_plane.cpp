// 2D quadrature cells cut along the boundaries' local models (quadrature_cell.hpp). The steps:
// the cell's frame (half-sides, corner lattice), the neighbours that may matter nearest first,
// each neighbour's model (exact distance where a threshold may cross the cell, sector cuts from
// the direction's pole model, distance cuts from its slope and curvature), the cell cut into
// convex pieces, and the pieces gathered into parts with equal statistics.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "libshapeproc/core/constants.hpp"
#include "libshapeproc/fit/detail/cell_cuts.hpp"
#include "libshapeproc/fit/detail/level_set_chords.hpp"
#include "libshapeproc/fit/detail/quadrature_cell_internal.hpp"
#include "libshapeproc/geometry/domain.hpp"

namespace shapeproc::fit {

using geometry::Vec3;
using model::Interaction;

namespace {

// A sector boundary is looked for when the angle to it times the distance between centres (its
// distance for directions between centres) is below this many half-diagonals of the cell: the
// gravitation direction of near shapes may turn faster.
constexpr double kSectorReach = 1.5;

// Corners of the cell, in units of half its side.
constexpr std::array<Point2, 4> kCorners{{{1, 1}, {-1, 1}, {1, -1}, {-1, -1}}};

// A data element near the dummy: the gap between their circles and its (minimum-image) offset.
struct Candidate {
  double gap;
  int k;
  Vec3 offset;
};

// One neighbour being modelled: its element, offset, distance bounds and exact distance.
struct NeighbourView {
  const geometry::Element* other;
  int k;
  Vec3 offset;
  double lo, hi;  // bounds on the distance at the centre
  double d;       // the distance at the centre (lo unless exact)
  bool exact;
  double cutoff;
};

class PlaneCell {
 public:
  PlaneCell(const CellContext& context, const geometry::Element& dummy, const Vec3& size,
            CornerCache* cache)
      : context_(context),
        interaction_(*context.interaction),
        measurer_(*context.measurer),
        dummy_(dummy),
        size_(size),
        cache_(cache),
        neighbours_(neighbours_storage()),
        cuts_(cuts_storage()),
        sides_(sides_storage()) {
    set_frame();
    neighbours_.clear();
    cuts_.clear();
    sides_.clear();
  }

  std::vector<CellPart> integrate(bool* uniform, bool* too_curved) {
    for (const Candidate& candidate : nearest_candidates()) {
      if (!model_neighbour(candidate)) break;
    }
    if (uniform) *uniform = true;
    if (too_curved) *too_curved = too_curved_;
    if (forbidden_) return {};
    const std::vector<Piece>& pieces = cut_into_pieces(uniform);
    return parts_of(pieces);
  }

 private:
  // Work space kept by the thread (integrate_cell_adaptive calls integrate again only after the
  // previous call returned).
  static std::vector<PlaneNeighbour>& neighbours_storage() {
    thread_local std::vector<PlaneNeighbour> v;
    return v;
  }
  static std::vector<PlaneCut>& cuts_storage() {
    thread_local std::vector<PlaneCut> v;
    return v;
  }
  static std::vector<HalfPlane>& sides_storage() {
    thread_local std::vector<HalfPlane> v;
    return v;
  }

  // Half-sides, half-diagonal, the corner samples' reach, and the corners' lattice coordinates
  // when they lie on the lattice (so that their samples can be shared).
  void set_frame() {
    hx_ = 0.5 * size_.x();
    hy_ = 0.5 * size_.y();
    corner_ = std::hypot(hx_, hy_);
    // Samples at the corners use one cut-off whatever the refinement, so that they can be shared.
    sample_reach_ = 3 * (context_.top_corner > 0 ? context_.top_corner : corner_);
    on_lattice_ =
        cache_ != nullptr && context_.lattice_step.x() > 0 && context_.lattice_step.y() > 0;
    for (std::size_t i = 0; i < 4 && on_lattice_; ++i) {
      const double fx = (dummy_.position.x() + kCorners[i].x * hx_ - context_.lattice_origin.x()) /
                        context_.lattice_step.x();
      const double fy = (dummy_.position.y() + kCorners[i].y * hy_ - context_.lattice_origin.y()) /
                        context_.lattice_step.y();
      lattice_x_[i] = std::lround(fx);
      lattice_y_[i] = std::lround(fy);
      on_lattice_ = std::abs(fx - static_cast<double>(lattice_x_[i])) < 1e-6 &&
                    std::abs(fy - static_cast<double>(lattice_y_[i])) < 1e-6;
    }
  }

  // Whether the line n·p = c meets the cell.
  bool meets(double nx, double ny, double c) const {
    return std::abs(c) < std::abs(nx) * hx_ + std::abs(ny) * hy_;
  }

  // The data elements whose interaction may reach the cell, nearest first: a hard core over the
  // whole cell then ends the work early.
  const std::vector<Candidate>& nearest_candidates() const {
    thread_local std::vector<Candidate> candidates;
    candidates.clear();
    context_.grid->for_each_candidate(dummy_.position, [&](int k) {
      const geometry::Element& other = (*context_.data)[static_cast<std::size_t>(k)];
      if (!interaction_.sees(dummy_.category, other.category)) return;
      const Vec3 offset =
          geometry::minimum_image(other.position - dummy_.position, context_.period);
      const double gap =
          offset.norm() - measurer_.radius(dummy_.shape) - measurer_.radius(other.shape);
      if (gap >= interaction_.max_range(dummy_.category, other.category) + corner_) return;
      candidates.push_back({gap, k, offset});
    });
    std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
      return a.gap < b.gap || (a.gap == b.gap && a.k < b.k);
    });
    return candidates;
  }

  // The neighbour's effect on the cell: none, a hard core over all of it (returns false), one
  // band over all of it (added to base_), or cuts through it (a PlaneNeighbour).
  bool model_neighbour(const Candidate& candidate) {
    NeighbourView v;
    v.other = &(*context_.data)[static_cast<std::size_t>(candidate.k)];
    v.k = candidate.k;
    v.offset = candidate.offset;
    const int ca = dummy_.category, cb = v.other->category;
    const double reach = interaction_.max_range(ca, cb);
    const auto bounds = measurer_.distance_bounds(dummy_.shape, v.other->shape, v.offset);
    // The circles about the reference positions may bound d better than the boxes (round shapes).
    v.lo = std::max(bounds.first, candidate.gap);
    v.hi = bounds.second;
    if (v.lo >= reach + corner_) return true;
    const double hard_core = interaction_.min_hard_core(ca, cb);
    if (v.hi + corner_ < hard_core) {
      forbidden_ = true;  // within every axis's hard core all over the cell
      return false;
    }
    // The exact distance when a threshold that matters may fall within the cell's range: of any
    // axis, or of the axis alone when it is certain over the cell.
    v.cutoff = reach + sample_reach_;
    const std::vector<double>& breakpoints = interaction_.breakpoints(ca, cb);
    const int certain = measurer_.certain_axis(dummy_.shape, v.other->shape, v.offset, corner_);
    const std::vector<double>& deciding =
        certain >= 0 ? interaction_.thresholds(ca, cb, certain) : breakpoints;
    v.d = v.lo;
    v.exact = any_within(deciding, v.lo - corner_, v.hi + corner_);
    if (v.exact) {
      v.d = measurer_.distance(dummy_.shape, v.other->shape, v.offset, v.cutoff);
      if (v.d + corner_ < hard_core) {
        forbidden_ = true;
        return false;
      }
      if (v.d - corner_ >= reach) return true;
    }
    PlaneNeighbour n{cb, certain, v.d, static_cast<int>(cuts_.size()), 0};
    std::uint64_t axes = 0;  // axes whose thresholds matter in the cell
    if (n.axis < 0 && (v.exact ? !any_within(breakpoints, v.d - corner_, v.d + corner_) : true)) {
      // Every axis keeps one band over the cell: when all are a hard core, or all beyond, the
      // axis does not matter.
      const int first = interaction_.band(ca, cb, 0, v.d);
      bool same = first < 0;
      for (int axis = 1; axis < measurer_.bins().axis_count() && same; ++axis)
        same = interaction_.band(ca, cb, axis, v.d) == first;
      if (same) n.axis = 0;
    }
    if (n.axis < 0) add_sector_cuts(v, n, axes);
    axes |= std::uint64_t{1} << n.axis;
    if (v.exact) add_distance_cuts(v, axes);
    n.cut_count = static_cast<int>(cuts_.size()) - n.first_cut;
    if (n.cut_count == 0) {
      const int band = interaction_.band(ca, cb, n.axis, n.distance);
      if (band >= 0) base_.add(interaction_.parameter(ca, cb, n.axis, band));
      if (band == Interaction::kHardCore) {
        forbidden_ = true;
        return false;
      }
      return true;
    }
    neighbours_.push_back(n);
    return true;
  }

  static bool any_within(const std::vector<double>& marks, double low, double high) {
    return std::any_of(marks.begin(), marks.end(), [&](double t) { return t > low && t <= high; });
  }

  // The key of a corner sample in the cache: the dummy moved by p sees the neighbour at
  // offset − p, in the image the offset is.
  CornerCache::Key corner_key(const NeighbourView& v, std::size_t i) const {
    const Vec3 image = v.offset - (v.other->position - dummy_.position);
    return CornerCache::Key{
        dummy_.shape,
        v.k,
        lattice_x_[i],
        lattice_y_[i],
        context_.period.x() > 0 ? static_cast<int>(std::lround(image.x() / context_.period.x()))
                                : 0,
        context_.period.y() > 0 ? static_cast<int>(std::lround(image.y() / context_.period.y()))
                                : 0};
  }

  Vec3 offset_at_corner(const NeighbourView& v, std::size_t i) const {
    Vec3 o = v.offset;
    o.x() -= kCorners[i].x * hx_;
    o.y() -= kCorners[i].y * hy_;
    return o;
  }

  double corner_distance(const NeighbourView& v, std::size_t i) const {
    const auto measure = [&] {
      return measurer_.distance(dummy_.shape, v.other->shape, offset_at_corner(v, i), v.cutoff);
    };
    return on_lattice_ ? cache_->distance(corner_key(v, i), measure) : measure();
  }

  double corner_angle(const NeighbourView& v, std::size_t i) const {
    const auto measure = [&] {
      const Vec3 g = measurer_.direction(dummy_.shape, v.other->shape, offset_at_corner(v, i));
      return std::atan2(g.y(), g.x());
    };
    return on_lattice_ ? cache_->angle(corner_key(v, i), measure) : measure();
  }

  // Sector boundaries, where the bands of the two axes differ: the direction modelled as turning
  // about a pole fitted to the corners' angles, its boundaries rays from the pole.
  void add_sector_cuts(const NeighbourView& v, PlaneNeighbour& n, std::uint64_t& axes) {
    const int ca = dummy_.category, cb = v.other->category;
    const std::vector<double>& breakpoints = interaction_.breakpoints(ca, cb);
    const Vec3 direction = measurer_.direction(dummy_.shape, v.other->shape, v.offset);
    n.axis = measurer_.bins().axis_of(direction);
    const int directions = measurer_.bins().directions();
    const double step = 2 * core::kPi / directions;
    const double angle = std::atan2(direction.y(), direction.x());
    const long sector = std::lround(angle / step);
    const double margin = step / 2 - std::abs(angle - static_cast<double>(sector) * step);
    // Whether two axes give different bands somewhere in the cell's range of distances.
    const double range_low = v.exact ? v.d - corner_ : v.lo - corner_;
    const double range_high = v.exact ? v.d + corner_ : v.hi + corner_;
    // (Bands of two axes are other parameters unless both are a hard core or beyond.)
    const auto differ = [&](int axis_a, int axis_b) {
      const auto differ_at = [&](double x) {
        const int band_a = interaction_.band(ca, cb, axis_a, x);
        return band_a >= 0 || band_a != interaction_.band(ca, cb, axis_b, x);
      };
      if (differ_at(std::max(0.0, range_low))) return true;
      return std::any_of(breakpoints.begin(), breakpoints.end(), [&](double t) {
        return t > range_low && t <= range_high && differ_at(t);
      });
    };
    const long half_turn = directions / 2;
    const auto axis_of_sector = [&](long s) {
      return static_cast<int>(((s % half_turn) + half_turn) % half_turn);
    };
    const long nearest_other = sector + (angle > static_cast<double>(sector) * step ? 1 : -1);
    if (!(directions > 2 && margin * v.offset.norm() < kSectorReach * corner_ &&
          differ(n.axis, axis_of_sector(nearest_other)))) {
      return;
    }
    // The angle at the four corners, relative to the centre's; its slope by least squares.
    std::array<double, 4> turns;
    for (std::size_t i = 0; i < 4; ++i) {
      const double diff = corner_angle(v, i) - angle;
      turns[i] = diff - 2 * core::kPi * std::round(diff / (2 * core::kPi));
    }
    double ax = 0.0, ay = 0.0;  // the corners are symmetric: least squares per axis
    for (std::size_t i = 0; i < 4; ++i) {
      ax += kCorners[i].x * turns[i] / (4 * hx_);
      ay += kCorners[i].y * turns[i] / (4 * hy_);
    }
    const double rate = std::hypot(ax, ay);
    // The direction turns about a pole: for the angle of (P − p), ∇θ = (P_y, −P_x)/|P|²
    // at p = 0, so P = (−a_y, a_x)/|a|². Sector boundaries are then rays from P.
    const double px = -ay / (rate * rate), py = ax / (rate * rate);
    const double pole_angle = std::atan2(py, px);
    for (const int sign : {-1, 1}) {
      // The boundary's ray from the pole, in the pole model's angles.
      const double ray = pole_angle + (static_cast<double>(sector) + 0.5 * sign) * step - angle;
      const double nx = -std::sin(ray), ny = std::cos(ray);
      const double centre_side = -(nx * px + ny * py);  // n·(0 − P)
      if (!meets(nx, ny, nx * px + ny * py)) continue;
      const long other_sector = sector + sign;
      const int other_axis = axis_of_sector(other_sector);
      if (other_axis == n.axis || !differ(n.axis, other_axis)) continue;
      // Beyond the boundary: the side of the ray's line away from the centre.
      const double s0 = centre_side >= 0 ? 1.0 : -1.0;
      sides_.push_back({s0 * nx, s0 * ny, s0 * (nx * px + ny * py)});
      cuts_.push_back({true, 0.0, false, other_axis, 0, static_cast<int>(sides_.size()) - 1, 1});
      axes |= std::uint64_t{1} << other_axis;
    }
  }

  // Thresholds of `axes` within (low, high], ascending, with the axes they belong to.
  std::vector<std::pair<double, std::uint64_t>> thresholds_within(int ca, int cb,
                                                                  std::uint64_t axes, double low,
                                                                  double high) const {
    std::vector<std::pair<double, std::uint64_t>> found;
    for (int axis = 0; axis < 64 && (axes >> axis) != 0; ++axis) {
      if (!holds(axes, axis)) continue;
      for (const double t : interaction_.thresholds(ca, cb, axis)) {
        if (t <= low || t > high) continue;
        auto at =
            std::find_if(found.begin(), found.end(), [&](const auto& f) { return f.first == t; });
        if (at == found.end()) {
          found.push_back({t, 0});
          at = found.end() - 1;
        }
        at->second |= std::uint64_t{1} << axis;
      }
    }
    std::sort(found.begin(), found.end());
    return found;
  }

  // Level sets of the distance at the thresholds that cross the cell (level_set_chords.hpp): the
  // gradient by least squares through the centre from the corners off contact, then the circle
  // field through them from there.
  void add_distance_cuts(const NeighbourView& v, std::uint64_t axes) {
    const auto crossing =
        thresholds_within(dummy_.category, v.other->category, axes, v.d - corner_, v.d + corner_);
    if (crossing.empty()) return;
    const double d = v.d;
    // The corners off contact (at contact the field is flat).
    std::array<double, 4> at;
    std::array<Point2, 4> q;
    int off = 0;
    double sxx = 0.0, sxy = 0.0, syy = 0.0, bx = 0.0, by = 0.0;
    for (std::size_t i = 0; i < 4; ++i) {
      const double distance = corner_distance(v, i);
      if (distance <= 0.0) continue;
      const double qx = kCorners[i].x * hx_, qy = kCorners[i].y * hy_;
      q[static_cast<std::size_t>(off)] = {qx, qy};
      at[static_cast<std::size_t>(off++)] = distance;
      sxx += qx * qx;
      sxy += qx * qy;
      syy += qy * qy;
      bx += qx * (distance - d);
      by += qy * (distance - d);
    }
    const double det = sxx * syy - sxy * sxy;
    const double corner4 = (corner_ * corner_) * (corner_ * corner_);
    const double gx = det > 1e-12 * corner4 ? (syy * bx - sxy * by) / det : 0.0;
    const double gy = det > 1e-12 * corner4 ? (sxx * by - sxy * bx) / det : 0.0;
    const double slope = std::hypot(gx, gy);
    if (!(slope > 1e-9)) return;
    // A curvature radius below the cell's half-diagonal is taken as that radius.
    const CircleField linear{gx / slope, gy / slope, slope, 0.0};
    const CircleField field =
        off >= 3 ? fitted_circle_field(q.data(), at.data(), off, d, linear, 1.0 / corner_) : linear;
    for (const auto& [b, threshold_axes] : crossing) {
      const LevelSet set =
          level_set_at(field.nx, field.ny, field.slope, field.curvature, d, b, 1.0 / corner_);
      PlaneCut cut{
          false, b, set.curvature >= 0, -1, threshold_axes, static_cast<int>(sides_.size()), 0};
      cut.side_count = append_level_chords(set, hx_, hy_, sides_);
      too_curved_ |= std::abs(set.curvature) * corner_ >= 1.0 - 1e-9;  // clamped
      cuts_.push_back(cut);
    }
  }

  // The cell cut along every boundary, nearest neighbours first (their hard cores drop pieces
  // early); after a neighbour's cuts, pieces in its hard core are dropped. A distance cut only
  // splits pieces on the side of the axes whose threshold it is.
  const std::vector<Piece>& cut_into_pieces(bool* uniform) {
    std::stable_sort(
        neighbours_.begin(), neighbours_.end(),
        [](const PlaneNeighbour& a, const PlaneNeighbour& b) { return a.distance < b.distance; });
    constexpr std::size_t kMaxCuts = 64, kMaxPieces = 256;
    thread_local std::vector<Piece> pieces, next;
    pieces.assign(1, Piece{});
    pieces[0].polygon.n = 4;
    pieces[0].polygon.p[0] = {-hx_, -hy_};
    pieces[0].polygon.p[1] = {hx_, -hy_};
    pieces[0].polygon.p[2] = {hx_, hy_};
    pieces[0].polygon.p[3] = {-hx_, hy_};
    const double cell_area = size_.x() * size_.y();
    const double negligible = 1e-12 * cell_area;
    Polygon beyond;
    std::array<Polygon, 2> left;
    for (const PlaneNeighbour& n : neighbours_) {
      for (int c = n.first_cut; c < n.first_cut + n.cut_count; ++c) {
        const PlaneCut& cut = cuts_[static_cast<std::size_t>(c)];
        const HalfPlane* first = sides_.data() + cut.first_side;
        const HalfPlane* last = first + cut.side_count;
        if (static_cast<std::size_t>(c) >= kMaxCuts || pieces.size() >= kMaxPieces) {
          // Too many boundaries: the rest keep the centre's side.
          const bool centre_inside =
              std::all_of(first, last, [](const HalfPlane& h) { return h.c >= 0; });
          if (static_cast<std::size_t>(c) < kMaxCuts && centre_inside) {
            for (Piece& piece : pieces) piece.inside |= std::uint64_t{1} << c;
          }
          continue;
        }
        next.clear();
        for (Piece& piece : pieces) {
          if (!cut.sector && !holds(cut.axes, piece_axis(n, cuts_, piece.inside))) {
            next.push_back(piece);
            continue;
          }
          // Outside C: beyond the first side, then beyond the second within the first, ….
          // What is left inside the sides so far, alternating between two buffers.
          const Polygon* rest = &piece.polygon;
          bool empty = false;
          for (const HalfPlane* h = first; h != last; ++h) {
            clip(*rest, {-h->nx, -h->ny, -h->c}, beyond);
            if (beyond.area() > negligible) next.push_back({beyond, piece.inside});
            Polygon& out = rest == &left[0] ? left[1] : left[0];
            clip(*rest, *h, out);
            rest = &out;
            if (rest->area() <= negligible) {
              empty = true;
              break;
            }
          }
          if (!empty) next.push_back({*rest, piece.inside | (std::uint64_t{1} << c)});
        }
        if (uniform && next.size() != pieces.size()) *uniform = false;
        std::swap(pieces, next);
      }
      next.clear();
      for (const Piece& piece : pieces) {
        const int axis = piece_axis(n, cuts_, piece.inside);
        if (interaction_.band(dummy_.category, n.category, axis,
                              piece_distance(n, cuts_, piece.inside, axis)) !=
            Interaction::kHardCore) {
          next.push_back(piece);
        }
      }
      std::swap(pieces, next);
    }
    return pieces;
  }

  // Pieces with the same statistics are one part (few pieces: a linear search), parts ordered by
  // their statistics.
  std::vector<CellPart> parts_of(const std::vector<Piece>& pieces) const {
    const double cell_area = size_.x() * size_.y();
    std::vector<CellPart> result;
    for (const Piece& piece : pieces) {
      model::InteractionCounts counts = base_;
      for (const PlaneNeighbour& n : neighbours_) {
        const int axis = piece_axis(n, cuts_, piece.inside);
        const int band = interaction_.band(dummy_.category, n.category, axis,
                                           piece_distance(n, cuts_, piece.inside, axis));
        if (band >= 0) counts.add(interaction_.parameter(dummy_.category, n.category, axis, band));
      }
      const double fraction = piece.polygon.area() / cell_area;
      const auto same = std::find_if(result.begin(), result.end(),
                                     [&](const CellPart& p) { return p.counts == counts.counts; });
      if (same != result.end()) {
        same->fraction += fraction;
      } else {
        result.push_back({fraction, std::move(counts.counts)});
      }
    }
    std::sort(result.begin(), result.end(),
              [](const CellPart& a, const CellPart& b) { return a.counts < b.counts; });
    return result;
  }

  const CellContext& context_;
  const Interaction& interaction_;
  const geometry::PairMeasurer& measurer_;
  const geometry::Element& dummy_;
  const Vec3 size_;
  CornerCache* cache_;
  std::vector<PlaneNeighbour>& neighbours_;
  std::vector<PlaneCut>& cuts_;
  std::vector<HalfPlane>& sides_;
  double hx_ = 0, hy_ = 0, corner_ = 0, sample_reach_ = 0;
  std::array<long, 4> lattice_x_{}, lattice_y_{};
  bool on_lattice_ = false;
  model::InteractionCounts base_;  // neighbours with one effect on the whole cell
  bool forbidden_ = false;
  bool too_curved_ = false;  // a level set curves more than the chords can follow
};

}  // namespace

std::vector<CellPart> integrate_cell_plane(const CellContext& context,
                                           const geometry::Element& dummy, const Vec3& size,
                                           bool* uniform, bool* too_curved, CornerCache* cache) {
  return PlaneCell(context, dummy, size, cache).integrate(uniform, too_curved);
}

}  // namespace shapeproc::fit
