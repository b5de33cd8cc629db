// How a chain of a fitted model starts from the empty configuration: its burn-in, chosen by the
// fit and kept in the model's record, so that every output, every check and every chain of the
// fit itself starts the same way (sample/compression.hpp has the mechanics, docs/sample.md "From
// empty" the reasons):
// - plain: birth-death moves at the model from the first step;
// - compressing: a packed exemplar's; the hard cores grow while births at an annealed β keep
//   every proposal that fits, then the boost is released;
// - crystal: a lattice exemplar's; the compressing burn-in whose births are proposed at the
//   exemplar's neighbour offsets from the first element on, so the lattice grows as a crystal.
#pragma once

#include <optional>
#include <string_view>

namespace shapeproc::model {

struct ShapeProcessModel;

enum class BurnIn { plain, compressing, crystal };

// "plain", "compressing", "crystal": the model file's names.
constexpr std::string_view burn_in_name(BurnIn burn_in) {
  switch (burn_in) {
    case BurnIn::compressing:
      return "compressing";
    case BurnIn::crystal:
      return "crystal";
    case BurnIn::plain:
      break;
  }
  return "plain";
}

// The burn-in of a name (also "none", the model files' name for plain); none for another name.
std::optional<BurnIn> parse_burn_in(std::string_view name);

// The burn-in outputs of `model` run: that of its maximum-likelihood chains, as its fit record
// says; plain for a model without one (the pseudo-likelihood's, or one written by hand).
BurnIn output_burn_in(const ShapeProcessModel& model);

}  // namespace shapeproc::model
