#include "libshapeproc/fit/detail/existence_check.hpp"

#include <cmath>

namespace shapeproc::fit {

bool can_check_existence(double data_weight) {
  return data_weight > 0 && kExistenceFactor * data_weight < 1;
}

bool check_existence(const PseudoLikelihoodDesign& heavier, MpleResult& mple) {
  const MpleResult check = maximise_pseudo_likelihood(heavier, mple.theta);
  bool follows_share = false;
  for (std::size_t p = 0; p < mple.theta.size(); ++p) {
    if (mple.status[p] != model::ParameterStatus::free) continue;
    if (std::abs(check.theta[p] - mple.theta[p]) > kExistenceTolerance) {
      follows_share = true;
      mple.status[p] = model::ParameterStatus::unbounded;
    }
  }
  return follows_share;
}

void add_existence_notes(const MpleResult& mple, bool follows_share,
                         std::vector<std::string>& notes) {
  if (follows_share) {
    notes.push_back(
        "the pseudo-likelihood has no finite maximum without the data points' share of the "
        "quadrature: no region of the window offers another element the neighbourhoods the "
        "elements have (a packed exemplar, or one whose statistics are separated); the estimates "
        "follow that share (the fit's data weight), and parameters that move with it are marked "
        "unbounded");
  }
  bool unbounded = false;
  for (model::ParameterStatus status : mple.status)
    unbounded = unbounded || status == model::ParameterStatus::unbounded;
  if (unbounded && !follows_share) {
    notes.push_back(
        "some parameters have no finite maximum: the exemplar separates their statistics (for "
        "example every element of a category near another category); they stay at the search "
        "bound |log gamma| = 30 and are marked unbounded. Fewer bands (quantile orders), fewer "
        "directions or one category help.");
  }
}

}  // namespace shapeproc::fit
