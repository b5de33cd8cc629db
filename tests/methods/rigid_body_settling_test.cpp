#include "libshapeproc/methods/physics/detail/rigid_body_settling.hpp"

#include <gtest/gtest.h>

#include "tests/geometry/measurement_fixtures.hpp"

namespace shapeproc::methods {
namespace {

namespace fx = geometry::fixtures;

RigidBody at(const CollisionShape& shape, const Vec3& position, bool fixed = false) {
  RigidBody body;
  body.shape = &shape;
  body.placement.translation = position;
  body.fixed = fixed;
  return body;
}

// Two unit squares overlapping by 0.3 along x, and one far away.
TEST(RigidBodySettling, Box2dPushesOverlapsApartAndLeavesTheRestAlone) {
  const CollisionShape square = collision_shape(fx::planar({fx::rectangle(-5, -5, 5, 5)}), 0.1);
  const std::vector<RigidBody> bodies = {at(square, Vec3(100, 50, 0)), at(square, Vec3(107, 50, 0)),
                                         at(square, Vec3(200, 200, 0))};
  const std::vector<Similarity> placed = settle_bodies_2d(bodies, 10.0, 20);
  const double gap = placed[1].translation.x() - placed[0].translation.x();
  EXPECT_GE(gap, 10.0);  // no overlap left
  EXPECT_LT(gap, 10.5);  // pushed apart, not thrown
  // Equal bodies share the correction.
  EXPECT_NEAR(placed[0].translation.x() + placed[1].translation.x(), 207.0, 0.05);
  // The squares' triangulated contact may slide them sideways a little (under 5% of the side).
  EXPECT_NEAR(placed[0].translation.y(), 50.0, 0.5);
  // Untouched: to the last bit.
  EXPECT_EQ(placed[2].translation, bodies[2].placement.translation);
  EXPECT_EQ(placed[2].linear, bodies[2].placement.linear);
}

TEST(RigidBodySettling, FixedBodiesDoNotMove) {
  const CollisionShape square = collision_shape(fx::planar({fx::rectangle(-5, -5, 5, 5)}), 0.1);
  const std::vector<RigidBody> bodies = {at(square, Vec3(0, 0, 0), true),
                                         at(square, Vec3(6, 0, 0))};
  const std::vector<Similarity> placed = settle_bodies_2d(bodies, 10.0, 20);
  EXPECT_EQ(placed[0].translation, Vec3(0, 0, 0));
  EXPECT_GE(placed[1].translation.x(), 10.0);
}

TEST(RigidBodySettling, BulletPushesOverlappingSolidsApart) {
  const geometry::Shape cube{
      geometry::MeshShape{fx::box_mesh(geometry::Vec3(-5, -5, -5), geometry::Vec3(5, 5, 5))}, ""};
  const CollisionShape shape = collision_shape(cube, 0.1);
  const std::vector<RigidBody> bodies = {at(shape, Vec3(0, 0, 0)), at(shape, Vec3(8, 0, 0)),
                                         at(shape, Vec3(50, 50, 50))};
  const std::vector<Similarity> placed = settle_bodies_3d(bodies, 10.0, 20);
  const double gap = placed[1].translation.x() - placed[0].translation.x();
  EXPECT_GE(gap, 9.9);  // within Bullet's collision margin of touching
  EXPECT_LT(gap, 10.5);
  EXPECT_EQ(placed[2].translation, bodies[2].placement.translation);
}

}  // namespace
}  // namespace shapeproc::methods
