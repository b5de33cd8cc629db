// One run of the birth-death Metropolis-Hastings chain (birth_death_sampler.hpp gives the moves
// and their acceptance ratios): the configuration, the generator and the three moves, over a
// region of the domain. The whole-domain sampler runs one chain over everything; the
// domain-decomposition sampler (domain_decomposition.hpp) runs one per cell, the elements around
// the cell held fixed.
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "libshapeproc/core/random.hpp"
#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/model/shape_process_model.hpp"
#include "libshapeproc/sample/configuration.hpp"
#include "libshapeproc/sample/move_counts.hpp"
#include "libshapeproc/sample/neighbour_births.hpp"
#include "libshapeproc/sample/overlap_guard.hpp"

namespace shapeproc::sample {

// The proxies of a model's shapes on a domain and the guard of their drawn outlines: what depends
// on the shapes, the measurement and the thresholds but not on β or γ, so that the samplers of
// one maximum-likelihood fit, one per θ, build it once (its pair expansions too, on first use).
struct ChainGeometry {
  // `interaction`: the model's (its thresholds: the guard's breakpoints).
  ChainGeometry(const model::ShapeProcessModel& model, const model::Interaction& interaction,
                const geometry::Domain& domain);
  // The geometry of `same_shapes` for a model that differs in its thresholds only (a growth
  // stage's hard cores): the proxies are shared, the guard takes the new breakpoints.
  ChainGeometry(const ChainGeometry& same_shapes, const model::Interaction& interaction);
  ~ChainGeometry();

  geometry::Scene shape_space;  // the model's shapes, the domain's box as window
  std::shared_ptr<const geometry::PairMeasurer> measurer;
  std::unique_ptr<const OverlapGuard> guard;  // the drawn outlines kept apart
};

// What every chain of one model shares, built once: the compiled interaction, the proxies (from
// `geometry` when given: built for a model with the same shapes, measurement and thresholds on
// the same domain), the shapes of each category and their probabilities, log β per category.
struct ChainTables {
  // With `other_thresholds`, `geometry` is of a model whose shapes and measurement are the same
  // but not its thresholds: its proxies are shared and a guard is made for the new ones.
  // With `layer` ≥ 0, births are of that layer's categories only (a layered model's stage,
  // model::CategoryParameters::layer): the others' log β is −∞.
  ChainTables(const model::ShapeProcessModel& model, const geometry::Domain& domain,
              std::shared_ptr<const ChainGeometry> geometry = nullptr,
              bool other_thresholds = false, int layer = -1);
  ~ChainTables();

  int dimension = 2;
  std::unique_ptr<const model::Interaction> interaction;
  std::shared_ptr<const ChainGeometry> geometry;  // never null
  std::vector<std::vector<int>> shapes_of;        // per category
  // Per category, with shape classes: the cumulative probabilities of its shapes (a class's
  // weight shared equally by its shapes); empty: its shapes are equally likely.
  std::vector<std::vector<double>> shape_cumulative;
  std::vector<double> log_beta;  // per category: log(β_c Σ_k w_k)
  std::vector<int> born;         // the categories a uniform birth proposes (every one unlayered)
  int layer = -1;                // the layer whose births these are; -1: every category's
  double reach = 0.0;            // farthest apart two interacting reference positions can be
  // Per shape (one point shape for a point pattern): the log of its probability within its
  // category as a uniform birth draws it.
  std::vector<double> log_shape_probability;
  // Births near neighbours (neighbour_births.hpp); null: the model has no offsets to use.
  std::unique_ptr<const NeighbourBirths> near_births;
};

// Where a chain moves elements.
struct ChainRegion {
  ChainRegion(geometry::Domain d, const geometry::Box3& free)
      : domain(std::move(d)), free_region(free) {}

  // The configuration's domain: its box bounds the neighbour grid, its boundary decides
  // wrapping, its mask and intensity map give β's local factor.
  geometry::Domain domain;
  // Births place reference positions uniformly here; shifts that leave it are rejected (on an
  // open domain; a torus wraps them unless `confined`).
  geometry::Box3 free_region;
  // What the neighbour grid covers (empty: the domain's box): the free region and the elements
  // around it that can interact with it.
  geometry::Box3 grid_box;
  bool confined = false;  // a cell of a decomposition: shifts never leave the free region
  // Where β's local factor (the intensity map) is read when not from `domain`: a decomposed
  // torus's cell, whose domain is an open box about it, reads the whole torus's map at positions
  // wrapped into it. Null: `domain`'s.
  const geometry::Domain* local_factor = nullptr;
  // A decomposition's cell that spans a torus along an axis it does not cut: the torus's period
  // along that axis (0 along the others). The configuration and the shifts wrap along it.
  geometry::Vec3 period = geometry::Vec3::Zero();
  double shift_probability = 1.0 / 3.0;
  double shift_radius = 1.0;
  // The share of birth proposals drawn near a neighbour (neighbour_births.hpp) when the tables
  // have them and the configuration is not empty; the others are uniform.
  double near_birth_share = 0.0;
  // Whether births and deaths divide by the birth proposal's density (the model's chain); a
  // compressing burn-in's growth, which only chooses where the chain starts, grows from its
  // elements as a crystal grows: every proposal that fits is kept.
  bool proposal_corrected = true;
};

class BirthDeathChain {
 public:
  // Starts from `fixed` (never moved or removed; their hard cores are checked) and then `start`
  // (each kept unless outside the free region or forbidden by those before it).
  BirthDeathChain(const ChainTables& tables, const ChainRegion& region, core::Random& random,
                  const std::vector<Element>& fixed, const std::vector<Element>& start);

  // Adds elements as the constructor adds `start` (each kept unless outside the free region or
  // forbidden by those before it).
  void add_start(const std::vector<Element>& start);

  // Adds elements as add_start does; one the hard core forbids where it is is tried at up to
  // `attempts` positions uniform in the ball of `radius` around it (the same shape and category),
  // the first that fits kept: the compressing burn-in's push of an element its neighbours' grown
  // hard cores now cover. Returns how many found no place.
  int add_or_place_near(const std::vector<Element>& elements, double radius, int attempts);

  // Random sequential insertion, a burn-in's start rather than a Metropolis-Hastings move: up to
  // `attempts` proposals of a new element (position uniform in the free region, category in
  // proportion to β_c Σ w, shape by class weight), each kept when the hard core and the mask
  // allow it (with an intensity map, with probability its local factor, at most 1), until
  // `wanted` have been added. Returns how many were.
  int insert_at_random(int wanted, long long attempts);

  // Elements whose own pairs are not needed (the ring of a decomposition's cell): in the grid
  // for the free elements' interactions, without links among themselves. Call before any other
  // element is added.
  void add_surroundings(const std::vector<Element>& around);

  // One step: with the shift probability a shift, otherwise a birth or a death with equal
  // probability.
  void step();

  // The compressing burn-in (compression.hpp): births and deaths see β_c e^boost instead of β_c
  // (0: the model itself).
  void set_log_boost(double boost) { log_boost_ = boost; }

  int size() const { return state_.size(); }  // fixed elements included
  int start_kept() const { return start_kept_; }
  int start_left_out() const { return start_left_out_; }
  const std::vector<double>& statistics() const { return state_.statistics(); }
  void statistics_in(const geometry::Box3& region, std::vector<double>& out) const {
    state_.statistics_in(region, out);
  }
  double log_density() const { return log_density_; }
  const MoveCounts& moves() const { return moves_; }
  std::vector<Element> elements() const;       // every element, fixed ones included
  std::vector<Element> free_elements() const;  // those the chain may move or remove

 private:
  Element random_element();
  int random_shape(int category);
  bool near_births() const { return t_.near_births && r_.near_birth_share > 0; }
  Element birth_proposal();
  bool on_an_element(const Vec3& position) const;
  double log_proposal_excess(const Element& e, int skip) const;
  bool settle(Vec3& position) const;
  void propose_birth();
  void propose_death();
  void propose_shift();
  int uniform_slot();
  bool in_free_region(const Vec3& p) const;
  double log_local_factor(const Element& e) const;
  double log_lambda_over_beta(const Element& e, int skip);

  const ChainTables& t_;
  const ChainRegion& r_;
  core::Random& random_;
  Configuration state_;
  double log_measure_categories_ = 0.0;  // log(|R| C), R the free region
  std::vector<Link> links_;              // of the last proposal
  double local_term_ = 0.0;              // of the last proposal
  double log_density_ = 0.0;             // unnormalised, tracked incrementally
  double log_boost_ = 0.0;               // compression.hpp; 0 at the model
  int fixed_ = 0;                        // fixed elements, at ranks 0 … fixed_ − 1
  int start_kept_ = 0, start_left_out_ = 0;
  MoveCounts moves_;
};

}  // namespace shapeproc::sample
