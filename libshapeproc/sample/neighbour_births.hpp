// Births near neighbours (docs/mathematics.md, "Births near neighbours"). A uniform birth
// proposal almost never finds the slot a packed exemplar leaves for the next element: a chain
// from empty then jams far below the exemplar's density. This proposal takes an element of the
// configuration (the anchor, uniformly), one of the offsets at which the exemplar showed a
// neighbour of the anchor's kind (model::NeighbourOffsets, by weight), and a position uniform in
// a ball around the anchor plus that offset (a radius of the model's, each as likely); the
// newborn has the neighbour's kind. The chain draws a birth from it with some probability, else
// uniformly, and divides the acceptance ratio by the mixture's density: the target density is
// the model's whatever the offsets say.
#pragma once

#include <memory>
#include <vector>

#include "libshapeproc/core/random.hpp"
#include "libshapeproc/model/shape_process_model.hpp"
#include "libshapeproc/sample/configuration.hpp"

namespace shapeproc::sample {

class NeighbourBirths {
 public:
  // Null when the model has no offsets, or when an offset of some kind the chain holds reaches
  // farther than `reach` (the neighbour grid's cell) or some kind has none left: then births are
  // uniform only.
  static std::unique_ptr<const NeighbourBirths> make(const model::ShapeProcessModel& model,
                                                     double reach);

  // A proposal around `anchor`: its category, shape and position (not yet wrapped).
  Element propose(const Element& anchor, core::Random& random) const;

  // The density at ξ of a proposal around an element of `configuration` chosen uniformly among
  // all but `skip` (−1: none), per unit measure and per (category, shape): q_near(ξ | x). 0 when
  // no element is left.
  double density(const Element& xi, const Configuration& configuration, int skip) const;

 private:
  struct Entry {
    int to_category = 0, to_shape = 0;
    Vec3 offset = Vec3::Zero();
    double probability = 0.0;
  };
  int kind(const Element& e) const { return by_shape_ ? e.shape : e.category; }

  std::vector<std::vector<Entry>> from_;         // per kind
  std::vector<std::vector<double>> cumulative_;  // per kind, of its entries' probabilities
  std::vector<double> radii_, ball_measure_;
  bool by_shape_ = true;
  int dimension_ = 2;
};

}  // namespace shapeproc::sample
