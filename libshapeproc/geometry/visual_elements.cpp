#include "libshapeproc/geometry/visual_elements.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <optional>
#include <tuple>
#include <utility>

#include "libshapeproc/geometry/box_tree.hpp"

namespace shapeproc::geometry {

namespace {

// One subpath of the scene, flattened, in scene coordinates.
struct Subpath {
  std::size_t drawable = 0;  // into Grouping::drawables_
  std::vector<Vec2> polyline;
  bool closed = false;
  Box2 box;
  double area = 0.0;  // of the closed polygon
  Path2 path;         // as drawn (clipped to the tile: the clipped polygon)
};

// One drawable of the scene, in scene coordinates: its style and the subpaths it holds.
struct Drawn {
  Drawable2 drawable;  // paths moved out into Subpath::path
  std::size_t element = 0;
  int category = 0;
  std::string name;
  Box2 box;
  std::vector<std::size_t> subpaths;
};

constexpr double kBorderSnap = 1e-3;
// Pieces of ink whose outlines run side by side closer than this (in the drawing's units: a
// tenth of a pixel of an SVG at its own scale) are one piece: no one sees such a gap, and drawing
// programs leave them where a tile's border cut a shape in two (one half ending at y = 39.977,
// the other starting at y = 40).
constexpr double kInkGap = 0.1;

// Another subpath joined to this one, its copy moved by `shift` (a whole number of periods).
struct Link {
  std::size_t to;
  Vec2 shift;
};

// Sutherland–Hodgman: the polygon clipped to the box (the box is convex, so the result is right
// for any polygon; where the polygon leaves and re-enters, the result runs along the box's side).
std::vector<Vec2> clip_to_box(std::vector<Vec2> polygon, const Box2& box) {
  for (int side = 0; side < 4 && !polygon.empty(); ++side) {
    const int axis = side / 2;
    const bool upper = side % 2 == 1;
    const double limit = upper ? box.max()[axis] : box.min()[axis];
    const auto inside = [&](const Vec2& p) { return upper ? p[axis] <= limit : p[axis] >= limit; };
    std::vector<Vec2> out;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const Vec2& a = polygon[i];
      const Vec2& b = polygon[(i + 1) % polygon.size()];
      if (inside(a)) out.push_back(a);
      if (inside(a) != inside(b)) {
        const double t = (limit - a[axis]) / (b[axis] - a[axis]);
        Vec2 crossing = a + t * (b - a);
        crossing[axis] = limit;
        out.push_back(crossing);
      }
    }
    polygon = std::move(out);
  }
  return polygon;
}

Path2 closed_polyline_path(const std::vector<Vec2>& polygon) {
  Path2 path;
  path.closed = true;
  for (std::size_t i = 0; i < polygon.size(); ++i)
    path.segments.push_back(Segment2::line(polygon[i], polygon[(i + 1) % polygon.size()]));
  return path;
}

class Grouping {
 public:
  Grouping(const Scene& scene, const VisualOptions& options) : scene_(scene), options_(options) {
    const Vec3 sizes = scene.window.sizes();
    period_ = Vec2(sizes.x(), sizes.y());
    window_ = Box2(Vec2(scene.window.min().x(), scene.window.min().y()),
                   Vec2(scene.window.max().x(), scene.window.max().y()));
    shifts_.push_back(Vec2::Zero());
    if (options.tile) {
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
          if (dx != 0 || dy != 0) shifts_.push_back(Vec2(dx * period_.x(), dy * period_.y()));
    }
  }

  VisualElements run() {
    collect_subpaths();
    links_.assign(subpaths_.size(), {});
    if (options_.keep_elements) join_within_elements();
    join_crossing_outlines();
    join_contained();
    return assemble();
  }

 private:
  // Every subpath of every element, flattened in scene coordinates (clipped to the tile).
  void collect_subpaths() {
    for (std::size_t e = 0; e < scene_.elements.size(); ++e) {
      const Shape placed = scene_.placed_shape(e);
      const auto* planar = std::get_if<PlanarShape>(&placed.geometry);
      if (!planar) continue;
      for (const Drawable2& drawable : planar->parts) {
        Drawn drawn{Drawable2{{}, drawable.fill_rule, drawable.style},
                    e,
                    scene_.elements[e].category,
                    placed.name,
                    Box2(),
                    {}};
        const bool filled = drawable.filled();
        for (const Path2& path : drawable.paths) {
          if (path.segments.empty()) continue;
          Subpath s;
          s.drawable = drawables_.size();
          const Box2 box = bounding_box(path);
          s.polyline = flatten(path, std::max(box.diagonal().norm() * 1e-3, 1e-9));
          s.closed = path.closed || filled;
          s.path = path;
          if (options_.tile && s.closed) {
            snap_to_border(s.polyline);
            s.polyline = clip_to_box(std::move(s.polyline), window_);
            if (s.polyline.size() < 3) continue;
            s.path = closed_polyline_path(s.polyline);
          }
          if (s.polyline.empty()) continue;
          for (const Vec2& p : s.polyline) s.box.extend(p);
          if (s.closed) s.area = std::abs(signed_area(s.polyline));
          if (options_.tile && s.closed && s.area <= 1e-12 * period_.x() * period_.y()) {
            continue;  // only touches the tile
          }
          drawn.box.extend(s.box);
          drawn.subpaths.push_back(subpaths_.size());
          subpaths_.push_back(std::move(s));
        }
        if (!drawn.subpaths.empty()) drawables_.push_back(std::move(drawn));
      }
    }
  }

  // Vertices within kBorderSnap of the tile's smaller side from its border are moved onto it:
  // drawings stop a rounding short of the border (leaf: 0.024 of 40 units), and their pieces
  // must still meet their counterparts across it.
  void snap_to_border(std::vector<Vec2>& polyline) const {
    const double reach = kBorderSnap * std::min(period_.x(), period_.y());
    for (Vec2& p : polyline) {
      for (int axis = 0; axis < 2; ++axis) {
        if (std::abs(p[axis] - window_.min()[axis]) < reach) p[axis] = window_.min()[axis];
        if (std::abs(p[axis] - window_.max()[axis]) < reach) p[axis] = window_.max()[axis];
      }
    }
  }

  // Pieces of different categories stay apart: the user said they are different kinds.
  void link(std::size_t a, std::size_t b, const Vec2& shift) {
    if (drawables_[subpaths_[a].drawable].category != drawables_[subpaths_[b].drawable].category)
      return;
    links_[a].push_back({b, shift});
    links_[b].push_back({a, -shift});
  }

  void join_within_elements() {
    std::vector<std::optional<std::size_t>> first(scene_.elements.size());
    for (std::size_t i = 0; i < subpaths_.size(); ++i) {
      auto& f = first[drawables_[subpaths_[i].drawable].element];
      if (f) {
        link(*f, i, Vec2::Zero());
      } else {
        f = i;
      }
    }
  }

  static Box2 moved(Box2 box, const Vec2& shift) {
    box.translate(shift);
    return box;
  }

  // Pieces whose outlines meet (segments_meet), the pieces and their copies a period away.
  // Candidate pieces come from a tree of the pieces' boxes (all pairs took minutes on 200,000
  // circles); a piece whose box meets many others' (outlines nested inside each other) is tested
  // through a tree of every outline's segments instead, against the few segments near each of
  // its own.
  void join_crossing_outlines() {
    std::vector<Box2> boxes(subpaths_.size());
    for (std::size_t i = 0; i < subpaths_.size(); ++i) boxes[i] = subpaths_[i].box;
    const BoxTree<2> tree = BoxTree<2>::build(boxes);
    std::vector<std::pair<std::size_t, std::size_t>> near, pairs;  // (j, shift)
    for (std::size_t i = 0; i < subpaths_.size(); ++i) {
      near.clear();
      pairs.clear();
      bool few = true;  // the candidates are few enough to test outline against outline
      for (std::size_t s = 0; s < shifts_.size() && few; ++s) {
        few = tree.for_each_intersecting_while(
            widened(moved(subpaths_[i].box, -shifts_[s]), shifts_[s]), boxes, [&](int found) {
              const auto j = static_cast<std::size_t>(found);
              if (j > i || (j == i && !shifts_[s].isZero())) near.emplace_back(j, s);
              return near.size() <= kDirectPairs;
            });
      }
      if (!few) {
        meeting_segments(i, pairs);
      } else {
        for (const auto& [j, s] : near)
          if (outlines_meet(subpaths_[i], subpaths_[j], shifts_[s])) pairs.emplace_back(j, s);
      }
      std::sort(pairs.begin(), pairs.end());
      pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
      for (const auto& [j, s] : pairs) link(i, j, shifts_[s]);
    }
  }

  // Beyond this many candidate pieces, a piece's segments are looked up in the segment tree.
  static constexpr std::size_t kDirectPairs = 32;

  // A box widened by the ink gap and a rounding slack.
  static Box2 widened(Box2 box, const Vec2& shift) {
    const double slack = kInkGap + 1e-9 * (1.0 + box.sizes().maxCoeff() + shift.norm());
    box.extend(box.min() - Vec2::Constant(slack)).extend(box.max() + Vec2::Constant(slack));
    return box;
  }

  // Whether a's outline meets b's moved by `shift`: each pair of segments whose widened boxes meet.
  static bool outlines_meet(const Subpath& a, const Subpath& b, const Vec2& shift) {
    for (std::size_t k = 0; k < segment_count(a); ++k) {
      const Vec2 &p = a.polyline[k], &q = a.polyline[(k + 1) % a.polyline.size()];
      const Box2 around = widened(Box2(p).extend(q), shift);
      for (std::size_t m = 0; m < segment_count(b); ++m) {
        const Vec2 r = b.polyline[m] + shift, t = b.polyline[(m + 1) % b.polyline.size()] + shift;
        if (around.intersects(Box2(r).extend(t)) && segments_meet(p, q, r, t, kInkGap)) return true;
      }
    }
    return false;
  }

  // The pieces (with their shifts) whose segments meet subpath i's, through the segment tree
  // (built when first needed).
  void meeting_segments(std::size_t i, std::vector<std::pair<std::size_t, std::size_t>>& pairs) {
    if (segment_boxes_.empty()) {
      for (std::size_t j = 0; j < subpaths_.size(); ++j) {
        const std::vector<Vec2>& line = subpaths_[j].polyline;
        for (std::size_t k = 0; k < segment_count(subpaths_[j]); ++k) {
          segment_boxes_.push_back(Box2(line[k]).extend(line[(k + 1) % line.size()]));
          segment_owner_.emplace_back(j, k);
        }
      }
      segment_tree_ = BoxTree<2>::build(segment_boxes_);
    }
    const std::vector<Vec2>& line = subpaths_[i].polyline;
    for (std::size_t k = 0; k < segment_count(subpaths_[i]); ++k) {
      const Vec2 &p = line[k], &q = line[(k + 1) % line.size()];
      for (std::size_t s = 0; s < shifts_.size(); ++s) {
        const Vec2& shift = shifts_[s];
        segment_tree_.for_each_intersecting(
            widened(moved(Box2(p).extend(q), -shift), shift), segment_boxes_, [&](int found) {
              const auto [j, m] = segment_owner_[static_cast<std::size_t>(found)];
              if (!(j > i || (j == i && !shift.isZero()))) return;
              const std::vector<Vec2>& other = subpaths_[j].polyline;
              if (segments_meet(p, q, other[m] + shift, other[(m + 1) % other.size()] + shift,
                                kInkGap))
                pairs.emplace_back(j, s);
            });
      }
    }
  }

  // The segments of a subpath's outline: its closing side included when it is closed.
  static std::size_t segment_count(const Subpath& s) {
    const std::size_t n = s.polyline.size();
    return n < 2 ? 0 : (s.closed ? n : n - 1);
  }

  // A point of the subpath's outline away from its vertices (the midpoint of its longest side):
  // pieces touching at a vertex must not count as one inside the other.
  static Vec2 probe(const Subpath& s) {
    const std::size_t n = s.polyline.size();
    if (n < 2) return s.polyline.front();
    std::size_t longest = 0;
    double length = -1.0;
    for (std::size_t k = 0; k + (s.closed ? 0 : 1) < n; ++k) {
      const double l = (s.polyline[(k + 1) % n] - s.polyline[k]).squaredNorm();
      if (l > length) {
        length = l;
        longest = k;
      }
    }
    return 0.5 * (s.polyline[longest] + s.polyline[(longest + 1) % n]);
  }

  // A subpath inside a drawable's closed subpaths: inside its fill (ink over ink, or a hole of
  // its own drawable) it joins the innermost of them; inside a hole (within the outer contour but
  // not filled) likewise, unless nested pieces stay separate.
  void join_contained() {
    std::vector<Box2> boxes(drawables_.size());
    for (std::size_t d = 0; d < drawables_.size(); ++d) boxes[d] = drawables_[d].box;
    const BoxTree<2> tree = BoxTree<2>::build(boxes);
    // Per drawable, its subpaths' boxes in a tree: a point meets the few boxes around it, not
    // every subpath of a path that draws thousands of dots.
    piece_boxes_.assign(drawables_.size(), {});
    pieces_.clear();
    for (std::size_t d = 0; d < drawables_.size(); ++d) {
      for (std::size_t k : drawables_[d].subpaths) piece_boxes_[d].push_back(subpaths_[k].box);
      pieces_.push_back(BoxTree<2>::build(piece_boxes_[d]));
    }
    chains_.assign(subpaths_.size(), Chain{});
    by_area_.assign(drawables_.size(), {});
    for (std::size_t d = 0; d < drawables_.size(); ++d) {
      for (std::size_t k : drawables_[d].subpaths)
        if (subpaths_[k].closed) by_area_[d].push_back(k);
      std::sort(by_area_[d].begin(), by_area_[d].end(), [this](std::size_t a, std::size_t b) {
        return std::tie(subpaths_[a].area, a) < std::tie(subpaths_[b].area, b);
      });
    }
    std::vector<std::pair<std::size_t, std::size_t>> found;  // (drawable, shift), in order
    for (std::size_t i = 0; i < subpaths_.size(); ++i) {
      const Vec2 p = probe(subpaths_[i]);
      found.clear();
      for (std::size_t s = 0; s < shifts_.size(); ++s) {
        const Vec2 q = p - shifts_[s];
        tree.for_each_intersecting(
            Box2(q, q), boxes, [&](int d) { found.emplace_back(static_cast<std::size_t>(d), s); });
      }
      std::sort(found.begin(), found.end());
      for (const auto& [index, s] : found) {
        const Depth at = depth_at(index, p - shifts_[s], i);
        if (at.depth == 0) continue;
        const Drawn& d = drawables_[index];
        const bool in_fill =
            d.drawable.filled() &&
            (d.drawable.fill_rule == FillRule::evenodd ? at.depth % 2 == 1 : at.winding != 0);
        if (in_fill || !options_.nested_separate) link(i, at.innermost, shifts_[s]);
      }
    }
  }

  // How a point lies in a drawable's closed subpaths larger than subpath `i`: how many hold it,
  // the sum of their winding numbers about it, and the innermost (smallest) of them.
  struct Depth {
    int depth = 0, winding = 0;
    std::size_t innermost = 0;
  };

  // Outlines nested deeper than this at a point are counted along the chain of innermost
  // containers (each container's own depth found once): exact for outlines that do not cross,
  // and linear where outlines nest thousands deep, where testing every container of every
  // subpath is quadratic. Shallower nesting is counted container by container.
  static constexpr std::size_t kChainFrom = 64;

  // The closed subpaths of drawable `d` larger than subpath `i` whose boxes hold `q`, in no
  // particular order.
  std::vector<std::size_t> larger_around(std::size_t d, const Vec2& q, std::size_t i) const {
    std::vector<std::size_t> around;
    pieces_[d].for_each_intersecting(Box2(q, q), piece_boxes_[d], [&](int local) {
      const std::size_t k = drawables_[d].subpaths[static_cast<std::size_t>(local)];
      if (k != i && subpaths_[k].closed && subpaths_[k].area > subpaths_[i].area)
        around.push_back(k);
    });
    return around;
  }

  // The smallest of `candidates` (the first in drawing order among equals) that winds about `q`,
  // or subpaths_.size().
  std::size_t innermost_of(std::vector<std::size_t> candidates, const Vec2& q) const {
    while (!candidates.empty()) {
      const auto smallest = std::min_element(
          candidates.begin(), candidates.end(), [this](std::size_t a, std::size_t b) {
            return std::tie(subpaths_[a].area, a) < std::tie(subpaths_[b].area, b);
          });
      const std::size_t k = *smallest;
      if (winding_number(subpaths_[k].polyline, q) != 0) return k;
      *smallest = candidates.back();
      candidates.pop_back();
    }
    return subpaths_.size();
  }

  // The innermost closed subpath of drawable `d` larger than subpath `i` about `q`, looked for
  // among the kChainFrom next larger ones (by area, then drawing order); nullopt when it is not
  // among them, subpaths_.size() when there is none at all.
  std::optional<std::size_t> near_innermost(std::size_t d, const Vec2& q, std::size_t i) const {
    const std::vector<std::size_t>& order = by_area_[d];
    auto it =
        std::upper_bound(order.begin(), order.end(), subpaths_[i].area,
                         [this](double area, std::size_t k) { return area < subpaths_[k].area; });
    for (std::size_t looked = 0; it != order.end(); ++it, ++looked) {
      if (looked == kChainFrom) return std::nullopt;
      const Subpath& k = subpaths_[*it];
      if (*it != i && k.box.contains(q) && winding_number(k.polyline, q) != 0) return *it;
    }
    return subpaths_.size();
  }

  Depth depth_at(std::size_t d, const Vec2& q, std::size_t i) {
    Depth at;
    at.innermost = subpaths_.size();
    const std::optional<std::size_t> near = near_innermost(d, q, i);
    if (near && *near != subpaths_.size()) {
      const Chain& outer = chain_of(d, *near);
      if (outer.depth + 1 > static_cast<int>(kChainFrom)) {
        at.innermost = *near;
        at.depth = 1 + outer.depth;
        at.winding = winding_number(subpaths_[*near].polyline, q) + outer.winding;
        return at;
      }
    }
    std::vector<std::size_t> around = larger_around(d, q, i);
    std::sort(around.begin(), around.end());  // drawing order: the first of equals is innermost
    for (std::size_t k : around) {
      const int w = winding_number(subpaths_[k].polyline, q);
      if (w == 0) continue;
      ++at.depth;
      at.winding += w;
      if (at.innermost == subpaths_.size() || subpaths_[k].area < subpaths_[at.innermost].area)
        at.innermost = k;
    }
    return at;
  }

  // A closed subpath's own containers in its drawable, at its probe: their count and winding sum
  // along the chain of innermost containers.
  struct Chain {
    bool known = false;
    int depth = 0, winding = 0;
  };

  const Chain& chain_of(std::size_t d, std::size_t m) {
    std::vector<std::size_t> pending = {m};
    while (!pending.empty()) {
      const std::size_t k = pending.back();
      if (chains_[k].known) {
        pending.pop_back();
        continue;
      }
      const Vec2 q = probe(subpaths_[k]);
      const std::optional<std::size_t> near = near_innermost(d, q, k);
      const std::size_t parent = near ? *near : innermost_of(larger_around(d, q, k), q);
      if (parent != subpaths_.size() && !chains_[parent].known) {
        pending.push_back(parent);  // its chain first
        continue;
      }
      Chain& chain = chains_[k];
      chain.known = true;
      if (parent != subpaths_.size()) {
        chain.depth = 1 + chains_[parent].depth;
        chain.winding = winding_number(subpaths_[parent].polyline, q) + chains_[parent].winding;
      }
      pending.pop_back();
    }
    return chains_[m];
  }

  // Components of the links, each subpath at the offset its links give it; one element each.
  VisualElements assemble() {
    VisualElements result;
    result.scene.dimension = 2;
    result.scene.window = scene_.window;
    result.scene.units = scene_.units;
    result.scene.categories = scene_.categories;
    result.subpaths = subpaths_.size();
    std::vector<bool> seen(subpaths_.size(), false);
    std::vector<Vec2> offset(subpaths_.size(), Vec2::Zero());
    bool wraps = false;
    for (std::size_t start = 0; start < subpaths_.size(); ++start) {
      if (seen[start]) continue;
      std::vector<std::size_t> members;
      std::deque<std::size_t> queue{start};
      seen[start] = true;
      while (!queue.empty()) {
        const std::size_t i = queue.front();
        queue.pop_front();
        members.push_back(i);
        for (const Link& l : links_[i]) {
          const Vec2 at = offset[i] + l.shift;
          if (!seen[l.to]) {
            seen[l.to] = true;
            offset[l.to] = at;
            queue.push_back(l.to);
          } else if ((offset[l.to] - at).norm() > 1e-9 * period_.norm()) {
            wraps = true;  // the piece meets itself a period away: a motif, not an element
          }
        }
      }
      std::sort(members.begin(), members.end());
      add_element(result.scene, members, offset);
    }
    if (wraps) {
      result.notes.push_back(
          "a piece of ink wraps around the tile (it meets its own copy a period away): it is a "
          "continuous motif, kept as one element");
    }
    return result;
  }

  void add_element(Scene& out, const std::vector<std::size_t>& members,
                   const std::vector<Vec2>& offset) const {
    PlanarShape shape;
    std::vector<std::size_t> part_of(drawables_.size(), std::numeric_limits<std::size_t>::max());
    for (std::size_t i : members) {
      const Subpath& s = subpaths_[i];
      std::size_t& part = part_of[s.drawable];
      if (part == std::numeric_limits<std::size_t>::max()) {
        part = shape.parts.size();
        shape.parts.push_back(drawables_[s.drawable].drawable);
      }
      Path2 path = s.path;
      translate(path, offset[i]);
      shape.parts[part].paths.push_back(std::move(path));
    }
    const Drawn& first = drawables_[subpaths_[members.front()].drawable];
    const std::size_t index =
        geometry::add_element(out, Shape{std::move(shape), first.name}, first.category);
    if (!options_.tile) return;
    // The reference position back in the tile.
    Vec3& position = out.elements[index].position;
    for (int axis = 0; axis < 2; ++axis) {
      const double low = window_.min()[axis];
      position[axis] =
          low +
          std::fmod(std::fmod(position[axis] - low, period_[axis]) + period_[axis], period_[axis]);
      if (position[axis] >= window_.max()[axis]) position[axis] = low;
    }
  }

  const Scene& scene_;
  const VisualOptions& options_;
  Vec2 period_;
  Box2 window_;
  std::vector<Vec2> shifts_;
  std::vector<Drawn> drawables_;
  std::vector<Subpath> subpaths_;
  std::vector<std::vector<Link>> links_;
  std::vector<Box2> segment_boxes_;  // every outline's segments, when a piece needs them
  std::vector<std::pair<std::size_t, std::size_t>> segment_owner_;  // their subpath, first point
  BoxTree<2> segment_tree_;
  std::vector<std::vector<Box2>> piece_boxes_;     // per drawable: its subpaths' boxes
  std::vector<BoxTree<2>> pieces_;                 // per drawable: a tree of them
  std::vector<Chain> chains_;                      // per subpath, found when first needed
  std::vector<std::vector<std::size_t>> by_area_;  // per drawable: closed subpaths by area
};

}  // namespace

VisualElements visual_elements(const Scene& scene, const VisualOptions& options) {
  return Grouping(scene, options).run();
}

}  // namespace shapeproc::geometry
