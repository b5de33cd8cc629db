// Interpenetrating elements pushed apart by a real rigid-body engine (Ma et al. 2011, §5, use
// Bullet): Box2D in 2D, Bullet in 3D. The bodies carry the elements' collision shapes at their
// rigid placements; the world has no gravity and no velocity survives a step (full damping), so
// that a step only resolves contacts: each overlap shrinks by the engine's position correction
// and bodies that touch nothing stay exactly where they are. Bodies marked fixed do not move
// (the ghosts that stand for a torus's periodic images); bodies that do not turn only move.
//
// Engines are tuned for bodies of about a metre: lengths are divided by `unit` (the elements'
// typical size) and taken relative to the bodies' mean position. What moves a body is read as
// the change of its engine position, so untouched bodies keep their placement to the last bit.
#pragma once

#include <vector>

#include "libshapeproc/methods/common/element_reconstruction.hpp"
#include "libshapeproc/methods/physics/collision_shapes.hpp"

namespace shapeproc::methods {

struct RigidBody {
  const CollisionShape* shape = nullptr;
  Similarity placement;  // rigid: local shape coordinates to the scene
  bool fixed = false;
  bool turns = true;  // false: the engine may only move it
};

// The bodies' placements after `steps` engine steps of 1/60 s.
std::vector<Similarity> settle_bodies_2d(const std::vector<RigidBody>& bodies, double unit,
                                         int steps);
std::vector<Similarity> settle_bodies_3d(const std::vector<RigidBody>& bodies, double unit,
                                         int steps);

}  // namespace shapeproc::methods
