#include "libshapeproc/methods/davison2018/growth_state.hpp"

#include <algorithm>

#include "libshapeproc/geometry/overlap_depth.hpp"
#include "libshapeproc/methods/common/neighbourhood_search.hpp"

namespace shapeproc::methods {

namespace {

constexpr double kTouching = 1e-9;  // relative slack of "circles touch"

double largest(const std::vector<double>& values) {
  double m = 0.0;
  for (const double v : values) m = std::max(m, v);
  return m;
}

}  // namespace

GrowthState::GrowthState(const GrowthExemplar& exemplar, const geometry::Domain& domain)
    : exemplar_(exemplar),
      domain_(domain),
      largest_radius_(largest(exemplar.radius)),
      reach_(std::max(
          {largest(exemplar.reach), 2.0 * largest_radius_, 2.0 * largest(exemplar.shape_radius)})),
      contact_(std::max(2.0 * largest_radius_, 2.0 * largest(exemplar.shape_radius))),
      elements_(domain.box(), domain.dimension(), reach_, domain.periodic()),
      // No finer than a quarter neighbourhood radius: tiny bounding radii must not make a 3D grid
      // of 256³ cells.
      contacts_(domain.box(), domain.dimension(), std::max(contact_, 0.25 * reach_),
                domain.periodic()),
      // Free-space points are asked for at contact distance (on_free_point, consume), and only
      // the horizon's pruning asks farther.
      free_(domain.box(), domain.dimension(), std::max(contact_, 0.25 * reach_),
            domain.periodic()) {}

bool GrowthState::in_domain(const Vec3& p) const { return inside(domain_, p) >= 0.5; }

bool GrowthState::overlaps(const Vec3& p, double radius, int skip) const {
  return contacts_.any_candidate(p, [&](int o) {
    if (o == skip) return false;
    // Circles that touch do not overlap: bounding radii are half the nearest distance, so that
    // an exemplar's nearest pairs touch exactly, and rounding must not part them.
    const double reach =
        (radius + exemplar_.radius[static_cast<std::size_t>(source(o))]) * (1.0 - kTouching);
    return domain_.minimum_image(position(o) - p).squaredNorm() < reach * reach;
  });
}

bool GrowthState::collides(int source, const Vec3& p, int skip) const {
  if (!exemplar_.exact)
    return overlaps(p, exemplar_.radius[static_cast<std::size_t>(source)], skip);
  const auto& elements = exemplar_.em.scene.elements;
  const auto shape_of = [&](int sample) {
    const int element = exemplar_.em.samples.element[static_cast<std::size_t>(sample)];
    return static_cast<std::size_t>(elements[static_cast<std::size_t>(element)].shape);
  };
  const std::size_t shape = shape_of(source);
  return contacts_.any_candidate(p, [&](int o) {
    if (o == skip) return false;
    const auto other =
        static_cast<std::size_t>(elements[static_cast<std::size_t>(this->source(o))].shape);
    const Vec3 offset = domain_.minimum_image(position(o) - p);
    const double reach = exemplar_.shape_radius[shape] + exemplar_.shape_radius[other];
    if (offset.squaredNorm() >= reach * reach) return false;
    return domain_.dimension() == 3
               ? geometry::overlap_depth(exemplar_.proxy3[shape], exemplar_.proxy3[other], offset,
                                         true) > 0
               : geometry::overlap_depth(exemplar_.proxy2[shape], exemplar_.proxy2[other],
                                         geometry::Vec2(offset.x(), offset.y()), true) > 0;
  });
}

bool GrowthState::on_free_point(const Vec3& p, double radius) const {
  return free_.any_candidate(p, [&](int i) {
    const FreePoint& v = points_[static_cast<std::size_t>(i)];
    return v.alive && domain_.minimum_image(v.position - p).squaredNorm() <
                          (v.radius + radius) * (v.radius + radius);
  });
}

bool GrowthState::free_point_within(const Vec3& p, double distance) const {
  return free_.any_candidate_within(p, distance, [&](int i) {
    const FreePoint& v = points_[static_cast<std::size_t>(i)];
    return v.alive && domain_.minimum_image(v.position - p).squaredNorm() < distance * distance;
  });
}

int GrowthState::add(int source, const Vec3& p) {
  const int e = static_cast<int>(position_.size());
  position_.push_back(domain_.wrap(p));
  source_.push_back(source);
  match_.push_back(source);
  owned_.emplace_back();
  elements_.insert(e, position_.back());
  contacts_.insert(e, position_.back());
  consume_free_points(e);
  add_free_points(e);
  return e;
}

void GrowthState::move(int e, const Vec3& p) {
  const auto i = static_cast<std::size_t>(e);
  elements_.remove(e, position_[i]);
  contacts_.remove(e, position_[i]);
  position_[i] = domain_.wrap(p);
  elements_.insert(e, position_[i]);
  contacts_.insert(e, position_[i]);
  // A point already covered may have lent its slot to another element's.
  for (const int v : owned_[i])
    if (points_[static_cast<std::size_t>(v)].owner == e) kill(static_cast<std::size_t>(v));
  owned_[i].clear();
  consume_free_points(e);
  add_free_points(e);
}

void GrowthState::kill(std::size_t point) {
  if (!points_[point].alive) return;
  points_[point].alive = false;
  --alive_;
  free_.remove(static_cast<int>(point), points_[point].position);
  unused_.push_back(static_cast<int>(point));
}

void GrowthState::add_free_points(int e) {
  const auto i = static_cast<std::size_t>(e);
  const std::vector<FreeSpaceVector>& vectors = exemplar_.free[static_cast<std::size_t>(source(e))];
  if (vectors.empty()) return;
  // The elements that could overlap one of e's points, found once as offsets from e (not one
  // grid walk per point): those within the farthest point's reach of e.
  double far = 0.0;
  for (const FreeSpaceVector& v : vectors) far = std::max(far, v.offset.norm() + v.radius);
  far += largest_radius_;
  near_.clear();
  contacts_.for_each_candidate_within(position_[i], far, [&](int o) {
    const Vec3 offset = domain_.minimum_image(position(o) - position_[i]);
    if (offset.squaredNorm() < far * far)
      near_.push_back({offset, exemplar_.radius[static_cast<std::size_t>(source(o))]});
  });
  // Offsets between a point and those elements are under 2 far; when that is within half of
  // every period, each is its own nearest image and the test below needs no minimum image.
  bool plain = true;
  for (int axis = 0; axis < 3; ++axis) {
    const double period = domain_.period()[axis];
    if (period > 0 && !(2.0 * far < 0.5 * period)) plain = false;
  }
  for (const FreeSpaceVector& v : vectors) {
    const Vec3 q = domain_.wrap(position_[i] + v.offset);
    if (!in_domain(q)) continue;
    // As overlaps(q, v.radius), over the elements found.
    bool covered = false;
    for (const Nearby& n : near_) {
      const double reach = (v.radius + n.radius) * (1.0 - kTouching);
      const Vec3 d = n.offset - v.offset;
      covered |= (plain ? d : domain_.minimum_image(d)).squaredNorm() < reach * reach;
    }
    if (covered) continue;
    int id = static_cast<int>(points_.size());
    if (!unused_.empty()) {  // a dead point's slot
      id = unused_.back();
      unused_.pop_back();
      points_[static_cast<std::size_t>(id)] = {q, v.radius, e, true};
    } else {
      points_.push_back({q, v.radius, e, true});
    }
    ++alive_;
    free_.insert(id, q);
    owned_[i].push_back(id);
  }
}

void GrowthState::consume_free_points(int e) {
  const Vec3& p = position(e);
  const double r = exemplar_.radius[static_cast<std::size_t>(source(e))];
  std::vector<int> covered;  // killed after the walk, which removes them from the grid
  free_.for_each_candidate(p, [&](int id) {
    const FreePoint& v = points_[static_cast<std::size_t>(id)];
    if (v.alive &&
        domain_.minimum_image(v.position - p).squaredNorm() < (v.radius + r) * (v.radius + r))
      covered.push_back(id);
  });
  for (const int id : covered) kill(static_cast<std::size_t>(id));
}

geometry::Neighbourhood GrowthState::neighbourhood(int e) const {
  geometry::Neighbourhood out;
  const double r2 = exemplar_.reach_of(source(e)) * exemplar_.reach_of(source(e));
  elements_.for_each_candidate(position(e), [&](int o) {
    if (o == e) return;
    const Vec3 offset = domain_.minimum_image(position(o) - position(e));
    if (offset.squaredNorm() >= r2) return;
    const auto s = static_cast<std::size_t>(source(o));
    out.push_back({offset, exemplar_.em.samples.key[s], o, exemplar_.em.sample_attribute[s]});
  });
  std::sort(out.begin(), out.end(), [](const geometry::Neighbour& a, const geometry::Neighbour& b) {
    return a.element < b.element;
  });
  return out;
}

std::size_t GrowthState::count_within(const Vec3& p, double distance, std::size_t enough) const {
  std::size_t n = 0;
  if (enough == 0) return 0;
  elements_.any_candidate(p, [&](int o) {
    if (domain_.minimum_image(position(o) - p).squaredNorm() < distance * distance) ++n;
    return n >= enough;
  });
  return n;
}

std::vector<int> GrowthState::elements_within(const Vec3& p, double distance) const {
  std::vector<int> out;
  elements_.for_each_candidate(p, [&](int o) {
    if (domain_.minimum_image(position(o) - p).squaredNorm() < distance * distance)
      out.push_back(o);
  });
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace shapeproc::methods
