// The interleaved physics solver of Ma et al. 2011 (§5): after each iteration's search and
// assignment, a few steps of a rigid-body engine (5, as in their §6.2) push interpenetrating
// output elements apart, an implicit term the energy of eq. 2 does not hold. Off by default, as in
// the comparison of Landes et al. 2013 (§7.2).
//
// Each element is placed rigidly on its samples (rigid_placement), collides as its source's
// collision shape (collision_shapes.hpp), and its samples follow the rigid motion the engine gives
// it. Single-sample elements do not turn (a lone sample has no orientation to keep one). On a
// torus, the periodic images of the elements near the box's faces stand in the world as fixed
// ghosts, so that elements meet across the seam.
#pragma once

#include <vector>

#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/methods/common/em_exemplar.hpp"
#include "libshapeproc/methods/common/orientation_field.hpp"
#include "libshapeproc/methods/common/output_samples.hpp"
#include "libshapeproc/methods/physics/collision_shapes.hpp"

namespace shapeproc::methods {

inline constexpr int kPhysicsSubSteps = 5;

class InterleavedPhysics {
 public:
  // Collision shapes for every exemplar shape, sized for the engine by the elements' median
  // bounding-box diagonal.
  explicit InterleavedPhysics(const EmExemplar& exemplar, int sub_steps = kPhysicsSubSteps);

  // Moves the elements of `output` (and their samples) as the engine settles them; whether any
  // moved.
  bool settle(const EmExemplar& exemplar, OutputSamples& output, const geometry::Domain& domain,
              const OrientationField& orientation) const;

  double unit() const { return unit_; }
  const std::vector<CollisionShape>& shapes() const { return shapes_; }

 private:
  std::vector<CollisionShape> shapes_;  // per exemplar shape
  double unit_ = 1.0;
  double largest_radius_ = 0.0;
  int sub_steps_;
};

}  // namespace shapeproc::methods
