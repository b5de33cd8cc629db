#include "libshapeproc/methods/ma2011/neighbourhood_em.hpp"

#include <algorithm>
#include <cmath>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/format.hpp"
#include "libshapeproc/methods/common/position_assignment.hpp"
#include "libshapeproc/methods/ma2011/attribute_vote.hpp"

namespace shapeproc::methods {

namespace {

void check_options(const EmOptions& o, const geometry::Scene& exemplar,
                   const geometry::Domain& domain) {
  if (!(o.rings > 0 && o.rings <= 10))
    throw core::ArgumentError("neighbourhood EM", "rings: expected rings in (0, 10]");
  if (o.k < 1 || o.k > 100) throw core::ArgumentError("neighbourhood EM", "k: expected 1 to 100");
  if (!(o.alpha >= 0) || !(o.lambda >= 0))
    throw core::ArgumentError("neighbourhood EM", "alpha: the weights must be >= 0");
  if (o.iterations < 0 || o.iterations > 10000)
    throw core::ArgumentError("neighbourhood EM", "iterations: expected 0 to 10000 EM iterations");
  if (o.samples.per_element < 0 || o.samples.per_element > kMaxSamplesPerElement)
    throw core::ArgumentError("neighbourhood EM", "samples.per_element: expected 1 to " +
                                                      std::to_string(kMaxSamplesPerElement));
  if (exemplar.dimension != domain.dimension())
    throw core::ArgumentError(
        "neighbourhood EM", "the exemplar is " + std::to_string(exemplar.dimension) +
                                "D but the domain is " + std::to_string(domain.dimension()) + "D");
  if (o.physics_steps < 0 || o.physics_steps > 1000)
    throw core::ArgumentError("neighbourhood EM",
                              "physics_steps: expected 0 to 1000 engine steps per iteration");
  if (!o.orientation.empty() && exemplar.dimension != 2)
    throw core::ArgumentError("neighbourhood EM",
                              "orientation: orientation fields are for 2D outputs");
}

// The output with its positions moved by `step` of `displacement` and its sources replaced.
OutputSamples moved(const OutputSamples& output, const std::vector<Vec3>& displacement, double step,
                    const std::vector<int>& sources, const EmExemplar& exemplar,
                    const geometry::Domain& domain) {
  OutputSamples out = output;
  for (std::size_t s = 0; s < out.samples.size(); ++s)
    out.samples.positions[s] = domain.wrap(out.samples.positions[s] + step * displacement[s]);
  for (std::size_t e = 0; e < out.elements(); ++e)
    if (sources[e] != out.source[e]) out.set_source(exemplar, static_cast<int>(e), sources[e]);
  return out;
}

}  // namespace

NeighbourhoodEm::NeighbourhoodEm(const geometry::Scene& exemplar,
                                 geometry::Boundary exemplar_boundary, geometry::Domain domain,
                                 EmOptions options)
    : domain_(std::move(domain)), options_(std::move(options)) {
  check_options(options_, exemplar, domain_);
  exemplar_ = analyse_exemplar(exemplar, exemplar_boundary, options_.rings, options_.samples);
  const double unit = exemplar_.spacing * exemplar_.spacing;
  settings_.rule = options_.search;
  settings_.alpha = options_.alpha * unit;
  settings_.lambda = options_.lambda * unit;
  settings_.orientation = options_.orientation.empty() ? nullptr : &options_.orientation;
  if (options_.search == SearchRule::k_coherence)
    sets_ = build_similarity_sets(exemplar_, options_.k, settings_.alpha);
  settings_.sets = &sets_;
  if (options_.physics_steps > 0) physics_.emplace(exemplar_, options_.physics_steps);
}

std::vector<std::pair<std::string, std::string>> NeighbourhoodEm::record_options() const {
  const auto number = [](double v) { return core::format_number(v); };
  return {
      {"em.neighbourhood_rings", number(options_.rings)},
      {"em.radius", number(exemplar_.radius)},
      {"em.k", std::to_string(options_.k)},
      {"em.alpha", number(options_.alpha)},
      {"em.lambda", number(options_.lambda)},
      {"em.samples_per_element",
       options_.samples.per_element > 0 ? std::to_string(options_.samples.per_element) : "auto"},
      {"em.initialisation", to_string(options_.initialisation)},
      {"em.diverse_patches", options_.diverse_patches ? "yes" : "no"},
      {"em.search", options_.search == SearchRule::brute_force ? "brute-force" : "k-coherence"},
      {"em.reconstruction", to_string(options_.reconstruction)},
      {"em.orientation", options_.orientation.describe()},
      {"em.physics_steps", std::to_string(options_.physics_steps)}};
}

synthesis::SynthesisResult NeighbourhoodEm::synthesize(
    core::Random& random, const synthesis::ChainControl& control) const {
  InitialOutput start =
      initialise(exemplar_, domain_, options_.orientation, options_.initialisation, settings_.alpha,
                 random, options_.diverse_patches);
  OutputSamples output = std::move(start.output);
  SearchResult seed;
  seed.match = std::move(start.copied_from);
  SearchResult current = search(exemplar_, output, domain_, settings_, seed);

  synthesis::SynthesisResult result;
  const auto elements = static_cast<int>(output.elements());
  result.trace.push_back({0, elements, current.energy});
  const double first_energy = current.energy;
  int done = 0;
  bool converged = false;
  SearchSettings fixed = settings_;
  fixed.rule = SearchRule::fixed;
  while (done < options_.iterations && !converged) {
    if (control.cancelled()) throw core::Cancelled();
    // Assignment: positions (eq. 4), then attributes (eq. 5), each kept only if the energy of
    // the current matches falls.
    SearchResult kept;
    bool accepted = false;
    const std::vector<Vec3> displacement =
        solve_positions(output.samples.positions, current.predictions, domain_);
    for (double step = 1.0; step >= kShortestStep && !accepted; step *= 0.5) {
      OutputSamples candidate =
          moved(output, displacement, step, output.source, exemplar_, domain_);
      SearchResult energy = search(exemplar_, candidate, domain_, fixed, current);
      if (energy.energy < current.energy) {
        output = std::move(candidate);
        kept = std::move(energy);
        accepted = true;
      }
    }
    const std::vector<int> sources = vote_attributes(exemplar_, output, current);
    if (sources != output.source) {
      const SearchResult& before = accepted ? kept : current;
      OutputSamples candidate =
          moved(output, std::vector<Vec3>(output.samples.size(), Vec3::Zero()), 0.0, sources,
                exemplar_, domain_);
      SearchResult energy = search(exemplar_, candidate, domain_, fixed, current);
      if (energy.energy < before.energy) {
        output = std::move(candidate);
        kept = std::move(energy);
        accepted = true;
      }
    }
    // The interleaved physics solver, after search and assignment.
    bool settled = false;
    if (physics_) {
      settled = physics_->settle(exemplar_, output, domain_, options_.orientation);
      if (settled) kept = search(exemplar_, output, domain_, fixed, accepted ? kept : current);
    }
    if (accepted || settled) {
      // Search: the next matches (the current ones among the candidates, so no increase).
      SearchResult next = search(exemplar_, output, domain_, settings_, kept);
      if (next.energy > kept.energy) next = std::move(kept);
      converged = std::abs(current.energy - next.energy) <= options_.tolerance * current.energy;
      current = std::move(next);
    }
    converged = converged || !(accepted || settled);
    ++done;
    result.trace.push_back({done, elements, current.energy});
    if (control.progress) control.progress(done, options_.iterations);
  }
  result.scene =
      reconstruct(exemplar_, output, domain_, options_.orientation, options_.reconstruction);
  // Eq. 6 is a soft constraint: elements the EM moved out of the domain are left out.
  const std::size_t before = result.scene.elements.size();
  auto& placed = result.scene.elements;
  placed.erase(
      std::remove_if(placed.begin(), placed.end(),
                     [&](const geometry::Element& e) { return inside(domain_, e.position) < 0.5; }),
      placed.end());
  result.record.set_domain(domain_);
  result.record.options = record_options();
  result.record.iterations = std::to_string(options_.iterations);
  result.record.steps = done;
  result.record.stationary = converged || done < options_.iterations;
  result.counters = {
      {"iterations", std::to_string(done) + "/" + std::to_string(options_.iterations)},
      {"energy", core::format_number(first_energy) + " -> " + core::format_number(current.energy)},
      {"samples", std::to_string(output.samples.size())},
      {"left outside the domain", std::to_string(before - result.scene.elements.size())}};
  return result;
}

}  // namespace shapeproc::methods
