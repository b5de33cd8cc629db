#include "libshapeproc/methods/physics/interleaved_physics.hpp"

#include <algorithm>

#include "libshapeproc/methods/common/element_reconstruction.hpp"
#include "libshapeproc/methods/physics/detail/rigid_body_settling.hpp"

namespace shapeproc::methods {

namespace {

// The median bounding-box diagonal of the exemplar's elements (1 when they are all points).
double typical_size(const geometry::Scene& scene) {
  std::vector<double> diagonals;
  for (const geometry::Element& e : scene.elements) {
    const double d =
        geometry::bounding_box(scene.shapes[static_cast<std::size_t>(e.shape)]).sizes().norm();
    if (d > 0.0) diagonals.push_back(d);
  }
  if (diagonals.empty()) return 1.0;
  std::nth_element(diagonals.begin(), diagonals.begin() + diagonals.size() / 2, diagonals.end());
  return diagonals[diagonals.size() / 2];
}

// Ghosts of `body` (a copy: `bodies` may move while they are added) at its periodic images that
// come within `reach` of the box.
void add_ghosts(RigidBody body, const geometry::Domain& domain, double reach,
                std::vector<RigidBody>& bodies) {
  const int dim = domain.dimension();
  const geometry::Box3& box = domain.box();
  const Vec3 period = domain.period();
  const int images = dim == 3 ? 27 : 9;
  for (int code = 0; code < images; ++code) {
    const Vec3 k(code % 3 - 1, (code / 3) % 3 - 1, dim == 3 ? code / 9 - 1 : 0);
    if (k.isZero()) continue;
    const Vec3 at = body.placement.translation + k.cwiseProduct(period);
    bool near = true;
    for (int a = 0; a < dim; ++a)
      near = near && at[a] >= box.min()[a] - reach && at[a] <= box.max()[a] + reach;
    if (!near) continue;
    RigidBody& ghost = bodies.emplace_back(body);
    ghost.placement.translation = at;
    ghost.fixed = true;
  }
}

}  // namespace

InterleavedPhysics::InterleavedPhysics(const EmExemplar& exemplar, int sub_steps)
    : unit_(typical_size(exemplar.scene)), sub_steps_(sub_steps) {
  for (const geometry::Shape& shape : exemplar.scene.shapes) {
    shapes_.push_back(collision_shape(shape, 0.01 * unit_));
    largest_radius_ = std::max(largest_radius_, shapes_.back().radius);
  }
}

bool InterleavedPhysics::settle(const EmExemplar& exemplar, OutputSamples& output,
                                const geometry::Domain& domain,
                                const OrientationField& orientation) const {
  std::vector<RigidBody> bodies;
  for (std::size_t e = 0; e < output.elements(); ++e) {
    const int shape = exemplar.scene.elements[static_cast<std::size_t>(output.source[e])].shape;
    RigidBody body;
    body.shape = &shapes_[static_cast<std::size_t>(shape)];
    body.placement = rigid_placement(exemplar, output, e, domain, orientation);
    body.turns = output.samples.count_of(static_cast<int>(e)) > 1;
    bodies.push_back(body);
  }
  const std::size_t elements = bodies.size();
  if (domain.periodic())
    for (std::size_t e = 0; e < elements; ++e)
      add_ghosts(bodies[e], domain, 2.0 * largest_radius_, bodies);
  const std::vector<Similarity> placed = domain.dimension() == 3
                                             ? settle_bodies_3d(bodies, unit_, sub_steps_)
                                             : settle_bodies_2d(bodies, unit_, sub_steps_);
  ElementSamples& samples = output.samples;
  bool moved = false;
  for (std::size_t e = 0; e < elements; ++e) {
    const Similarity& before = bodies[e].placement;
    const Similarity& after = placed[e];
    if (after.translation == before.translation && after.linear == before.linear) continue;
    // The engine's rigid motion after ∘ before⁻¹, applied to the samples unwrapped near the body.
    moved = true;
    const Eigen::Matrix3d turn = after.linear * before.linear.transpose();
    for (int s = samples.first[e]; s < samples.first[e + 1]; ++s) {
      Vec3& p = samples.positions[static_cast<std::size_t>(s)];
      const Vec3 local = domain.minimum_image(p - before.translation);
      p = domain.wrap(after.translation + turn * local);
    }
  }
  return moved;
}

}  // namespace shapeproc::methods
