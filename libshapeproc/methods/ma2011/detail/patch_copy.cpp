#include "libshapeproc/methods/ma2011/detail/patch_copy.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <utility>

#include "libshapeproc/geometry/neighbour_grid.hpp"
#include "libshapeproc/methods/common/neighbourhood_search.hpp"

namespace shapeproc::methods {

namespace {

// One patch's elements placed in a cell: (exemplar element, output position).
using Placement = std::vector<std::pair<int, Vec3>>;

// The elements of the exemplar patch at `origin` (extent as the cell's), moved to the cell at
// `lo` and turned by `radians` about its centre; those outside the domain are left out.
Placement patch_at(const EmExemplar& exemplar, const geometry::Domain& domain, const Vec3& origin,
                   const Vec3& lo, const Vec3& extent, double radians) {
  const int dim = domain.dimension();
  const Vec3 period = exemplar.scene.window.sizes();
  const bool wraps = exemplar.boundary == geometry::Boundary::torus;
  const Vec3 centre = lo + 0.5 * extent;
  Placement out;
  for (std::size_t e = 0; e < exemplar.scene.elements.size(); ++e) {
    // Every image of the element inside the patch (one on an open exemplar).
    std::vector<Vec3> images = {exemplar.scene.elements[e].position - origin};
    for (int a = 0; a < dim && wraps; ++a) {
      std::vector<Vec3> more;
      for (Vec3 p : images) {
        p[a] -= period[a] * std::floor(p[a] / period[a]);
        for (; p[a] < extent[a]; p[a] += period[a]) more.push_back(p);
      }
      images = std::move(more);
    }
    for (const Vec3& p : images) {
      bool in_patch = true;
      for (int a = 0; a < dim; ++a) in_patch = in_patch && p[a] >= 0.0 && p[a] < extent[a];
      if (!in_patch) continue;
      const Vec3 position = domain.wrap(centre + turn_about_z(lo + p - centre, radians));
      if (inside(domain, position) >= 0.5) out.emplace_back(static_cast<int>(e), position);
    }
  }
  return out;
}

// Whether exemplar sample `sample` could have a neighbour at `offset` (exemplar frame): always on
// a torus; in an open exemplar, only where the offset stays inside its window. Eq. 1 between an
// output neighbourhood and an exemplar one truncated by the window's edge judges only what the
// exemplar saw.
bool visible(const EmExemplar& exemplar, std::size_t sample, const Vec3& offset) {
  if (exemplar.boundary == geometry::Boundary::torus) return true;
  const Vec3 p = exemplar.samples.positions[sample] + offset;
  const geometry::Box3& window = exemplar.scene.window;
  for (int a = 0; a < exemplar.scene.dimension; ++a)
    if (p[a] < window.min()[a] || p[a] > window.max()[a]) return false;
  return true;
}

// Offsets at which the exemplar shows a neighbour sample of another element, by the neighbour's
// key, pooled over all its samples' neighbourhoods (radius r).
using PooledOffsets = std::vector<std::vector<Vec3>>;

PooledOffsets pooled_sample_offsets(const EmExemplar& exemplar) {
  PooledOffsets out;
  const std::vector<int>& element = exemplar.samples.element;
  for (std::size_t sample = 0; sample < exemplar.near.size(); ++sample) {
    for (const geometry::Neighbour& n : exemplar.near[sample]) {
      // Not the sample's own element: its other samples are no neighbour an output sample has.
      if (n.key < 0 || element[static_cast<std::size_t>(n.element)] == element[sample]) continue;
      const auto key = static_cast<std::size_t>(n.key);
      if (out.size() <= key) out.resize(key + 1);
      out[key].push_back(n.offset);
    }
  }
  return out;
}

// Eq. 1's cost for an output neighbour of `key` at `offset` that the partner's own neighbourhood
// cannot show: its squared distance to the nearest pooled offset of that key, at most r².
double pooled_cost(const PooledOffsets& pooled, int key, const Vec3& offset, double r2) {
  double best = r2;
  if (key >= 0 && static_cast<std::size_t>(key) < pooled.size())
    for (const Vec3& v : pooled[static_cast<std::size_t>(key)])
      best = std::min(best, (v - offset).squaredNorm());
  return best;
}

// The placement moved by `offset` (wrapped), without the elements that leave the domain.
Placement translated(Placement patch, const geometry::Domain& domain, const Vec3& offset) {
  for (auto& [element, position] : patch) position = domain.wrap(position + offset);
  patch.erase(
      std::remove_if(patch.begin(), patch.end(),
                     [&](const std::pair<int, Vec3>& e) { return inside(domain, e.second) < 0.5; }),
      patch.end());
  return patch;
}

// Every offset from an exemplar element to a neighbour within 1.5 mean nearest distances: what
// the exemplar's elements see around them, pooled over the whole exemplar.
std::vector<Vec3> pooled_offsets(const EmExemplar& exemplar) {
  const geometry::Domain domain(exemplar.scene.window, exemplar.scene.dimension, exemplar.boundary);
  const geometry::NeighbourhoodIndex index(exemplar.scene.elements, domain, 1.5 * exemplar.spacing);
  std::vector<Vec3> out;
  for (std::size_t e = 0; e < exemplar.scene.elements.size(); ++e)
    for (const geometry::Neighbour& n : index.of(e)) out.push_back(n.offset);
  return out;
}

// How badly a patch fits the samples already placed: eq. 1 over its samples' neighbourhoods
// made of placed samples only (within a patch the exemplar's own arrangement holds), plus r² for
// every exemplar neighbour that would fall where elements are already placed but finds no
// partner there (eq. 1 alone lets a seam open a gap for free); the same from the other side for
// the placed samples within r of the cell (`bordering`): eq. 1 over their neighbourhoods among
// the patch's samples, plus r² for every neighbour their sources have inside the cell (`in_cell`)
// that the patch leaves without a partner, so that sparse or empty patches do not win; and the
// translation of the patch that best closes the seam (the mean move its paired samples ask for).
// With `pooled` (an open exemplar whose window leaves the patch's origin less than r of room along
// some axis, so that seam samples' exemplar neighbourhoods are cut by its edge), a neighbour the
// partner's window cannot show (`visible`) is judged by the pooled offsets (`pooled_cost`) instead
// of eq. 1's pairing with a neighbourhood cut short there.
struct Seam {
  double cost = 0.0;
  Vec3 shift = Vec3::Zero();
};

Seam seam_cost(const EmExemplar& exemplar, const geometry::Domain& domain,
               const InitialOutput& placed, const geometry::NeighbourGrid& grid,
               const Placement& patch, double radians, double alpha,
               const std::function<bool(const Vec3&)>& filled, const std::vector<int>& bordering,
               const std::function<bool(const Vec3&)>& in_cell, const PooledOffsets* pooled) {
  const ElementSamples& samples = placed.output.samples;
  const double r2 = exemplar.radius * exemplar.radius;
  Seam seam;
  int pairs = 0;
  geometry::Neighbourhood hood;
  std::vector<std::pair<Vec3, std::size_t>> patch_samples;  // position, exemplar sample
  for (const auto& [element, position] : patch) {
    const int first = exemplar.samples.first[static_cast<std::size_t>(element)];
    const int count = exemplar.samples.count_of(element);
    for (int k = 0; k < count; ++k) {
      const auto source = static_cast<std::size_t>(first + k);
      const Vec3 at = domain.wrap(
          position +
          turn_about_z(exemplar.samples.positions[source] -
                           exemplar.scene.elements[static_cast<std::size_t>(element)].position,
                       radians));
      patch_samples.emplace_back(at, source);
      hood.clear();
      grid.for_each_candidate(at, [&](int id) {
        const auto s = static_cast<std::size_t>(id);
        const Vec3 t = domain.minimum_image(samples.positions[s] - at);
        const Vec3 seen = turn_about_z(t, -radians);
        if (t.norm() >= exemplar.radius) return;
        if (!pooled || visible(exemplar, source, seen))
          hood.push_back({seen, samples.key[s], id, placed.output.attribute[s]});
        else
          seam.cost += pooled_cost(*pooled, samples.key[s], seen, r2);
      });
      const geometry::PairingNeighbourhood& partner = exemplar.wide[source];
      seam.cost += geometry::neighbourhood_distance(hood, partner, exemplar.radius, alpha);
      std::vector<char> paired(partner.size(), 0);
      for (const auto& [a, b] : geometry::match_neighbourhoods(hood, partner, exemplar.radius)) {
        seam.shift +=
            hood[static_cast<std::size_t>(a)].offset - partner[static_cast<std::size_t>(b)].offset;
        paired[static_cast<std::size_t>(b)] = 1;
        ++pairs;
      }
      for (std::size_t b = 0; b < partner.size(); ++b) {
        if (paired[b] || partner[b].offset.norm() >= exemplar.radius) continue;
        if (filled(domain.wrap(at + turn_about_z(partner[b].offset, radians))))
          seam.cost += exemplar.radius * exemplar.radius;
      }
    }
  }
  // The placed side.
  geometry::Neighbourhood expected;
  for (const int id : bordering) {
    const auto s = static_cast<std::size_t>(id);
    const Vec3 at = samples.positions[s];
    hood.clear();
    const auto from = static_cast<std::size_t>(placed.copied_from[s]);
    for (std::size_t i = 0; i < patch_samples.size(); ++i) {
      const Vec3 t = domain.minimum_image(patch_samples[i].first - at);
      const std::size_t e = patch_samples[i].second;
      const Vec3 seen = turn_about_z(t, -radians);
      if (t.norm() >= exemplar.radius) continue;
      if (!pooled || visible(exemplar, from, seen))
        hood.push_back(
            {seen, exemplar.samples.key[e], static_cast<int>(i), exemplar.sample_attribute[e]});
      else
        seam.cost += pooled_cost(*pooled, exemplar.samples.key[e], seen, r2);
    }
    expected.clear();
    for (const geometry::Neighbour& n : exemplar.near[from])
      if (in_cell(domain.wrap(at + turn_about_z(n.offset, radians)))) expected.push_back(n);
    const auto matched = geometry::match_neighbourhoods(hood, expected, exemplar.radius);
    for (const auto& [a, b] : matched)
      seam.cost +=
          geometry::pair_cost(hood[static_cast<std::size_t>(a)],
                              expected[static_cast<std::size_t>(b)], exemplar.radius, alpha);
    seam.cost += r2 * static_cast<double>(hood.size() + expected.size() - 2 * matched.size());
  }
  if (pairs > 0) seam.shift = turn_about_z(seam.shift / pairs, radians);
  return seam;
}

// The output's cells filled one by one (patch_copy): the grids of what is placed, and each filled
// cell's translation from the exemplar.
class PatchCopy {
 public:
  PatchCopy(const EmExemplar& exemplar, const geometry::Domain& domain, double alpha,
            InitialOutput& out, bool diverse)
      : exemplar_(exemplar),
        domain_(domain),
        alpha_(alpha),
        out_(out),
        diverse_(diverse),
        dim_(domain.dimension()),
        window_min_(exemplar.scene.window.min()),
        period_(exemplar.scene.window.sizes()),
        wraps_(exemplar.boundary == geometry::Boundary::torus),
        grid_(domain.box(), dim_, exemplar.radius, domain.periodic()),
        gap_(0.5 * smallest_gap(exemplar)),
        elements_(domain.box(), dim_, exemplar.radius, domain.periodic()) {
    double room = 0.0;  // the most an open exemplar's patch origin can move along an axis
    for (int a = 0; a < dim_; ++a) {
      cell_[a] = wraps_ ? 2.0 * exemplar.radius : std::min(2.0 * exemplar.radius, period_[a]);
      room = std::max(room, period_[a] - cell_[a]);
    }
    // (A lattice window of whole spacings leaves exactly one spacing of room: not cramped.)
    cramped_ = !wraps_ && room < (1.0 - 1e-6) * exemplar.spacing;
    // Otherwise the origin gets at least two spacings of room where the window allows: a structure
    // that repeats every two spacings (two kinds alternating) then has every phase within reach.
    for (int a = 0; a < dim_; ++a) {
      if (!wraps_ && !cramped_ && period_[a] >= 4.0 * exemplar.spacing)
        cell_[a] = std::min(cell_[a], period_[a] - 2.0 * exemplar.spacing);
      counts_[a] = std::max(1, static_cast<int>(std::ceil(domain.sizes()[a] / cell_[a] - 1e-9)));
    }
    double least_room = std::numeric_limits<double>::infinity();
    for (int a = 0; a < dim_; ++a) least_room = std::min(least_room, period_[a] - cell_[a]);
    cut_ = !wraps_ && least_room < exemplar.radius;
    if (cut_) pooled_ = pooled_sample_offsets(exemplar);
    if (cramped_) offsets_ = pooled_offsets(exemplar);
  }

  const Eigen::Vector3i& counts() const { return counts_; }

  // Fills the cell at `at` with the best of the candidate patches.
  void fill(const Eigen::Vector3i& at, const OrientationField& orientation, core::Random& random);

 private:
  // The patch without its elements nearer to a placed one than half the exemplar's smallest gap
  // (the patches' seams overlap when they are moved).
  Placement uncrowded(Placement patch) const;
  // Whether a cell's translation continues a neighbouring cell's (the diversity control).
  bool continues_neighbour(const Eigen::Vector3i& at, const Vec3& shift) const;
  // The output samples within the exemplar's radius of the cell.
  std::vector<int> bordering(const Vec3& lo, const Vec3& extent) const;
  // Places the chosen patch.
  void place(const Placement& patch, double radians);
  // The move that puts the patch's elements near placed ones where the exemplar's pooled element
  // offsets say they belong: the mean, over the patch elements within 1.5 mean nearest distances
  // of a placed element, of the gap between their offset from the nearest placed element and the
  // pooled offset nearest to it (zero when none is near).
  Vec3 seam_step(const Placement& patch, double radians) const;
  // The seam cost of a placement in this cell (seam_cost).
  Seam seam_of(const Placement& patch, double radians,
               const std::function<bool(const Vec3&)>& filled, const std::vector<int>& near,
               const std::function<bool(const Vec3&)>& in_cell) const {
    return seam_cost(exemplar_, domain_, out_, grid_, patch, radians, alpha_, filled, near, in_cell,
                     cut_ ? &pooled_ : nullptr);
  }

  const EmExemplar& exemplar_;
  const geometry::Domain& domain_;
  const double alpha_;
  InitialOutput& out_;
  const bool diverse_;
  const int dim_;
  const Vec3 window_min_, period_;
  const bool wraps_;
  Vec3 cell_ = Vec3::Ones();
  Eigen::Vector3i counts_ = Eigen::Vector3i::Ones();
  geometry::NeighbourGrid grid_;  // the output's samples
  const double gap_;
  geometry::NeighbourGrid elements_;  // the elements placed
  std::vector<Vec3> placed_;
  std::vector<std::pair<Eigen::Vector3i, Vec3>> shifts_;
  // An open exemplar that leaves the patch's origin less than a mean spacing of room along every
  // axis: every seam then joins the exemplar's own edges, which no exemplar neighbourhood
  // crosses, and no choice of origin can bring a seam into phase. Its seams are judged with the
  // pooled offsets, of samples (seam_cost) and of elements (seam_step).
  bool cramped_ = false;
  // An open exemplar that leaves the patch's origin less than r of room along some axis: seam
  // samples' exemplar neighbourhoods are cut by its window, and their neighbours beyond it are
  // judged by the pooled sample offsets (seam_cost).
  bool cut_ = false;
  PooledOffsets pooled_;
  std::vector<Vec3> offsets_;
};

Placement PatchCopy::uncrowded(Placement patch) const {
  patch.erase(
      std::remove_if(
          patch.begin(), patch.end(),
          [&](const std::pair<int, Vec3>& e) {
            bool crowded = false;
            elements_.for_each_candidate(e.second, [&](int id) {
              crowded =
                  crowded ||
                  domain_.minimum_image(placed_[static_cast<std::size_t>(id)] - e.second).norm() <
                      gap_;
            });
            return crowded;
          }),
      patch.end());
  return patch;
}

bool PatchCopy::continues_neighbour(const Eigen::Vector3i& at, const Vec3& shift) const {
  if (!diverse_) return false;
  for (const auto& [other, s] : shifts_) {
    if ((other - at).cwiseAbs().maxCoeff() > 1) continue;
    if (geometry::minimum_image(s - shift, exemplar_.tile_period).norm() < 0.25 * exemplar_.spacing)
      return true;
  }
  return false;
}

std::vector<int> PatchCopy::bordering(const Vec3& lo, const Vec3& extent) const {
  std::vector<int> out;
  const Vec3 centre = lo + 0.5 * extent;
  for (std::size_t s = 0; s < out_.output.samples.size(); ++s) {
    const Vec3 t = domain_.minimum_image(out_.output.samples.positions[s] - centre);
    bool near_cell = true;
    for (int a = 0; a < dim_; ++a)
      near_cell = near_cell && std::abs(t[a]) < 0.5 * extent[a] + exemplar_.radius;
    if (near_cell) out.push_back(static_cast<int>(s));
  }
  return out;
}

Vec3 PatchCopy::seam_step(const Placement& patch, double radians) const {
  Vec3 sum = Vec3::Zero();
  int count = 0;
  const double near = 1.5 * exemplar_.spacing;
  for (const auto& placement : patch) {
    const Vec3& position = placement.second;  // (a lambda may not capture a structured binding)
    Vec3 gap = Vec3::Zero();
    double nearest = near;
    elements_.for_each_candidate(position, [&](int id) {
      const Vec3 d = domain_.minimum_image(position - placed_[static_cast<std::size_t>(id)]);
      if (d.norm() < nearest) {
        nearest = d.norm();
        gap = d;
      }
    });
    if (nearest >= near || offsets_.empty()) continue;
    const Vec3 seen = turn_about_z(gap, -radians);  // in the exemplar's frame
    const Vec3* best = &offsets_.front();
    for (const Vec3& v : offsets_)
      if ((v - seen).squaredNorm() < (*best - seen).squaredNorm()) best = &v;
    sum += turn_about_z(*best - seen, radians);
    ++count;
  }
  return count > 0 ? Vec3(sum / count) : Vec3::Zero();
}

void PatchCopy::place(const Placement& patch, double radians) {
  for (const auto& [element, position] : patch) {
    elements_.insert(static_cast<int>(placed_.size()), position);
    placed_.push_back(position);
    const std::size_t before = out_.output.samples.size();
    out_.add(exemplar_, element, position, radians);
    for (std::size_t s = before; s < out_.output.samples.size(); ++s)
      grid_.insert(static_cast<int>(s), domain_.wrap(out_.output.samples.positions[s]));
  }
}

void PatchCopy::fill(const Eigen::Vector3i& at, const OrientationField& orientation,
                     core::Random& random) {
  Vec3 lo = Vec3::Zero(), extent = Vec3::Zero();
  for (int a = 0; a < dim_; ++a) {
    lo[a] = domain_.box().min()[a] + at[a] * cell_[a];
    extent[a] = std::min(cell_[a], domain_.box().max()[a] - lo[a]);
  }
  const double radians = orientation.angle_at(lo + 0.5 * extent);
  // Whether a place lies in a cell filled before this one.
  const int current = (at.z() * counts_.y() + at.y()) * counts_.x() + at.x();
  const auto filled = [&](const Vec3& p) {
    if (!domain_.contains(p)) return false;
    int index = 0;
    for (int a = dim_ - 1; a >= 0; --a) {
      const int c =
          std::clamp(static_cast<int>(std::floor((p[a] - domain_.box().min()[a]) / cell_[a])), 0,
                     counts_[a] - 1);
      index = index * counts_[a] + c;
    }
    return index < current;
  };
  // Whether a place lies in this cell.
  const auto in_cell = [&](const Vec3& p) {
    for (int a = 0; a < dim_; ++a) {
      double t = p[a] - lo[a];
      if (domain_.periodic()) {
        const double side = domain_.sizes()[a];
        t -= side * std::floor(t / side);
      }
      if (!(t >= 0.0 && t < extent[a])) return false;
    }
    return true;
  };
  const std::vector<int> near = bordering(lo, extent);
  Placement best;
  double best_cost = std::numeric_limits<double>::infinity();
  Vec3 best_shift = Vec3::Zero();
  const bool first_cell = out_.output.elements() == 0;
  for (int c = 0; c < (first_cell ? 1 : kPatchCandidates); ++c) {
    Vec3 origin = Vec3::Zero();
    for (int a = 0; a < dim_; ++a)
      origin[a] = wraps_ ? window_min_[a] + random.uniform() * period_[a]
                         : window_min_[a] + random.uniform() * std::max(0.0, period_[a] - cell_[a]);
    const Placement drawn = patch_at(exemplar_, domain_, origin, lo, extent, radians);
    Placement patch = uncrowded(drawn);
    if (first_cell) {
      best = std::move(patch);
      best_shift = lo - origin;
      break;
    }
    // The patch as drawn, and moved to close its seam.
    const Seam seam = seam_of(patch, radians, filled, near, in_cell);
    // The same cell filled from the exemplar patch moved the other way, so that its elements
    // move by the shift and the cell stays covered.
    Vec3 moved_origin = origin - turn_about_z(seam.shift, -radians);
    for (int a = 0; a < dim_ && !wraps_; ++a)
      moved_origin[a] = std::clamp(moved_origin[a], window_min_[a],
                                   window_min_[a] + std::max(0.0, period_[a] - cell_[a]));
    Placement moved = uncrowded(patch_at(exemplar_, domain_, moved_origin, lo, extent, radians));
    const double moved_cost = seam_of(moved, radians, filled, near, in_cell).cost;
    // A cramped exemplar's patch, as drawn, moved in the output by what the pooled offsets ask
    // (its origin has no room to move that far).
    const Vec3 step = cramped_ ? seam_step(drawn, radians) : Vec3::Zero();
    Placement stepped;
    double stepped_cost = std::numeric_limits<double>::infinity();
    if (step.squaredNorm() > 0.0) {
      stepped = uncrowded(translated(drawn, domain_, step));
      stepped_cost = seam_of(stepped, radians, filled, near, in_cell).cost;
    }
    if (seam.cost < best_cost && !continues_neighbour(at, lo - origin)) {
      best_cost = seam.cost;
      best = std::move(patch);
      best_shift = lo - origin;
    }
    if (moved_cost < best_cost && !continues_neighbour(at, lo - moved_origin)) {
      best_cost = moved_cost;
      best = std::move(moved);
      best_shift = lo - moved_origin;
    }
    if (stepped_cost < best_cost && !continues_neighbour(at, lo - origin + step)) {
      best_cost = stepped_cost;
      best = std::move(stepped);
      best_shift = lo - origin + step;
    }
  }
  shifts_.emplace_back(at, best_shift);
  place(best, radians);
}

}  // namespace

void patch_copy(const EmExemplar& exemplar, const geometry::Domain& domain,
                const OrientationField& orientation, double alpha, core::Random& random,
                InitialOutput& out, bool diverse) {
  PatchCopy copy(exemplar, domain, alpha, out, diverse);
  const Eigen::Vector3i& counts = copy.counts();
  for (int k = 0; k < counts.z(); ++k)
    for (int j = 0; j < counts.y(); ++j)
      for (int i = 0; i < counts.x(); ++i) copy.fill(Eigen::Vector3i(i, j, k), orientation, random);
}

}  // namespace shapeproc::methods
