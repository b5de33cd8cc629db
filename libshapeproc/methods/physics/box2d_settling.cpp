// settle_bodies_2d (rigid_body_settling.hpp) on Box2D: one body per element, one polygon fixture
// per collision triangle; Box2D's position solver pushes overlapping fixtures apart.
#include <box2d/box2d.h>

#include <cmath>

#include "libshapeproc/methods/physics/detail/rigid_body_settling.hpp"

namespace shapeproc::methods {

namespace {

constexpr float kStep = 1.0f / 60.0f;
constexpr int kVelocityIterations = 8, kPositionIterations = 3;

geometry::Vec3 mean_position(const std::vector<RigidBody>& bodies) {
  geometry::Vec3 sum = geometry::Vec3::Zero();
  for (const RigidBody& b : bodies) sum += b.placement.translation;
  return bodies.empty() ? sum : sum / static_cast<double>(bodies.size());
}

// A triangle as a Box2D polygon, or false when Box2D would not keep its three corners.
bool polygon_of(const std::array<geometry::Vec2, 3>& t, double scale, b2PolygonShape& polygon) {
  b2Vec2 corners[3];
  for (std::size_t k = 0; k < 3; ++k)
    corners[k].Set(static_cast<float>(t[k].x() * scale), static_cast<float>(t[k].y() * scale));
  for (std::size_t k = 0; k < 3; ++k)
    if (b2DistanceSquared(corners[k], corners[(k + 1) % 3]) <
        (2.0f * b2_linearSlop) * (2.0f * b2_linearSlop))
      return false;
  polygon.Set(corners, 3);
  return polygon.m_count == 3;
}

b2Body* add_body(b2World& world, const RigidBody& body, const geometry::Vec3& origin,
                 double scale) {
  b2BodyDef def;
  def.type = body.fixed ? b2_staticBody : b2_dynamicBody;
  const geometry::Vec3 at = (body.placement.translation - origin) * scale;
  def.position.Set(static_cast<float>(at.x()), static_cast<float>(at.y()));
  def.angle =
      static_cast<float>(std::atan2(body.placement.linear(1, 0), body.placement.linear(0, 0)));
  def.linearDamping = def.angularDamping = 0.0f;
  def.allowSleep = false;
  def.fixedRotation = !body.turns;
  b2Body* b = world.CreateBody(&def);
  for (const auto& triangle : body.shape->triangles) {
    b2PolygonShape polygon;
    if (!polygon_of(triangle, scale, polygon)) continue;
    b2FixtureDef fixture;
    fixture.shape = &polygon;
    fixture.density = 1.0f;
    fixture.friction = 0.0f;
    fixture.restitution = 0.0f;
    b->CreateFixture(&fixture);
  }
  return b;
}

}  // namespace

std::vector<Similarity> settle_bodies_2d(const std::vector<RigidBody>& bodies, double unit,
                                         int steps) {
  const double scale = 1.0 / unit;
  const geometry::Vec3 origin = mean_position(bodies);
  b2World world(b2Vec2(0.0f, 0.0f));
  std::vector<b2Body*> handles;
  std::vector<b2Vec2> start;
  std::vector<float> start_angle;
  for (const RigidBody& body : bodies) {
    handles.push_back(add_body(world, body, origin, scale));
    start.push_back(handles.back()->GetPosition());
    start_angle.push_back(handles.back()->GetAngle());
  }
  for (int s = 0; s < steps; ++s) {
    world.Step(kStep, kVelocityIterations, kPositionIterations);
    // No velocity survives a step: only the overlaps move bodies.
    for (b2Body* b : handles) {
      b->SetLinearVelocity(b2Vec2(0.0f, 0.0f));
      b->SetAngularVelocity(0.0f);
    }
  }
  std::vector<Similarity> placed;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    Similarity p = bodies[i].placement;
    const b2Vec2 moved = handles[i]->GetPosition() - start[i];
    const double turned = static_cast<double>(handles[i]->GetAngle() - start_angle[i]);
    // Box2D turns a body about its centre of mass and reports where its origin went.
    if (moved.x != 0.0f || moved.y != 0.0f || turned != 0.0) {
      Eigen::Matrix3d turn = Eigen::Matrix3d::Identity();
      turn.topLeftCorner<2, 2>() = Eigen::Rotation2Dd(turned).toRotationMatrix();
      p.linear = turn * p.linear;
      p.translation +=
          geometry::Vec3(static_cast<double>(moved.x), static_cast<double>(moved.y), 0.0) * unit;
    }
    placed.push_back(p);
  }
  return placed;
}

}  // namespace shapeproc::methods
