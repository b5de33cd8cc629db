#include "libshapeproc/fit/quadrature_cell.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "libshapeproc/core/constants.hpp"

namespace shapeproc::fit {

using geometry::Vec3;
using model::Interaction;

namespace {

// A sector boundary is looked for when the angle to it times the distance between centres (its
// distance for directions between centres) is below this many half-diagonals of the cell: the
// gravitation direction of near shapes may turn faster.
constexpr double kSectorReach = 1.5;

double cell_radius(int dimension, double measure) {
  return dimension == 2 ? std::sqrt(measure / core::kPi)
                        : std::cbrt(3.0 * measure / (4.0 * core::kPi));
}

// A place where the statistics change inside the cell: with probability `fraction` the
// neighbour's band is `other_band` (on `other_axis`) instead of the centre's.
struct Cut {
  int neighbour;  // index into the neighbour list
  double fraction;
  int other_band, other_axis;
};

struct Neighbour {
  int category;
  int band, axis;
};

}  // namespace

double cut_fraction(int dimension, double cell_measure, double x) {
  const double r = cell_radius(dimension, cell_measure);
  if (x >= r) return 0.0;
  x = std::max(0.0, x);
  if (dimension == 2) {
    return (r * r * std::acos(x / r) - x * std::sqrt(r * r - x * x)) / (core::kPi * r * r);
  }
  return (r - x) * (r - x) * (2 * r + x) / (4.0 * r * r * r);  // cap volume / ball volume
}

namespace {

// ---- 2D: cells cut along the boundaries' local models ------------------------------------------

struct Point2 {
  double x, y;
};

// The half-plane n·p ≤ c (p relative to the cell's centre).
struct HalfPlane {
  double nx, ny, c;
};

// A convex polygon with inline storage: a square cut by k lines has at most 4 + k vertices.
// Copies move only the vertices in use.
struct Polygon {
  static constexpr int kCapacity = 48;
  std::array<Point2, kCapacity> p;
  int n = 0;

  Polygon() = default;
  Polygon(const Polygon& o) : n(o.n) { std::copy_n(o.p.begin(), n, p.begin()); }
  Polygon& operator=(const Polygon& o) {
    n = o.n;
    std::copy_n(o.p.begin(), n, p.begin());
    return *this;
  }

  double area() const {
    if (n == 0) return 0.0;
    double twice = 0.0;
    for (int i = 0; i + 1 < n; ++i) {
      const Point2& a = p[static_cast<std::size_t>(i)];
      const Point2& b = p[static_cast<std::size_t>(i + 1)];
      twice += a.x * b.y - a.y * b.x;
    }
    const Point2& a = p[static_cast<std::size_t>(n - 1)];
    twice += a.x * p[0].y - a.y * p[0].x;
    return 0.5 * twice;
  }
};

// out = polygon ∩ h (Sutherland–Hodgman against one line).
void clip(const Polygon& polygon, const HalfPlane& h, Polygon& out) {
  out.n = 0;
  auto add = [&](const Point2& q) {
    if (out.n < Polygon::kCapacity) out.p[static_cast<std::size_t>(out.n++)] = q;
  };
  for (int i = 0; i < polygon.n; ++i) {
    const Point2& a = polygon.p[static_cast<std::size_t>(i)];
    const Point2& b = polygon.p[static_cast<std::size_t>((i + 1) % polygon.n)];
    const double fa = h.nx * a.x + h.ny * a.y - h.c;
    const double fb = h.nx * b.x + h.ny * b.y - h.c;
    if (fa <= 0) add(a);
    if ((fa < 0 && fb > 0) || (fa > 0 && fb < 0)) {
      const double t = fa / (fa - fb);
      add({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
    }
  }
}

// One boundary inside the cell, with the convex region C = ∩ sides on one side of it. A distance
// cut is a level set d = `breakpoint` of one neighbour, for the axes in `axes` (C holds the
// distances below it when `inside_below`, else those at or above it); a sector cut is where the
// neighbour's direction enters the sector of `other_axis` (C is that side).
struct PlaneCut {
  bool sector;
  double breakpoint;
  bool inside_below;
  int other_axis;
  std::uint64_t axes;
  int first_side, side_count;  // into the cell's list of half-planes
};

// A neighbour whose boundaries cross the cell: its centre's axis and exact distance, and its
// cuts (sector cuts first, then distance cuts by ascending breakpoint).
struct PlaneNeighbour {
  int category;
  int axis;
  double distance;
  int first_cut, cut_count;
};

// A piece of the cell and the cuts whose region C holds it.
struct Piece {
  Polygon polygon;
  std::uint64_t inside = 0;
};

bool holds(std::uint64_t inside, int cut) { return ((inside >> cut) & 1u) != 0; }

int piece_axis(const PlaneNeighbour& n, const std::vector<PlaneCut>& cuts, std::uint64_t inside) {
  for (int c = n.first_cut; c < n.first_cut + n.cut_count; ++c) {
    const PlaneCut& cut = cuts[static_cast<std::size_t>(c)];
    if (cut.sector && holds(inside, c)) return cut.other_axis;
  }
  return n.axis;
}

// A distance of the piece's interval between `axis`'s thresholds: with the cuts of that axis at
// b_0 < … < b_m-1, a piece below k of them lies in [b_{m-k-1}, b_{m-k}).
double piece_distance(const PlaneNeighbour& n, const std::vector<PlaneCut>& cuts,
                      std::uint64_t inside, int axis) {
  double lower = -1.0, upper = -1.0;  // breakpoints of the piece's interval (-1: none)
  int m = 0, below = 0;
  for (int c = n.first_cut; c < n.first_cut + n.cut_count; ++c) {
    const PlaneCut& cut = cuts[static_cast<std::size_t>(c)];
    if (cut.sector || !holds(cut.axes, axis)) continue;
    ++m;
    if (holds(inside, c) == cut.inside_below) ++below;
  }
  if (m == 0) return n.distance;
  const int first_above = m - below;
  int k = 0;
  for (int c = n.first_cut; c < n.first_cut + n.cut_count; ++c) {
    const PlaneCut& cut = cuts[static_cast<std::size_t>(c)];
    if (cut.sector || !holds(cut.axes, axis)) continue;
    if (k == first_above - 1) lower = cut.breakpoint;
    if (k == first_above) upper = cut.breakpoint;
    ++k;
  }
  if (upper < 0) return std::max(n.distance, lower);
  if (lower < 0) return std::min(n.distance, std::nextafter(upper, 0.0));
  return 0.5 * (lower + upper);
}

// Corners of the cell, in units of half its side.
constexpr std::array<Point2, 4> kCorners{{{1, 1}, {-1, 1}, {1, -1}, {-1, -1}}};

std::vector<CellPart> integrate_cell_plane(const CellContext& context,
                                           const geometry::Element& dummy, const Vec3& size,
                                           bool* uniform, CornerCache* cache) {
  const Interaction& interaction = *context.interaction;
  const geometry::PairMeasurer& measurer = *context.measurer;
  const double hx = 0.5 * size.x(), hy = 0.5 * size.y();
  const double side = std::sqrt(size.x() * size.y());  // of the square of the same area
  const double corner = std::hypot(hx, hy);
  // Samples at the corners use one cut-off whatever the refinement, so that they can be shared.
  const double sample_reach = 3 * (context.top_corner > 0 ? context.top_corner : corner);
  // Lattice coordinates of the corners, when they lie on the lattice.
  std::array<long, 4> lattice_x{}, lattice_y{};
  bool on_lattice =
      cache != nullptr && context.lattice_step.x() > 0 && context.lattice_step.y() > 0;
  for (std::size_t i = 0; i < 4 && on_lattice; ++i) {
    const double fx = (dummy.position.x() + kCorners[i].x * hx - context.lattice_origin.x()) /
                      context.lattice_step.x();
    const double fy = (dummy.position.y() + kCorners[i].y * hy - context.lattice_origin.y()) /
                      context.lattice_step.y();
    lattice_x[i] = std::lround(fx);
    lattice_y[i] = std::lround(fy);
    on_lattice = std::abs(fx - static_cast<double>(lattice_x[i])) < 1e-6 &&
                 std::abs(fy - static_cast<double>(lattice_y[i])) < 1e-6;
  }
  // Whether the line n·p = c meets the cell.
  const auto meets = [&](double nx, double ny, double c) {
    return std::abs(c) < std::abs(nx) * hx + std::abs(ny) * hy;
  };
  // Work space kept by the thread (integrate_cell_adaptive calls this function again only after
  // it returned).
  thread_local std::vector<PlaneNeighbour> neighbours;
  thread_local std::vector<PlaneCut> cuts;
  thread_local std::vector<HalfPlane> sides;
  neighbours.clear();
  cuts.clear();
  sides.clear();
  model::InteractionCounts base;  // neighbours with one effect on the whole cell
  bool forbidden = false;
  // Candidates nearest first: a hard core over the whole cell ends the work early.
  struct Candidate {
    double gap;
    int k;
    Vec3 offset;
  };
  thread_local std::vector<Candidate> candidates;
  candidates.clear();
  context.grid->for_each_candidate(dummy.position, [&](int k) {
    const geometry::Element& other = (*context.data)[static_cast<std::size_t>(k)];
    if (!interaction.interacts(dummy.category, other.category)) return;
    Vec3 offset = other.position - dummy.position;
    for (int axis = 0; axis < 2; ++axis) {
      if (context.period[axis] > 0)
        offset[axis] -= context.period[axis] * std::round(offset[axis] / context.period[axis]);
    }
    const double gap = offset.norm() - measurer.radius(dummy.shape) - measurer.radius(other.shape);
    if (gap >= interaction.max_range(dummy.category, other.category) + corner) return;
    candidates.push_back({gap, k, offset});
  });
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    return a.gap < b.gap || (a.gap == b.gap && a.k < b.k);
  });
  for (const Candidate& candidate : candidates) {
    if (forbidden) break;
    const int k = candidate.k;
    const Vec3& offset = candidate.offset;
    const geometry::Element& other = (*context.data)[static_cast<std::size_t>(k)];
    const int ca = dummy.category, cb = other.category;
    const double reach = interaction.max_range(ca, cb);
    const auto bounds = measurer.distance_bounds(dummy.shape, other.shape, offset);
    // The circles about the reference positions may bound d better than the boxes (round shapes).
    const double lo = std::max(bounds.first, candidate.gap), hi = bounds.second;
    if (lo >= reach + corner) continue;
    const double hard_core = interaction.min_hard_core(ca, cb);
    if (hi + corner < hard_core) {
      forbidden = true;  // within every axis's hard core all over the cell
      break;
    }
    // The exact distance when a threshold that matters may fall within the cell's range: of any
    // axis, or of the axis alone when it is certain over the cell.
    const double cutoff = reach + sample_reach;
    const std::vector<double>& breakpoints = interaction.breakpoints(ca, cb);
    const auto within = [](const std::vector<double>& marks, double low, double high) {
      return std::any_of(marks.begin(), marks.end(),
                         [&](double t) { return t > low && t <= high; });
    };
    const auto any_within = [&](double low, double high) { return within(breakpoints, low, high); };
    const int certain = measurer.certain_axis(dummy.shape, other.shape, offset, corner);
    const std::vector<double>& deciding =
        certain >= 0 ? interaction.thresholds(ca, cb, certain) : breakpoints;
    double d = lo;
    const bool exact = within(deciding, lo - corner, hi + corner);
    if (exact) {
      d = measurer.distance(dummy.shape, other.shape, offset, cutoff);
      if (d + corner < hard_core) {
        forbidden = true;
        break;
      }
      if (d - corner >= reach) continue;
    }
    // The dummy moved by p sees the neighbour at offset − p.
    const Vec3 image = offset - (other.position - dummy.position);
    const auto key = [&](std::size_t i) {
      return CornerCache::Key{
          dummy.shape,
          k,
          lattice_x[i],
          lattice_y[i],
          context.period.x() > 0 ? static_cast<int>(std::lround(image.x() / context.period.x()))
                                 : 0,
          context.period.y() > 0 ? static_cast<int>(std::lround(image.y() / context.period.y()))
                                 : 0};
    };
    const auto at_corner = [&](std::size_t i) {
      Vec3 o = offset;
      o.x() -= kCorners[i].x * hx;
      o.y() -= kCorners[i].y * hy;
      return o;
    };
    const auto sample_distance = [&](std::size_t i) {
      const auto measure = [&] {
        return measurer.distance(dummy.shape, other.shape, at_corner(i), cutoff);
      };
      return on_lattice ? cache->distance(key(i), measure) : measure();
    };
    const auto sample_angle = [&](std::size_t i) {
      const auto measure = [&] {
        const Vec3 g = measurer.direction(dummy.shape, other.shape, at_corner(i));
        return std::atan2(g.y(), g.x());
      };
      return on_lattice ? cache->angle(key(i), measure) : measure();
    };
    PlaneNeighbour n{cb, certain, d, static_cast<int>(cuts.size()), 0};
    std::uint64_t axes = 0;  // axes whose thresholds matter in the cell
    if (n.axis < 0 && (exact ? !any_within(d - corner, d + corner) : true)) {
      // Every axis keeps one band over the cell: when all are a hard core, or all beyond, the
      // axis does not matter.
      const int first = interaction.band(ca, cb, 0, d);
      bool same = first < 0;
      for (int axis = 1; axis < measurer.bins().axis_count() && same; ++axis)
        same = interaction.band(ca, cb, axis, d) == first;
      if (same) n.axis = 0;
    }
    if (n.axis < 0) {
      // Sector boundaries, where the bands of the two axes differ.
      const Vec3 direction = measurer.direction(dummy.shape, other.shape, offset);
      n.axis = measurer.bins().axis_of(direction);
      const int directions = measurer.bins().directions();
      const double step = 2 * core::kPi / directions;
      const double angle = std::atan2(direction.y(), direction.x());
      const long sector = std::lround(angle / step);
      const double margin = step / 2 - std::abs(angle - static_cast<double>(sector) * step);
      // Whether two axes give different bands somewhere in the cell's range of distances.
      const double range_low = exact ? d - corner : lo - corner,
                   range_high = exact ? d + corner : hi + corner;
      // (Bands of two axes are other parameters unless both are a hard core or beyond.)
      const auto differ = [&](int axis_a, int axis_b) {
        const auto differ_at = [&](double x) {
          const int band_a = interaction.band(ca, cb, axis_a, x);
          return band_a >= 0 || band_a != interaction.band(ca, cb, axis_b, x);
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
      if (directions > 2 && margin * offset.norm() < kSectorReach * corner &&
          differ(n.axis, axis_of_sector(nearest_other))) {
        // The angle at the four corners, relative to the centre's; its slope by least squares.
        std::array<double, 4> turns;
        for (std::size_t i = 0; i < 4; ++i) {
          const double diff = sample_angle(i) - angle;
          turns[i] = diff - 2 * core::kPi * std::round(diff / (2 * core::kPi));
        }
        double ax = 0.0, ay = 0.0;  // the corners are symmetric: least squares per axis
        for (std::size_t i = 0; i < 4; ++i) {
          ax += kCorners[i].x * turns[i] / (4 * hx);
          ay += kCorners[i].y * turns[i] / (4 * hy);
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
          sides.push_back({s0 * nx, s0 * ny, s0 * (nx * px + ny * py)});
          cuts.push_back({true, 0.0, false, other_axis, 0, static_cast<int>(sides.size()) - 1, 1});
          axes |= std::uint64_t{1} << other_axis;
        }
      }
    }
    axes |= std::uint64_t{1} << n.axis;
    // Thresholds of those axes within (low, high], ascending, with the axes they belong to.
    const auto thresholds_within = [&](double low, double high) {
      std::vector<std::pair<double, std::uint64_t>> found;
      for (int axis = 0; axis < 64 && (axes >> axis) != 0; ++axis) {
        if (!holds(axes, axis)) continue;
        for (const double t : interaction.thresholds(ca, cb, axis)) {
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
    };
    if (exact) {
      const auto crossing = thresholds_within(d - corner, d + corner);
      if (!crossing.empty()) {
        // Slope and curvature of the distance across the cell, from the corners off contact
        // (at contact the field is flat): d(p) ≈ d + g·p + ½κ (t·p)² with t across g, since
        // along a gradient line a distance grows linearly. Slope by least squares through the
        // centre, then κ from what is left.
        std::array<double, 4> at;
        std::array<Point2, 4> q;
        double sxx = 0.0, sxy = 0.0, syy = 0.0, bx = 0.0, by = 0.0;
        int off_contact = 0;
        for (std::size_t i = 0; i < 4; ++i) {
          at[i] = sample_distance(i);
          q[i] = {kCorners[i].x * hx, kCorners[i].y * hy};
          if (at[i] <= 0.0) continue;
          const double qx = q[i].x, qy = q[i].y;
          sxx += qx * qx;
          sxy += qx * qy;
          syy += qy * qy;
          bx += qx * (at[i] - d);
          by += qy * (at[i] - d);
          ++off_contact;
        }
        const double det = sxx * syy - sxy * sxy;
        const double corner4 = (corner * corner) * (corner * corner);
        const double gx = det > 1e-12 * corner4 ? (syy * bx - sxy * by) / det : 0.0;
        const double gy = det > 1e-12 * corner4 ? (sxx * by - sxy * bx) / det : 0.0;
        const double slope = std::hypot(gx, gy);
        if (slope > 1e-9) {
          const double nx = gx / slope, ny = gy / slope;  // ξ along the gradient, η across
          const double tx = -ny, ty = nx;
          double fit = 0.0, weight = 0.0;
          for (std::size_t i = 0; i < 4; ++i) {
            if (at[i] <= 0.0) continue;
            const double across = tx * q[i].x + ty * q[i].y;
            const double w = 0.5 * across * across;
            fit += w * (at[i] - d - gx * q[i].x - gy * q[i].y);
            weight += w * w;
          }
          const bool curved = off_contact >= 3 && weight > 1e-3 * corner4;
          // A curvature radius below the cell's half-diagonal is taken as that radius.
          const double bend =
              std::clamp(curved ? 0.5 * fit / weight / slope : 0.0, -1.0 / corner, 1.0 / corner);
          // The level set ξ = level − bend·η² as chords across the cell, each moved towards
          // the parabola by 2/3 of its sagitta so that the areas balance; the convex side is
          // the intersection of the chords' half-planes.
          const double sagitta = std::abs(bend) * corner * corner;
          const int chords = sagitta < 0.05 * side ? 1 : sagitta < 0.5 * side ? 2 : 4;
          for (const auto& [b, threshold_axes] : crossing) {
            const double level = (b - d) / slope;
            PlaneCut cut{false, b, bend >= 0, -1, threshold_axes, static_cast<int>(sides.size()),
                         chords};
            const double sign = cut.inside_below ? 1.0 : -1.0;
            for (int i = 0; i < chords; ++i) {
              const double e0 = -corner + 2 * corner * i / chords, e1 = e0 + 2 * corner / chords;
              const double lift = (2.0 / 3.0) * bend * 0.25 * (e1 - e0) * (e1 - e0);
              const double f0 = level - bend * e0 * e0 + lift, f1 = level - bend * e1 * e1 + lift;
              const double s = (f1 - f0) / (e1 - e0);
              // ξ − s·η ≤ f0 − s·e0 below the chord; ≥ on the other side.
              sides.push_back({sign * (nx - s * tx), sign * (ny - s * ty), sign * (f0 - s * e0)});
            }
            cuts.push_back(cut);
          }
        }
      }
    }
    n.cut_count = static_cast<int>(cuts.size()) - n.first_cut;
    if (n.cut_count == 0) {
      const int band = interaction.band(ca, cb, n.axis, n.distance);
      if (band == Interaction::kHardCore) forbidden = true;
      if (band >= 0) base.add(interaction.parameter(ca, cb, n.axis, band));
      continue;
    }
    neighbours.push_back(n);
  }
  if (uniform) *uniform = true;
  if (forbidden) return {};
  // Cut the cell along every boundary, nearest neighbours first (their hard cores drop pieces
  // early); after a neighbour's cuts, pieces in its hard core are dropped. A distance cut only
  // splits pieces on the side of the axes whose threshold it is.
  std::stable_sort(
      neighbours.begin(), neighbours.end(),
      [](const PlaneNeighbour& a, const PlaneNeighbour& b) { return a.distance < b.distance; });
  constexpr std::size_t kMaxCuts = 64, kMaxPieces = 256;
  thread_local std::vector<Piece> pieces, next;
  pieces.assign(1, Piece{});
  pieces[0].polygon.n = 4;
  pieces[0].polygon.p[0] = {-hx, -hy};
  pieces[0].polygon.p[1] = {hx, -hy};
  pieces[0].polygon.p[2] = {hx, hy};
  pieces[0].polygon.p[3] = {-hx, hy};
  const double cell_area = size.x() * size.y();
  const double negligible = 1e-12 * cell_area;
  Polygon beyond;
  std::array<Polygon, 2> left;
  for (const PlaneNeighbour& n : neighbours) {
    for (int c = n.first_cut; c < n.first_cut + n.cut_count; ++c) {
      const PlaneCut& cut = cuts[static_cast<std::size_t>(c)];
      const HalfPlane* first = sides.data() + cut.first_side;
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
        if (!cut.sector && !holds(cut.axes, piece_axis(n, cuts, piece.inside))) {
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
      const int axis = piece_axis(n, cuts, piece.inside);
      if (interaction.band(dummy.category, n.category, axis,
                           piece_distance(n, cuts, piece.inside, axis)) != Interaction::kHardCore) {
        next.push_back(piece);
      }
    }
    std::swap(pieces, next);
  }
  // Pieces with the same statistics are one part (few pieces: a linear search), parts ordered by
  // their statistics.
  std::vector<CellPart> result;
  for (const Piece& piece : pieces) {
    model::InteractionCounts counts = base;
    for (const PlaneNeighbour& n : neighbours) {
      const int axis = piece_axis(n, cuts, piece.inside);
      const int band = interaction.band(dummy.category, n.category, axis,
                                        piece_distance(n, cuts, piece.inside, axis));
      if (band >= 0) counts.add(interaction.parameter(dummy.category, n.category, axis, band));
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

// 3D: each boundary cuts the ball of the cell's measure at its estimated distance.
std::vector<CellPart> integrate_cell_ball(const CellContext& context,
                                          const geometry::Element& dummy, const Vec3& size,
                                          bool* uniform) {
  double measure = 1.0;
  for (int axis = 0; axis < context.dimension; ++axis) measure *= size[axis];
  const double side = std::pow(measure, 1.0 / context.dimension);
  const Interaction& interaction = *context.interaction;
  const geometry::PairMeasurer& measurer = *context.measurer;
  const double cell_measure = context.dimension == 2 ? side * side : side * side * side;
  const double radius = cell_radius(context.dimension, cell_measure);
  // Every point of the cell lies within `corner` of its centre.
  const double corner = 0.5 * side * std::sqrt(static_cast<double>(context.dimension));
  bool near_boundary = false;
  std::vector<Neighbour> neighbours;
  std::vector<Cut> cuts;
  bool hard_core = false;
  context.grid->for_each_candidate(dummy.position, [&](int k) {
    if (hard_core) return;
    const geometry::Element& other = (*context.data)[static_cast<std::size_t>(k)];
    if (!interaction.interacts(dummy.category, other.category)) return;
    const double reach = interaction.max_range(dummy.category, other.category);
    Vec3 offset = other.position - dummy.position;
    for (int axis = 0; axis < context.dimension; ++axis) {
      if (context.period[axis] > 0)
        offset[axis] -= context.period[axis] * std::round(offset[axis] / context.period[axis]);
    }
    if (offset.norm() - measurer.radius(dummy.shape) - measurer.radius(other.shape) >=
        reach + corner)
      return;
    auto [lo, hi] = measurer.distance_bounds(dummy.shape, other.shape, offset);
    if (lo >= reach + corner) return;
    int axis = measurer.axis_from_boxes(dummy.shape, other.shape, offset, corner);
    double angular_margin = -1.0;
    int other_axis = -1;
    if (axis < 0) {
      const Vec3 direction = measurer.direction(dummy.shape, other.shape, offset);
      axis = measurer.bins().axis_of(direction);
      if (context.dimension == 2 && measurer.bins().directions() > 1) {
        const double step = 2 * core::kPi / measurer.bins().directions();
        const double angle = std::atan2(direction.y(), direction.x());
        const double sector = std::round(angle / step);
        angular_margin = step / 2 - std::abs(angle - sector * step);
        const long neighbour_sector = static_cast<long>(sector) + (angle > sector * step ? 1 : -1);
        const long half = measurer.bins().directions() / 2;
        other_axis = static_cast<int>(((neighbour_sector % half) + half) % half);
        // The angle to the sector boundary becomes a distance in the plane at the rate of a
        // direction between centres, 1/|offset|; the gravitation direction turns at a similar
        // rate, and measuring its own rate would cost one more direction per near pair.
        angular_margin *= offset.norm();
      }
    }
    // Thresholds of this axis near [lo, hi] decide whether the exact distance is needed.
    double d = lo;
    bool exact = false;
    auto threshold_near = [&](double low, double high) {
      const int band_low = interaction.band(dummy.category, other.category, axis, low);
      const int band_high = interaction.band(dummy.category, other.category, axis, high);
      return band_low != band_high;
    };
    // With an uncertain axis the other axis's thresholds matter too: measure exactly then.
    if (angular_margin >= 0 || threshold_near(std::max(0.0, lo - corner), hi + corner)) {
      d = measurer.distance(dummy.shape, other.shape, offset, reach + corner);
      exact = true;
    }
    const int band = interaction.band(dummy.category, other.category, axis, d);
    const int index = static_cast<int>(neighbours.size());
    neighbours.push_back({other.category, band, axis});
    bool neighbour_near = false;
    if (exact) {
      // The nearest threshold on either side within the cell.
      const int below =
          interaction.band(dummy.category, other.category, axis, std::max(0.0, d - corner));
      const int above = interaction.band(dummy.category, other.category, axis, d + corner);
      if (below != band || above != band) {
        neighbour_near = true;
        // Find the threshold crossing by bisection on the band function (bands are monotone in d).
        const bool downward = below != band;
        double inside = d, outside = downward ? std::max(0.0, d - corner) : d + corner;
        for (int it = 0; it < 60; ++it) {
          const double mid = 0.5 * (inside + outside);
          if (interaction.band(dummy.category, other.category, axis, mid) == band)
            inside = mid;
          else
            outside = mid;
        }
        const double x = std::abs(0.5 * (inside + outside) - d);
        const int other_band = downward ? below : above;
        // Only the nearest crossing on that side is modelled; a second one within the cell is rare.
        if (x < radius)
          cuts.push_back(
              {index, cut_fraction(context.dimension, cell_measure, x), other_band, axis});
      }
    }
    if (angular_margin >= 0 && d < reach + corner) {
      const double x = angular_margin;  // already a distance
      if (x < corner) neighbour_near = true;
      if (x < radius) {
        const int other_band = interaction.band(dummy.category, other.category, other_axis, d);
        // Another axis means other parameters even in the same band.
        if (other_band != band || other_band >= 0) {
          cuts.push_back(
              {index, cut_fraction(context.dimension, cell_measure, x), other_band, other_axis});
        }
      }
    }
    near_boundary = near_boundary || neighbour_near;
    if (band == Interaction::kHardCore) {
      bool rescued = false;
      for (const Cut& cut : cuts)
        rescued = rescued || (cut.neighbour == index && cut.other_band != Interaction::kHardCore);
      // Deep inside a hard core (no boundary of this neighbour within the cell) the whole cell is
      // forbidden, whatever the others do.
      if (!rescued && !neighbour_near) {
        hard_core = true;
        near_boundary = false;
      } else if (!rescued) {
        hard_core = true;
      }
    }
  });
  if (uniform) *uniform = !near_boundary;
  std::vector<CellPart> parts;
  if (hard_core) return parts;
  // At most 5 cuts are combined (32 parts); further ones keep the centre's value.
  const std::size_t used = std::min<std::size_t>(cuts.size(), 5);
  for (std::size_t mask = 0; mask < (std::size_t{1} << used); ++mask) {
    double fraction = 1.0;
    std::vector<Neighbour> state = neighbours;
    for (std::size_t c = 0; c < used; ++c) {
      const Cut& cut = cuts[c];
      if (mask & (std::size_t{1} << c)) {
        fraction *= cut.fraction;
        state[static_cast<std::size_t>(cut.neighbour)].band = cut.other_band;
        state[static_cast<std::size_t>(cut.neighbour)].axis = cut.other_axis;
      } else {
        fraction *= 1.0 - cut.fraction;
      }
    }
    if (fraction <= 0.0) continue;
    model::InteractionCounts counts;
    bool forbidden = false;
    for (const Neighbour& n : state) {
      if (n.band == Interaction::kHardCore) {
        forbidden = true;
        break;
      }
      if (n.band >= 0)
        counts.add(interaction.parameter(dummy.category, n.category, n.axis, n.band));
    }
    if (!forbidden) parts.push_back({fraction, std::move(counts.counts)});
  }
  return parts;
}

}  // namespace

std::vector<CellPart> integrate_cell(const CellContext& context, const geometry::Element& dummy,
                                     const Vec3& size, bool* uniform, CornerCache* cache) {
  if (context.dimension == 2) return integrate_cell_plane(context, dummy, size, uniform, cache);
  return integrate_cell_ball(context, dummy, size, uniform);
}

std::vector<CellPart> integrate_cell_adaptive(const CellContext& context,
                                              const geometry::Element& dummy, const Vec3& size,
                                              int depth, CornerCache* cache) {
  bool uniform = true;
  std::vector<CellPart> parts = integrate_cell(context, dummy, size, &uniform, cache);
  if (uniform || depth <= 0) return parts;
  parts.clear();
  const int children = context.dimension == 2 ? 4 : 8;
  const double share = 1.0 / children;
  for (int child = 0; child < children; ++child) {
    geometry::Element sub = dummy;
    for (int axis = 0; axis < context.dimension; ++axis) {
      sub.position[axis] += ((child >> axis) & 1 ? 0.25 : -0.25) * size[axis];
    }
    for (CellPart& part : integrate_cell_adaptive(context, sub, 0.5 * size, depth - 1, cache)) {
      part.fraction *= share;
      parts.push_back(std::move(part));
    }
  }
  return parts;
}

}  // namespace shapeproc::fit
