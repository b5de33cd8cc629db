#include "libshapeproc/sample/birth_death_sampler.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "libshapeproc/model/interaction.hpp"
#include "libshapeproc/geometry/neighbour_grid.hpp"
#include "libshapeproc/core/random.hpp"

namespace shapeproc::sample {

using geometry::Element;
using geometry::Vec3;

namespace {

double domain_measure(const geometry::Box3& domain, int dimension) {
  const Vec3 sizes = domain.sizes();
  return dimension == 3 ? sizes.prod() : sizes.x() * sizes.y();
}

// One interaction of an element with a neighbour: the neighbour's slot and log Γ of the pair.
struct Link {
  int slot;
  double log_gamma;
};

// The state: elements in a vector (ids are slots; removed slots are reused), a grid, and for every
// element its links (the neighbours it interacts with and log Γ of each pair) and the log of its
// local factor. The links make a death, and the old position of a shift, cost a sum instead of a
// new measurement of every neighbour: log λ(x | x \ x) − log β_c = local + Σ links.
class Configuration {
 public:
  Configuration(const model::Interaction& interaction, const geometry::PairMeasurer& measurer,
                const geometry::Box3& domain, int dimension, double reach, bool periodic)
      : interaction_(interaction), measurer_(measurer), grid_(domain, dimension, reach, periodic) {
    if (periodic) period_.head(dimension) = domain.sizes().head(dimension);
    shape_distances_ = measurer.options().distance == geometry::DistanceKind::shape;
  }

  int size() const { return static_cast<int>(alive_.size()); }
  const Element& at(int slot) const { return elements_[static_cast<std::size_t>(slot)]; }
  int slot_of_rank(std::size_t rank) const { return alive_[rank]; }

  // Σ log Γ(ξ, x_m) over the elements except `skip`, −∞ on a hard core; `links` receives the
  // pairs that interact. Two passes: the distances first (cheap, with the pair's reach as
  // cut-off), so that a hard-core violation rejects before any direction is computed; then the
  // axes of the neighbours in range.
  double log_interaction(const Element& xi, int skip, std::vector<Link>& links) const {
    near_.clear();
    links.clear();
    // Candidates nearest first (by the minimum-image distance of reference positions), so that a
    // hard core, most likely with the nearest, rejects after few measurements.
    candidates_.clear();
    grid_.for_each_candidate(xi.position, [&](int slot) {
      if (slot == skip) return;
      const Element& other = elements_[static_cast<std::size_t>(slot)];
      if (!interaction_.interacts(xi.category, other.category)) return;
      Vec3 t = other.position - xi.position;
      for (int axis = 0; axis < 3; ++axis) {
        if (period_[axis] > 0) t[axis] -= period_[axis] * std::round(t[axis] / period_[axis]);
      }
      // Shape distances are at least the reference positions' distance minus both radii (t is
      // the nearest image in every coordinate, so no other image is nearer).
      const double squared = t.squaredNorm();
      const double far =
          interaction_.max_range(xi.category, other.category) + measurer_.radius(xi.shape) + measurer_.radius(other.shape);
      if (shape_distances_ && squared >= far * far) return;
      candidates_.emplace_back(squared, slot);
    });
    std::sort(candidates_.begin(), candidates_.end());
    bool forbidden = false;
    for (const auto& [squared, slot] : candidates_) {
      const model::PairEffect effect = model::pair_distance_effect(interaction_, measurer_, xi, elements_[static_cast<std::size_t>(slot)]);
      if (effect.band == model::Interaction::kHardCore) {
        forbidden = true;
        break;
      }
      if (effect.axis_pending) near_.emplace_back(slot, effect);
    }
    if (forbidden) return -std::numeric_limits<double>::infinity();
    double total = 0.0;
    for (auto& [slot, effect] : near_) {
      const Element& other = elements_[static_cast<std::size_t>(slot)];
      model::decide_axis(interaction_, measurer_, xi, other, effect);
      if (effect.band == model::Interaction::kHardCore) return -std::numeric_limits<double>::infinity();
      if (effect.band >= 0) {
        const double value = interaction_.log_gamma(xi.category, other.category, effect.axis, effect.band);
        links.push_back({slot, value});
        total += value;
      }
    }
    return total;
  }

  // log λ(x | x \ x) − log β_c of an element of the configuration, from its links.
  double log_lambda_over_beta(int slot) const {
    double total = local_[static_cast<std::size_t>(slot)];
    for (const Link& link : links_[static_cast<std::size_t>(slot)]) total += link.log_gamma;
    return total;
  }

  // Adds `e` with its local term and the links log_interaction found for it.
  void add(const Element& e, double local, const std::vector<Link>& links) {
    int slot;
    if (!free_.empty()) {
      slot = free_.back();
      free_.pop_back();
      elements_[static_cast<std::size_t>(slot)] = e;
    } else {
      slot = static_cast<int>(elements_.size());
      elements_.push_back(e);
      links_.emplace_back();
      local_.push_back(0.0);
    }
    position_in_alive_.resize(elements_.size(), -1);
    position_in_alive_[static_cast<std::size_t>(slot)] = static_cast<int>(alive_.size());
    alive_.push_back(slot);
    grid_.insert(slot, e.position);
    link(slot, local, links);
  }

  void remove(int slot) {
    grid_.remove(slot, elements_[static_cast<std::size_t>(slot)].position);
    unlink(slot);
    const int rank = position_in_alive_[static_cast<std::size_t>(slot)];
    const int last = alive_.back();
    alive_[static_cast<std::size_t>(rank)] = last;
    position_in_alive_[static_cast<std::size_t>(last)] = rank;
    alive_.pop_back();
    position_in_alive_[static_cast<std::size_t>(slot)] = -1;
    free_.push_back(slot);
  }

  // Moves an element to `position`, with its new local term and links.
  void move(int slot, const Vec3& position, double local, const std::vector<Link>& links) {
    Element& e = elements_[static_cast<std::size_t>(slot)];
    grid_.remove(slot, e.position);
    e.position = position;
    grid_.insert(slot, position);
    unlink(slot);
    link(slot, local, links);
  }

  std::vector<Element> elements() const {
    std::vector<Element> out;
    std::vector<int> slots = alive_;
    std::sort(slots.begin(), slots.end());  // a deterministic order
    for (int slot : slots) out.push_back(elements_[static_cast<std::size_t>(slot)]);
    return out;
  }

 private:
  void link(int slot, double local, const std::vector<Link>& links) {
    local_[static_cast<std::size_t>(slot)] = local;
    links_[static_cast<std::size_t>(slot)] = links;
    for (const Link& l : links) links_[static_cast<std::size_t>(l.slot)].push_back({slot, l.log_gamma});
  }

  void unlink(int slot) {
    for (const Link& l : links_[static_cast<std::size_t>(slot)]) {
      std::vector<Link>& back = links_[static_cast<std::size_t>(l.slot)];
      const auto it = std::find_if(back.begin(), back.end(), [&](const Link& b) { return b.slot == slot; });
      *it = back.back();
      back.pop_back();
    }
    links_[static_cast<std::size_t>(slot)].clear();
  }

  const model::Interaction& interaction_;
  const geometry::PairMeasurer& measurer_;
  geometry::NeighbourGrid grid_;
  std::vector<Element> elements_;
  std::vector<int> alive_, free_, position_in_alive_;
  std::vector<std::vector<Link>> links_;  // per slot
  std::vector<double> local_;             // per slot: log of the local factor of β
  Vec3 period_ = Vec3::Zero();            // the torus's sizes (0: open)
  bool shape_distances_ = true;
  mutable std::vector<std::pair<double, int>> candidates_;       // scratch of log_interaction: (squared distance, slot)
  mutable std::vector<std::pair<int, model::PairEffect>> near_;  // scratch of log_interaction: (slot, effect in range)
};

// Whether the element's proxy lies inside the mask: its reference position and its outline at
// half-pixel spacing.
bool inside_mask(const geometry::Raster& mask, const geometry::Box3& domain, const geometry::PairMeasurer& measurer,
                 const Element& e) {
  const geometry::Vec2 at = e.position.head<2>();
  if (mask.sample(domain, at) < 0.5f) return false;
  const double pixel = 0.5 * std::min(domain.sizes().x() / mask.width, domain.sizes().y() / mask.height);
  const geometry::Proxy2& proxy = measurer.proxies2()[static_cast<std::size_t>(e.shape)];
  for (std::size_t k = 0; k < proxy.segment_start.size(); ++k) {
    const geometry::Vec2 a = proxy.segment_start[k] + at, b = proxy.segment_end[k] + at;
    const int steps = std::max(1, static_cast<int>(std::ceil((b - a).norm() / pixel)));
    for (int i = 0; i <= steps; ++i) {
      if (mask.sample(domain, a + (b - a) * (static_cast<double>(i) / steps)) < 0.5f) return false;
    }
  }
  return true;
}

// The automatic rule's test on the counts recorded so far: the second half of the run, cut into
// ten batches; the means of its two quarters, a quarter of the run apart, must differ by at most
// a quarter of max(1, 1% of the mean) plus two standard errors from the batch means. So a trend
// that would move the count by max(1, 1%) over as many steps again keeps the chain going (packed
// exemplars creep up by an element every few ten thousand steps, with little noise).
bool is_stationary(const std::vector<int>& counts) {
  const std::size_t half = counts.size() / 2, length = counts.size() - half;
  if (length < 100) return false;
  constexpr int kBatches = 10;
  std::vector<double> batch(kBatches, 0.0);
  const std::size_t per_batch = length / kBatches;
  for (int b = 0; b < kBatches; ++b) {
    for (std::size_t i = 0; i < per_batch; ++i) batch[b] += counts[half + b * per_batch + i];
    batch[b] /= static_cast<double>(per_batch);
  }
  double first = 0.0, second = 0.0, mean = 0.0;
  for (int b = 0; b < kBatches; ++b) {
    (b < kBatches / 2 ? first : second) += batch[b] / (kBatches / 2);
    mean += batch[b] / kBatches;
  }
  double variance = 0.0;
  for (double m : batch) variance += (m - mean) * (m - mean) / (kBatches - 1);
  const double standard_error = std::sqrt(variance * (2.0 / (kBatches / 2)));
  return std::abs(second - first) <= 0.25 * std::max(1.0, 0.01 * mean) + 2.0 * standard_error;
}

}  // namespace

std::uint64_t chain_seed(std::uint64_t seed, int chain) {
  if (chain == 0) return seed;
  // SplitMix64 of (seed, chain): well-separated streams for neighbouring seeds and chains.
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ULL * static_cast<std::uint64_t>(chain + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

SampleResult sample_shape_process(const model::ShapeProcessModel& model, const geometry::Box3& domain,
                                  const SamplerOptions& options) {
  model::validate(model);
  const int dimension = model.dimension;
  if (dimension != 2 && (options.mask || options.intensity)) {
    throw std::invalid_argument("sample: domain masks and intensity maps are for 2D models");
  }
  const double measure = domain_measure(domain, dimension);
  if (!(measure > 0)) throw std::invalid_argument("sample: the domain has zero size");

  SampleResult result;
  geometry::Scene& scene = result.scene;
  scene = model.shape_space();
  scene.window = domain;
  const model::Interaction interaction(model);
  const geometry::PairMeasurer measurer(scene, model.measurement_options(options.periodic));
  double max_radius = 0.0;
  for (std::size_t s = 0; s < scene.shapes.size(); ++s) max_radius = std::max(max_radius, measurer.radius(static_cast<int>(s)));
  Configuration state(interaction, measurer, domain, dimension, interaction.range() + 2 * max_radius, options.periodic);

  const int categories = static_cast<int>(model.categories.size());
  std::vector<std::vector<int>> shapes_of(static_cast<std::size_t>(categories));
  if (model.shapes.empty()) {
    for (auto& list : shapes_of) list.push_back(0);  // the point shape
  } else {
    for (std::size_t s = 0; s < model.shapes.size(); ++s) shapes_of[static_cast<std::size_t>(model.shapes[s].category)].push_back(static_cast<int>(s));
  }
  std::vector<double> log_beta;
  for (const auto& c : model.categories) log_beta.push_back(std::log(c.beta));
  const double log_measure_categories = std::log(measure) + std::log(static_cast<double>(categories));

  core::Random random(options.seed);
  const bool automatic = options.iterations <= 0;
  if (!(options.shift_probability >= 0 && options.shift_probability < 1) || !(options.shift_radius >= 0)) {
    throw std::invalid_argument("sample: the shift probability must be in [0, 1) and the shift radius >= 0");
  }
  const double shift_radius = options.shift_radius > 0 ? options.shift_radius
                              : interaction.range() > 0 ? 0.5 * interaction.range()
                                                        : 0.05 * domain.sizes().head(dimension).minCoeff();
  // log of the local factor of β at a location (−∞ outside the mask or where the map is black).
  auto log_local = [&](const Element& e) {
    double factor = 0.0;
    if (options.intensity) {
      const float v = options.intensity->sample(domain, e.position.head<2>());
      if (!(v > 0.0f)) return -std::numeric_limits<double>::infinity();
      factor = std::log(static_cast<double>(v));
    }
    if (options.mask && !inside_mask(*options.mask, domain, measurer, e)) return -std::numeric_limits<double>::infinity();
    return factor;
  };
  const bool local = options.mask || options.intensity;
  // log λ(e | x) − log β_c for a proposed position: the local factor, then (when it is finite)
  // the interactions with every element but `skip`, whose links go to `links`. −∞ outside the
  // mask or on a hard core.
  std::vector<Link> links;
  double local_term = 0.0;  // the local part of the last evaluation
  auto log_lambda_over_beta = [&](const Element& e, int skip) {
    local_term = local ? log_local(e) : 0.0;
    links.clear();
    return std::isfinite(local_term) ? local_term + state.log_interaction(e, skip, links) : local_term;
  };
  const long long progress_every = automatic ? 10000 : std::max<long long>(1, options.iterations / 100);
  // The automatic rule (see SamplerOptions::iterations): the count every kStride steps.
  constexpr long long kMinimumSteps = 20000, kStride = 10, kStepsPerElement = 1000;
  std::vector<int> counts;
  long long next_check = kMinimumSteps;
  double log_density = 0.0;  // unnormalised, tracked incrementally
  long long step = 1;
  for (;; ++step) {
    const int n = state.size();
    const double move = random.uniform();
    if (move < options.shift_probability) {
      ++result.shifts_proposed;
      if (n > 0) {
        const int slot = state.slot_of_rank(random.index(static_cast<std::uint64_t>(n)));
        const Element old = state.at(slot);
        Vec3 offset = Vec3::Zero();
        do {
          for (int axis = 0; axis < dimension; ++axis) offset[axis] = shift_radius * (2.0 * random.uniform() - 1.0);
        } while (offset.squaredNorm() > shift_radius * shift_radius);
        Element moved = old;
        moved.position += offset;
        bool inside = true;
        for (int axis = 0; axis < dimension; ++axis) {
          const double low = domain.min()[axis], size = domain.sizes()[axis];
          double& x = moved.position[axis];
          if (options.periodic) x -= size * std::floor((x - low) / size);
          else inside = inside && x >= low && x <= domain.max()[axis];
        }
        const double new_term = inside ? log_lambda_over_beta(moved, slot) : -std::numeric_limits<double>::infinity();
        if (std::isfinite(new_term)) {
          const double old_term = state.log_lambda_over_beta(slot);
          if (std::log(random.uniform()) < new_term - old_term) {
            state.move(slot, moved.position, local_term, links);
            log_density += new_term - old_term;
            ++result.shifts_accepted;
          }
        }
      }
    } else if ((move - options.shift_probability) < 0.5 * (1.0 - options.shift_probability)) {
      ++result.births_proposed;
      Element xi;
      for (int axis = 0; axis < dimension; ++axis) xi.position[axis] = random.uniform(domain.min()[axis], domain.max()[axis]);
      xi.category = static_cast<int>(random.index(static_cast<std::uint64_t>(categories)));
      const auto& shapes = shapes_of[static_cast<std::size_t>(xi.category)];
      xi.shape = shapes[random.index(shapes.size())];
      const double log_lambda = log_beta[static_cast<std::size_t>(xi.category)] + log_lambda_over_beta(xi, -1);
      const double log_ratio = log_lambda + log_measure_categories - std::log(n + 1.0);
      if (std::isfinite(log_lambda) && std::log(random.uniform()) < log_ratio) {
        state.add(xi, local_term, links);
        log_density += log_lambda;
        ++result.births_accepted;
      }
    } else {
      ++result.deaths_proposed;
      if (n > 0) {
        const int slot = state.slot_of_rank(random.index(static_cast<std::uint64_t>(n)));
        const Element& x = state.at(slot);
        const double log_lambda = log_beta[static_cast<std::size_t>(x.category)] + state.log_lambda_over_beta(slot);
        const double log_ratio = std::log(static_cast<double>(n)) - log_measure_categories - log_lambda;
        if (std::log(random.uniform()) < log_ratio) {
          log_density -= log_lambda;
          state.remove(slot);
          ++result.deaths_accepted;
        }
      }
    }
    if (options.trace_every > 0 && step % options.trace_every == 0) {
      result.trace.push_back({step, state.size(), log_density});
    }
    if (!automatic) {
      if (options.progress && (step % progress_every == 0 || step == options.iterations)) options.progress(step, options.iterations);
      if (step >= options.iterations) break;
      continue;
    }
    if (options.progress && step % progress_every == 0) options.progress(step, 0);
    if (step % kStride == 0) counts.push_back(state.size());
    if (step < next_check) continue;
    if (step >= kStepsPerElement * state.size() && is_stationary(counts)) break;
    if (step >= options.max_iterations) {
      result.stationary = false;
      break;
    }
    next_check = std::min(options.max_iterations, std::max(step + 10000, step + step / 4));
  }
  result.iterations = step;
  if (options.progress && automatic) options.progress(step, step);
  scene.elements = state.elements();
  return result;
}

}  // namespace shapeproc::sample
