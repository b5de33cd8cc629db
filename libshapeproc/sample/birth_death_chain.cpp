#include "libshapeproc/sample/birth_death_chain.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "libshapeproc/core/assert.hpp"
#include "libshapeproc/core/error.hpp"
#include "libshapeproc/geometry/pair_measurements.hpp"
#include "libshapeproc/model/interaction.hpp"
#include "libshapeproc/sample/ball_offset.hpp"

namespace shapeproc::sample {

namespace {

constexpr double kMinusInfinity = -std::numeric_limits<double>::infinity();

// Per category, the cumulative probabilities of its shapes under the model's shape classes
// (empty lists without classes), and the sum of its classes' weights in `weight_sum`. Drawing a
// birth's shape from them and using β_c Σ w in the acceptance ratio samples the density with
// class intensities β_c w_k.
std::vector<std::vector<double>> shape_probabilities(const model::ShapeProcessModel& model,
                                                     const std::vector<std::vector<int>>& shapes_of,
                                                     std::vector<double>& weight_sum) {
  weight_sum.assign(shapes_of.size(), 1.0);
  std::vector<std::vector<double>> cumulative(shapes_of.size());
  if (model.shape_classes.empty()) return cumulative;
  std::vector<int> class_size(model.shape_classes.size(), 0);
  for (const model::ModelShape& s : model.shapes)
    ++class_size[static_cast<std::size_t>(s.shape_class)];
  for (std::size_t c = 0; c < shapes_of.size(); ++c) {
    double total = 0.0;
    for (int s : shapes_of[c]) {
      const std::size_t k =
          static_cast<std::size_t>(model.shapes[static_cast<std::size_t>(s)].shape_class);
      total += model.shape_classes[k].weight / class_size[k];
      cumulative[c].push_back(total);
    }
    for (double& p : cumulative[c]) p /= total;
    weight_sum[c] = 0.0;
    for (const model::ShapeClass& k : model.shape_classes)
      if (k.category == static_cast<int>(c)) weight_sum[c] += k.weight;
  }
  return cumulative;
}

}  // namespace

ChainGeometry::ChainGeometry(const model::ShapeProcessModel& model,
                             const model::Interaction& interaction,
                             const geometry::Domain& domain) {
  shape_space = model.shape_space();
  shape_space.window = domain.box();
  measurer = std::make_shared<const geometry::PairMeasurer>(
      shape_space, model.measurement_options(domain.periodic()));
  guard = std::make_unique<const OverlapGuard>(interaction, shape_space, *measurer);
}

ChainGeometry::ChainGeometry(const ChainGeometry& same_shapes,
                             const model::Interaction& interaction)
    : shape_space(same_shapes.shape_space),
      measurer(same_shapes.measurer),
      guard(std::make_unique<const OverlapGuard>(*same_shapes.guard, interaction)) {}

ChainGeometry::~ChainGeometry() = default;

ChainTables::ChainTables(const model::ShapeProcessModel& model, const geometry::Domain& domain,
                         std::shared_ptr<const ChainGeometry> given, bool other_thresholds,
                         int births_of_layer)
    : dimension(model.dimension),
      interaction(std::make_unique<const model::Interaction>(model)),
      geometry(std::move(given)),
      layer(births_of_layer) {
  if (!geometry)
    geometry = std::make_shared<const ChainGeometry>(model, *interaction, domain);
  else if (other_thresholds)
    geometry = std::make_shared<const ChainGeometry>(*geometry, *interaction);
  const geometry::Scene& shape_space = geometry->shape_space;
  SHAPEPROC_ASSERT((model.shapes.empty() || shape_space.shapes.size() == model.shapes.size()) &&
                       shape_space.window.min() == domain.box().min() &&
                       shape_space.window.max() == domain.box().max(),
                   "a chain geometry is reused for a model of the same shapes on the same domain");
  double max_radius = 0.0;
  for (std::size_t s = 0; s < shape_space.shapes.size(); ++s)
    max_radius = std::max(max_radius, geometry->measurer->radius(static_cast<int>(s)));
  reach = interaction->range() + 2 * max_radius;
  shapes_of.resize(model.categories.size());
  if (model.shapes.empty()) {
    for (auto& list : shapes_of) list.push_back(0);  // the point shape
  } else {
    for (std::size_t s = 0; s < model.shapes.size(); ++s)
      shapes_of[static_cast<std::size_t>(model.shapes[s].category)].push_back(static_cast<int>(s));
  }
  std::vector<double> weight_sum;
  shape_cumulative = shape_probabilities(model, shapes_of, weight_sum);
  for (std::size_t c = 0; c < model.categories.size(); ++c) {
    if (layer >= 0 && model.categories[c].layer != layer) {
      log_beta.push_back(-std::numeric_limits<double>::infinity());
      continue;
    }
    log_beta.push_back(std::log(model.categories[c].beta * weight_sum[c]));
    born.push_back(static_cast<int>(c));
  }
  log_shape_probability.assign(std::max<std::size_t>(1, model.shapes.size()), 0.0);
  for (std::size_t c = 0; c < shapes_of.size(); ++c)
    for (std::size_t i = 0; i < shapes_of[c].size(); ++i) {
      const std::vector<double>& cumulative = shape_cumulative[c];
      const double p = cumulative.empty() ? 1.0 / static_cast<double>(shapes_of[c].size())
                                          : cumulative[i] - (i > 0 ? cumulative[i - 1] : 0.0);
      log_shape_probability[static_cast<std::size_t>(shapes_of[c][i])] = std::log(p);
    }
  near_births = NeighbourBirths::make(model, reach);
}

ChainTables::~ChainTables() = default;

BirthDeathChain::BirthDeathChain(const ChainTables& tables, const ChainRegion& region,
                                 core::Random& random, const std::vector<Element>& fixed,
                                 const std::vector<Element>& start)
    : t_(tables),
      r_(region),
      random_(random),
      state_(*tables.interaction, *tables.geometry->measurer, tables.geometry->guard.get(),
             region.domain, tables.reach, region.grid_box, region.period) {
  log_measure_categories_ = std::log(geometry::measure(r_.free_region, t_.dimension)) +
                            std::log(static_cast<double>(t_.born.size()));
  for (const Element& e : fixed) {
    const double term = log_lambda_over_beta(e, -1);
    if (!std::isfinite(term))
      throw core::ArgumentError("sample", "the fixed elements violate the model's hard core");
    state_.add(e, local_term_, links_);
    log_density_ += t_.log_beta[static_cast<std::size_t>(e.category)] + term;
  }
  fixed_ = state_.size();
  add_start(start);
}

void BirthDeathChain::add_start(const std::vector<Element>& start) {
  for (const Element& e : start) {
    const double term = in_free_region(e.position) ? log_lambda_over_beta(e, -1) : kMinusInfinity;
    if (!std::isfinite(term)) {
      ++start_left_out_;
      continue;
    }
    state_.add(e, local_term_, links_);
    log_density_ += t_.log_beta[static_cast<std::size_t>(e.category)] + term;
    ++start_kept_;
  }
}

int BirthDeathChain::add_or_place_near(const std::vector<Element>& elements, double radius,
                                       int attempts) {
  int lost = 0;
  for (const Element& e : elements) {
    Element placed = e;
    bool fits = false;
    for (int a = 0; a <= attempts && !fits; ++a) {
      if (a > 0) {
        placed.position =
            r_.domain.wrap(e.position + offset_in_ball(random_, radius, t_.dimension));
      }
      if (!in_free_region(placed.position) ||
          (!r_.domain.periodic() && !r_.domain.contains(placed.position)))
        continue;
      const double term = log_lambda_over_beta(placed, -1);
      if (!std::isfinite(term)) continue;
      state_.add(placed, local_term_, links_);
      log_density_ += t_.log_beta[static_cast<std::size_t>(placed.category)] + term;
      fits = true;
    }
    if (!fits) ++lost;
  }
  return lost;
}

void BirthDeathChain::add_surroundings(const std::vector<Element>& around) {
  SHAPEPROC_ASSERT(state_.size() == fixed_, "surroundings come before the free elements");
  for (const Element& e : around) state_.add(e, 0.0, {});
  fixed_ = state_.size();
}

void BirthDeathChain::step() {
  const double move = random_.uniform();
  const double p = r_.shift_probability;
  if (move < p)
    propose_shift();
  else if ((move - p) < 0.5 * (1.0 - p))
    propose_birth();
  else
    propose_death();
}

int BirthDeathChain::insert_at_random(int wanted, long long attempts) {
  std::vector<double> cumulative;  // categories in proportion to β_c Σ w
  for (double log_beta : t_.log_beta)
    cumulative.push_back((cumulative.empty() ? 0.0 : cumulative.back()) + std::exp(log_beta));
  int added = 0;
  for (long long a = 0; a < attempts && added < wanted; ++a) {
    Element xi = random_element();
    const double u = random_.uniform() * cumulative.back();
    xi.category = static_cast<int>(std::min<std::size_t>(
        cumulative.size() - 1,
        static_cast<std::size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), u) -
                                 cumulative.begin())));
    xi.shape = random_shape(xi.category);
    const double term = log_lambda_over_beta(xi, -1);
    if (!std::isfinite(term)) continue;
    if (local_term_ < 0.0 && std::log(random_.uniform()) >= local_term_) continue;
    state_.add(xi, local_term_, links_);
    log_density_ += t_.log_beta[static_cast<std::size_t>(xi.category)] + term;
    ++added;
  }
  return added;
}

// A position uniform in the free region; category and shape are the caller's.
Element BirthDeathChain::random_element() {
  Element xi;
  const geometry::Box3& box = r_.free_region;
  for (int axis = 0; axis < t_.dimension; ++axis)
    xi.position[axis] = random_.uniform(box.min()[axis], box.max()[axis]);
  return xi;
}

// One of the category's shapes, in proportion to its class's weight (all alike without classes).
int BirthDeathChain::random_shape(int category) {
  const auto& shapes = t_.shapes_of[static_cast<std::size_t>(category)];
  const auto& cumulative = t_.shape_cumulative[static_cast<std::size_t>(category)];
  if (cumulative.empty()) return shapes[random_.index(shapes.size())];
  const auto at = std::upper_bound(cumulative.begin(), cumulative.end(), random_.uniform());
  return shapes[std::min(shapes.size() - 1, static_cast<std::size_t>(at - cumulative.begin()))];
}

void BirthDeathChain::propose_birth() {
  ++moves_.births_proposed;
  const int n = state_.size() - fixed_;
  Element xi = birth_proposal();
  if (!settle(xi.position) || !in_free_region(xi.position)) return;
  if (!r_.proposal_corrected && on_an_element(xi.position)) return;
  const double log_lambda =
      t_.log_beta[static_cast<std::size_t>(xi.category)] + log_lambda_over_beta(xi, -1);
  if (!std::isfinite(log_lambda)) return;
  const double log_ratio = log_lambda + log_boost_ + log_measure_categories_ - std::log(n + 1.0) -
                           log_proposal_excess(xi, -1);
  if (std::log(random_.uniform()) < log_ratio) {
    state_.add(xi, local_term_, links_);
    log_density_ += log_lambda;
    ++moves_.births_accepted;
  }
}

// Whether an element of the configuration has its reference position at `position` (up to
// rounding): a crystal's growth proposes the sites of its elements again, exactly, and two
// identical outlines that coincide measure 0 apart, which a hard core at 0 (touching shapes)
// allows.
bool BirthDeathChain::on_an_element(const Vec3& position) const {
  const double tolerance = 1e-9 * std::max(1.0, t_.reach);
  bool found = false;
  state_.for_each_near(position, [&](int, const Element& e) {
    found = found ||
            geometry::minimum_image(e.position - position, state_.period()).norm() <= tolerance;
  });
  return found;
}

// A birth's proposal: near a neighbour with the region's share (when the configuration has an
// element), else uniform in the free region (category uniform, shape by class weight: the birth
// ratio is unchanged).
Element BirthDeathChain::birth_proposal() {
  if (near_births() && state_.size() > 0 && random_.uniform() < r_.near_birth_share) {
    const int slot = state_.slot_of_rank(random_.index(static_cast<std::uint64_t>(state_.size())));
    return t_.near_births->propose(state_.at(slot), random_);
  }
  Element xi = random_element();
  xi.category = t_.born[random_.index(t_.born.size())];
  xi.shape = random_shape(xi.category);
  return xi;
}

// log(q(e | x') / q_uniform(e)) for the configuration x' without `skip`: the birth proposal's
// density over the uniform proposal's, log((1 − s) + s q_near / q_uniform) with s the near share
// (0 when x' is empty or births are uniform only). q_uniform(e) = P(shape | category) / (|R| C).
double BirthDeathChain::log_proposal_excess(const Element& e, int skip) const {
  if (!near_births() || !r_.proposal_corrected || state_.size() - (skip >= 0 ? 1 : 0) <= 0)
    return 0.0;
  const double share = r_.near_birth_share;
  const double near = t_.near_births->density(e, state_, skip);
  const double uniform = std::exp(t_.log_shape_probability[static_cast<std::size_t>(e.shape)] -
                                  log_measure_categories_);
  return std::log((1.0 - share) + share * near / uniform);
}

void BirthDeathChain::propose_death() {
  ++moves_.deaths_proposed;
  const int slot = uniform_slot();
  if (slot < 0) return;
  const int n = state_.size() - fixed_;
  const Element& x = state_.at(slot);
  const double log_lambda =
      t_.log_beta[static_cast<std::size_t>(x.category)] + state_.log_lambda_over_beta(slot);
  const double log_ratio = std::log(static_cast<double>(n)) - log_measure_categories_ - log_lambda -
                           log_boost_ + log_proposal_excess(x, slot);
  if (std::log(random_.uniform()) < log_ratio) {
    log_density_ -= log_lambda;
    state_.remove(slot);
    ++moves_.deaths_accepted;
  }
}

void BirthDeathChain::propose_shift() {
  ++moves_.shifts_proposed;
  const int slot = uniform_slot();
  if (slot < 0) return;
  Element moved = state_.at(slot);
  moved.position += offset_in_ball(random_, r_.shift_radius, t_.dimension);
  const bool inside = settle(moved.position);
  const double new_term = inside ? log_lambda_over_beta(moved, slot) : kMinusInfinity;
  if (!std::isfinite(new_term)) return;
  const double old_term = state_.log_lambda_over_beta(slot);
  if (std::log(random_.uniform()) < new_term - old_term) {
    state_.move(slot, moved.position, local_term_, links_);
    log_density_ += new_term - old_term;
    ++moves_.shifts_accepted;
  }
}

// Wraps a position that left the region where the configuration wraps (a torus, or a cell's
// period); whether it then lies where the chain places elements.
bool BirthDeathChain::settle(Vec3& position) const {
  const geometry::Domain& domain = r_.domain;
  if (r_.confined) {
    for (int axis = 0; axis < t_.dimension; ++axis) {
      const double period = r_.period[axis];
      if (period > 0)
        position[axis] -=
            period * std::floor((position[axis] - r_.free_region.min()[axis]) / period);
    }
    return in_free_region(position);
  }
  position = domain.wrap(position);
  return domain.periodic() || (domain.contains(position) && in_free_region(position));
}

std::vector<Element> BirthDeathChain::elements() const { return state_.elements(); }

std::vector<Element> BirthDeathChain::free_elements() const {
  std::vector<Element> out;
  out.reserve(static_cast<std::size_t>(size()));
  for (int rank = fixed_; rank < state_.size(); ++rank)
    out.push_back(state_.at(state_.slot_of_rank(static_cast<std::size_t>(rank))));
  return out;
}

// A uniformly chosen free element's slot (fixed ones hold the first ranks: removals swap the last
// rank into the gap); -1 (and no draw) when there is none.
int BirthDeathChain::uniform_slot() {
  const int n = state_.size() - fixed_;
  return n == 0 ? -1
                : state_.slot_of_rank(static_cast<std::size_t>(fixed_) +
                                      random_.index(static_cast<std::uint64_t>(n)));
}

bool BirthDeathChain::in_free_region(const Vec3& p) const {
  for (int axis = 0; axis < t_.dimension; ++axis)
    if (p[axis] < r_.free_region.min()[axis] || p[axis] > r_.free_region.max()[axis]) return false;
  return true;
}

// log of the domain's local factor of β at the element: −∞ outside the mask or where the
// intensity map is black.
double BirthDeathChain::log_local_factor(const Element& e) const {
  const geometry::Domain& domain = r_.local_factor ? *r_.local_factor : r_.domain;
  double factor = 0.0;
  if (domain.intensity()) {
    const Vec3 at = r_.local_factor ? domain.wrap(e.position) : e.position;
    const double v = domain.intensity_at(at.head<2>());
    if (!(v > 0.0)) return kMinusInfinity;
    factor = std::log(v);
  }
  if (domain.mask() &&
      !domain.contains(t_.geometry->measurer->proxies2()[static_cast<std::size_t>(e.shape)],
                       e.position.head<2>())) {
    return kMinusInfinity;
  }
  return factor;
}

// log λ(e | x) − log β_c for a proposed element: the local factor, then (when it is finite) the
// interactions with every element but `skip`, whose links go to links_. −∞ outside the mask or
// on a hard core. The local part is kept in local_term_.
double BirthDeathChain::log_lambda_over_beta(const Element& e, int skip) {
  const bool local =
      r_.local_factor ? r_.local_factor->has_local_factor() : r_.domain.has_local_factor();
  local_term_ = local ? log_local_factor(e) : 0.0;
  links_.clear();
  return std::isfinite(local_term_) ? local_term_ + state_.log_interaction(e, skip, links_)
                                    : local_term_;
}

}  // namespace shapeproc::sample
