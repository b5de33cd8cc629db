// The state of a shape-process chain: the configuration x, with for every element its links (the
// neighbours it interacts with and log Γ of each pair) and the log of its local factor of β. The
// links make a death, and the old position of a shift, cost a sum instead of a new measurement
// of every neighbour: log λ(x_i | x \ x_i) − log β_c = local + Σ links.
#pragma once

#include <utility>
#include <vector>

#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/geometry/neighbour_grid.hpp"
#include "libshapeproc/geometry/pair_measurements.hpp"
#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/model/interaction.hpp"
#include "libshapeproc/sample/overlap_guard.hpp"

namespace shapeproc::sample {

using geometry::Element;
using geometry::Vec3;

// One interaction of an element with a neighbour: the neighbour's slot and log Γ of the pair.
struct Link {
  int slot;
  int parameter;  // θ index of the pair's band
  double log_gamma;
};

// Elements in a vector (ids are slots; removed slots are reused) and a grid of their positions.
class Configuration {
 public:
  // `reach`: the farthest reference positions of two interacting elements can be. The neighbour
  // grid covers `grid_box` (empty: the domain's box), the part of the domain where the
  // configuration's elements lie (a decomposition's cell and its surroundings). `period`, when
  // not zero, replaces the domain's torus period: the configuration wraps along the axes where it
  // is positive (a cell that spans a torus along an axis the decomposition does not cut).
  // `guard` (may be null) keeps the drawn outlines apart (overlap_guard.hpp).
  Configuration(const model::Interaction& interaction, const geometry::PairMeasurer& measurer,
                const OverlapGuard* guard, const geometry::Domain& domain, double reach,
                const geometry::Box3& grid_box = geometry::Box3(),
                const Vec3& period = Vec3::Zero());

  int size() const { return static_cast<int>(alive_.size()); }
  const Element& at(int slot) const { return elements_[static_cast<std::size_t>(slot)]; }
  int slot_of_rank(std::size_t rank) const { return alive_[rank]; }

  // Σ log Γ(ξ, x_m) over the elements except `skip`, −∞ on a hard core; `links` receives the
  // pairs that interact. Two passes: the distances first (cheap, with the pair's reach as
  // cut-off), so that a hard-core violation rejects before any direction is computed; then the
  // axes of the neighbours in range.
  double log_interaction(const Element& xi, int skip, std::vector<Link>& links) const;

  // log λ(x | x \ x) − log β_c of an element of the configuration, from its links (and, for
  // saturated bands, its neighbours' links: model/saturation.hpp).
  double log_lambda_over_beta(int slot) const {
    const std::vector<Link>& links = links_[static_cast<std::size_t>(slot)];
    if (interaction_.saturated())
      return local_[static_cast<std::size_t>(slot)] + linked_sum(links, slot);
    double total = local_[static_cast<std::size_t>(slot)];
    for (const Link& link : links) total += link.log_gamma;
    return total;
  }

  // Adds `e` with its local term and the links log_interaction found for it.
  void add(const Element& e, double local, const std::vector<Link>& links);

  void remove(int slot);

  // Moves an element to `position`, with its new local term and links.
  void move(int slot, const Vec3& position, double local, const std::vector<Link>& links);

  std::vector<Element> elements() const;

  // Calls f(slot, element) for every element whose reference position may lie within the reach
  // of `position` (a superset of them, each once).
  template <class F>
  void for_each_near(const Vec3& position, F&& f) const {
    grid_.for_each_candidate(position,
                             [&](int slot) { f(slot, elements_[static_cast<std::size_t>(slot)]); });
  }
  // The period the configuration wraps with (zero along open axes).
  const Vec3& period() const { return period_; }

  // The sufficient statistics t(x) of the configuration (Interaction::statistic_count): by θ
  // index elements per category, then pairs per interaction parameter (each pair once; for a
  // saturated band, Σ_i min(s, t_i): model/saturation.hpp), then elements per shape class. Kept
  // up to date by add, remove and move.
  const std::vector<double>& statistics() const { return statistics_; }
  // The same statistics of the elements whose reference positions lie in `region` (closed), and
  // of the pairs with both there: a window's view of the configuration (the stationary MLE's).
  void statistics_in(const geometry::Box3& region, std::vector<double>& out) const;

 private:
  void link(int slot, double local, const std::vector<Link>& links);

  void unlink(int slot);
  // Σ log Γ over `links` of an element, whose saturated bands count as model/saturation.hpp says,
  // with the neighbours' own counts taken without `skip`.
  double linked_sum(const std::vector<Link>& links, int skip) const;
  // The links of `slot` in band `parameter`, not counting one to `skip`.
  int links_in(int slot, int parameter, int skip) const;
  // The change an element linked to `links` makes to the saturated bands' statistics
  // (model/saturation.hpp), its neighbours' own counts taken without `skip`.
  model::InteractionCounts saturated_change(const std::vector<Link>& links, int skip) const;
  // Adds that change, times `sign`, for `slot` joining (+1) or leaving (−1) the configuration.
  void add_saturated_statistics(int slot, const std::vector<Link>& links, double sign);

  const model::Interaction& interaction_;
  const geometry::PairMeasurer& measurer_;
  const OverlapGuard* guard_;  // null or inactive: none
  geometry::NeighbourGrid grid_;
  std::vector<Element> elements_;
  std::vector<int> alive_, free_, position_in_alive_;
  std::vector<std::vector<Link>> links_;  // per slot
  std::vector<double> local_;             // per slot: log of the local factor of β
  std::vector<double> statistics_;        // t(x), by θ index
  Vec3 period_;  // the domain's torus period (zero when open), kept by value for the inner loop
  bool shape_distances_ = true;
  // A neighbour to measure, nearest first: by the gap between the proxies' boxes, then by the
  // squared distance of the reference positions.
  struct Candidate {
    double box_gap, squared;
    int slot;
    bool operator<(const Candidate& o) const {
      return box_gap != o.box_gap ? box_gap < o.box_gap : squared < o.squared;
    }
  };
  mutable std::vector<Candidate> candidates_;  // scratch of log_interaction
  mutable std::vector<std::pair<int, model::PairEffect>>
      near_;  // scratch of log_interaction: (slot, effect in range)
  mutable std::vector<std::pair<int, int>> saturated_;  // scratch: (slot, θ index) of links
};

}  // namespace shapeproc::sample
