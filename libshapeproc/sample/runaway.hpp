// A chain that runs away: a model whose attraction outweighs its repulsion on the domain sampled
// condenses, and its element count grows far past any density its exemplar showed. The sampler
// stops such a chain within seconds (SamplerOptions::runaway_count) instead of filling every gap
// for minutes, and says which interaction drives it.
#pragma once

#include <string>

#include "libshapeproc/model/shape_process_model.hpp"

namespace shapeproc::sample {

// The count past which an output expected to hold `expected` elements has run away:
// kRunawayFactor times it, and kRunawayMargin more at least (small outputs vary).
inline constexpr double kRunawayFactor = 8.0;
inline constexpr long long kRunawayMargin = 200;
long long runaway_count(double expected);

// The model's strongest attraction, "γ 1.45 between 'a' and 'b' at distances 3 to 7 (axis 1)", or
// an empty string when no γ is above 1.
std::string strongest_attraction(const model::ShapeProcessModel& model);

// Throws core::ArgumentError: the chain reached `count` elements, past `limit`.
[[noreturn]] void throw_runaway(const model::ShapeProcessModel& model, long long count,
                                long long limit);

}  // namespace shapeproc::sample
