#include "libshapeproc/methods/ma2011/patch_copy.hpp"

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

// How badly a patch fits the samples already placed: eq. 1 over its samples' neighbourhoods
// made of placed samples only (within a patch the exemplar's own arrangement holds), plus r² for
// every exemplar neighbour that would fall where elements are already placed but finds no
// partner there (eq. 1 alone lets a seam open a gap for free); the same from the other side for
// the placed samples within r of the cell (`bordering`): eq. 1 over their neighbourhoods among
// the patch's samples, plus r² for every neighbour their sources have inside the cell (`in_cell`)
// that the patch leaves without a partner, so that sparse or empty patches do not win; and the
// translation of the patch that best closes the seam (the mean move its paired samples ask for).
struct Seam {
  double cost = 0.0;
  Vec3 shift = Vec3::Zero();
};

Seam seam_cost(const EmExemplar& exemplar, const geometry::Domain& domain,
               const InitialOutput& placed, const geometry::NeighbourGrid& grid,
               const Placement& patch, double radians, double alpha,
               const std::function<bool(const Vec3&)>& filled, const std::vector<int>& bordering,
               const std::function<bool(const Vec3&)>& in_cell) {
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
        if (t.norm() < exemplar.radius)
          hood.push_back(
              {turn_about_z(t, -radians), samples.key[s], id, placed.output.attribute[s]});
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
    for (std::size_t i = 0; i < patch_samples.size(); ++i) {
      const Vec3 t = domain.minimum_image(patch_samples[i].first - at);
      const std::size_t e = patch_samples[i].second;
      if (t.norm() < exemplar.radius)
        hood.push_back({turn_about_z(t, -radians), exemplar.samples.key[e], static_cast<int>(i),
                        exemplar.sample_attribute[e]});
    }
    expected.clear();
    for (const geometry::Neighbour& n :
         exemplar.near[static_cast<std::size_t>(placed.copied_from[s])])
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

}  // namespace

void patch_copy(const EmExemplar& exemplar, const geometry::Domain& domain,
                const OrientationField& orientation, double alpha, core::Random& random,
                InitialOutput& out, bool diverse) {
  const int dim = domain.dimension();
  const Vec3 window_min = exemplar.scene.window.min(), period = exemplar.scene.window.sizes();
  const bool wraps = exemplar.boundary == geometry::Boundary::torus;
  Vec3 cell = Vec3::Ones();
  Eigen::Vector3i counts = Eigen::Vector3i::Ones();
  for (int a = 0; a < dim; ++a) {
    const double side = wraps ? 2.0 * exemplar.radius : std::min(2.0 * exemplar.radius, period[a]);
    cell[a] = side;
    counts[a] = std::max(1, static_cast<int>(std::ceil(domain.sizes()[a] / side - 1e-9)));
  }
  geometry::NeighbourGrid grid(domain.box(), dim, exemplar.radius, domain.periodic());
  // Elements already placed: a patch's element nearer to one than half the exemplar's smallest
  // gap is left out (the patches' seams overlap when they are moved).
  const double gap = 0.5 * smallest_gap(exemplar);
  geometry::NeighbourGrid elements(domain.box(), dim, exemplar.radius, domain.periodic());
  std::vector<Vec3> placed;
  const auto uncrowded = [&](Placement patch) {
    patch.erase(
        std::remove_if(
            patch.begin(), patch.end(),
            [&](const std::pair<int, Vec3>& e) {
              bool crowded = false;
              elements.for_each_candidate(e.second, [&](int id) {
                crowded =
                    crowded ||
                    domain.minimum_image(placed[static_cast<std::size_t>(id)] - e.second).norm() <
                        gap;
              });
              return crowded;
            }),
        patch.end());
    return patch;
  };
  // Each filled cell's translation from the exemplar (output minus exemplar position).
  std::vector<std::pair<Eigen::Vector3i, Vec3>> shifts;
  const auto continues_neighbour = [&](const Eigen::Vector3i& at, const Vec3& shift) {
    if (!diverse) return false;
    for (const auto& [other, s] : shifts) {
      if ((other - at).cwiseAbs().maxCoeff() > 1) continue;
      if (geometry::minimum_image(s - shift, exemplar.tile_period).norm() < 0.25 * exemplar.spacing)
        return true;
    }
    return false;
  };
  for (int k = 0; k < counts.z(); ++k)
    for (int j = 0; j < counts.y(); ++j)
      for (int i = 0; i < counts.x(); ++i) {
        const Eigen::Vector3i at(i, j, k);
        Vec3 lo = Vec3::Zero(), extent = Vec3::Zero();
        for (int a = 0; a < dim; ++a) {
          lo[a] = domain.box().min()[a] + at[a] * cell[a];
          extent[a] = std::min(cell[a], domain.box().max()[a] - lo[a]);
        }
        const double radians = orientation.angle_at(lo + 0.5 * extent);
        // Whether a place lies in a cell filled before this one.
        const int current = (k * counts.y() + j) * counts.x() + i;
        const auto filled = [&](const Vec3& p) {
          if (!domain.contains(p)) return false;
          int index = 0;
          for (int a = dim - 1; a >= 0; --a) {
            const int c =
                std::clamp(static_cast<int>(std::floor((p[a] - domain.box().min()[a]) / cell[a])),
                           0, counts[a] - 1);
            index = index * counts[a] + c;
          }
          return index < current;
        };
        // Whether a place lies in this cell, and the placed samples within r of it.
        const auto in_cell = [&](const Vec3& p) {
          for (int a = 0; a < dim; ++a) {
            double t = p[a] - lo[a];
            if (domain.periodic()) {
              const double side = domain.sizes()[a];
              t -= side * std::floor(t / side);
            }
            if (!(t >= 0.0 && t < extent[a])) return false;
          }
          return true;
        };
        std::vector<int> bordering;
        const Vec3 centre = lo + 0.5 * extent;
        for (std::size_t s = 0; s < out.output.samples.size(); ++s) {
          const Vec3 t = domain.minimum_image(out.output.samples.positions[s] - centre);
          bool near_cell = true;
          for (int a = 0; a < dim; ++a)
            near_cell = near_cell && std::abs(t[a]) < 0.5 * extent[a] + exemplar.radius;
          if (near_cell) bordering.push_back(static_cast<int>(s));
        }
        Placement best;
        double best_cost = std::numeric_limits<double>::infinity();
        Vec3 best_shift = Vec3::Zero();
        const bool first_cell = out.output.elements() == 0;
        for (int c = 0; c < (first_cell ? 1 : kPatchCandidates); ++c) {
          Vec3 origin = Vec3::Zero();
          for (int a = 0; a < dim; ++a)
            origin[a] = wraps
                            ? window_min[a] + random.uniform() * period[a]
                            : window_min[a] + random.uniform() * std::max(0.0, period[a] - cell[a]);
          Placement patch = uncrowded(patch_at(exemplar, domain, origin, lo, extent, radians));
          if (first_cell) {
            best = std::move(patch);
            best_shift = lo - origin;
            break;
          }
          // The patch as drawn, and moved to close its seam.
          const Seam seam = seam_cost(exemplar, domain, out, grid, patch, radians, alpha, filled,
                                      bordering, in_cell);
          // The same cell filled from the exemplar patch moved the other way, so that its
          // elements move by the shift and the cell stays covered.
          Vec3 moved_origin = origin - turn_about_z(seam.shift, -radians);
          for (int a = 0; a < dim && !wraps; ++a)
            moved_origin[a] = std::clamp(moved_origin[a], window_min[a],
                                         window_min[a] + std::max(0.0, period[a] - cell[a]));
          Placement moved =
              uncrowded(patch_at(exemplar, domain, moved_origin, lo, extent, radians));
          const double moved_cost = seam_cost(exemplar, domain, out, grid, moved, radians, alpha,
                                              filled, bordering, in_cell)
                                        .cost;
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
        }
        shifts.emplace_back(at, best_shift);
        for (const auto& [element, position] : best) {
          elements.insert(static_cast<int>(placed.size()), position);
          placed.push_back(position);
          const std::size_t before = out.output.samples.size();
          out.add(exemplar, element, position, radians);
          for (std::size_t s = before; s < out.output.samples.size(); ++s)
            grid.insert(static_cast<int>(s), domain.wrap(out.output.samples.positions[s]));
        }
      }
}

}  // namespace shapeproc::methods
