// Layers of categories (docs/fit.md, "Layers"): decorations placed after their bases.
// A pairwise process places every category at once, and a pair's γ acts both ways: a decoration
// that must overlap a base's edge also lowers the intensity of a base where decorations already
// lie, so bases born late into a field of decorations are refused, and the rare bases die out.
// The multi-class disc synthesis of Ecormier-Nocca et al. 2019 orders its classes instead, each
// placed given the ones before. Here the order is read from the exemplar: category b lies a
// layer above category a when at least a given share of b's elements overlap or lie inside an
// element of a (a negative shape distance) and a's elements are the larger (median bounding
// radius). Points have no overlap: a category of points lies a layer above one with fewer points
// when every one of them lies within half that one's mean spacing of one of its points (under
// independence each would with probability 0.54), as visitors around hosts, and is anchored.
// The model of a layered exemplar is then a sequence of conditional processes:
//   layer 0 is a pairwise process of its own categories;
//   layer k, given the elements of layers below, is a pairwise process of its categories whose
//   intensity also counts the elements below, through the pairs' γ and hard cores;
// and its (pseudo-)likelihood is the product of the layers' conditional ones. The earlier layers
// never see the later ones (model::Interaction::sees). A category whose every element lies on a
// base (overlapping it, or apart by less than FitDefaults::anchor_slack of its radius) is
// anchored there: its intensity is 0 off its base, which the data say and a pairwise γ cannot
// (the pseudo-likelihood would send β to 0 and the overlap's γ to ∞).
#pragma once

#include <string>
#include <vector>

#include "libshapeproc/geometry/pair_measurements.hpp"
#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/model/shape_process_model.hpp"

namespace shapeproc::fit {

// One dependence found: `share` of the category's elements overlap or lie inside `base`'s, and
// the farthest of them from a base lies `farthest` from it (shape distance; ∞ when one has no
// base within the measured range).
struct LayerDependence {
  int category = 0, base = 0;
  double share = 0.0;
  double farthest = 0.0;
  double contact = 0.0;  // "on a base" means closer than this: 0 for shapes, a distance for points
};

// The dependences of `exemplar`'s categories at `share` or more (none above 1), each towards a
// category of larger median radius.
std::vector<LayerDependence> layer_dependences(const geometry::Scene& exemplar,
                                               const std::vector<geometry::PairRecord>& pairs,
                                               const geometry::PairMeasurer& measurer,
                                               double share);

// Sets each category's layer (one above the highest of its bases, 0 without) from the exemplar
// and returns a note per dependence for the fit's record.
std::vector<std::string> assign_layers(model::ShapeProcessModel& model,
                                       const geometry::Scene& exemplar,
                                       const std::vector<geometry::PairRecord>& pairs,
                                       const geometry::PairMeasurer& measurer, double share);

}  // namespace shapeproc::fit
