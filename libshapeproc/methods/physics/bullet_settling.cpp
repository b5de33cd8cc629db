// settle_bodies_3d (rigid_body_settling.hpp) on Bullet: one body per element whose shape is the
// convex hull of its proxy's vertices; overlaps are resolved by split impulses (position-only
// corrections), so bodies gain no velocity from them.
#include <btBulletDynamicsCommon.h>

#include <Eigen/SVD>
#include <memory>

#include "libshapeproc/methods/physics/detail/rigid_body_settling.hpp"

namespace shapeproc::methods {

namespace {

constexpr btScalar kStep = 1.0f / 60.0f;
constexpr btScalar kMargin = 0.01f;  // collision margin, in engine metres

btTransform to_engine(const Similarity& placement, const geometry::Vec3& origin, double scale) {
  btMatrix3x3 basis;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) basis[r][c] = static_cast<btScalar>(placement.linear(r, c));
  const geometry::Vec3 at = (placement.translation - origin) * scale;
  return btTransform(basis, btVector3(static_cast<btScalar>(at.x()), static_cast<btScalar>(at.y()),
                                      static_cast<btScalar>(at.z())));
}

struct World {
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
  std::vector<std::unique_ptr<btConvexHullShape>> shapes;
  std::vector<std::unique_ptr<btDefaultMotionState>> states;
  std::vector<std::unique_ptr<btRigidBody>> bodies;

  World() {
    world.setGravity(btVector3(0, 0, 0));
    btContactSolverInfo& info = world.getSolverInfo();
    info.m_splitImpulse = true;
    info.m_splitImpulsePenetrationThreshold = 0;  // every overlap by position correction only
  }
  ~World() {
    for (auto& b : bodies) world.removeRigidBody(b.get());
  }
  World(const World&) = delete;
  World& operator=(const World&) = delete;
};

}  // namespace

std::vector<Similarity> settle_bodies_3d(const std::vector<RigidBody>& bodies, double unit,
                                         int steps) {
  const double scale = 1.0 / unit;
  geometry::Vec3 origin = geometry::Vec3::Zero();
  for (const RigidBody& b : bodies) origin += b.placement.translation;
  if (!bodies.empty()) origin /= static_cast<double>(bodies.size());
  World w;
  std::vector<btRigidBody*> handles;
  for (const RigidBody& body : bodies) {
    auto shape = std::make_unique<btConvexHullShape>();
    for (const geometry::Vec3& p : body.shape->hull_points)
      shape->addPoint(
          btVector3(static_cast<btScalar>(p.x() * scale), static_cast<btScalar>(p.y() * scale),
                    static_cast<btScalar>(p.z() * scale)),
          false);
    shape->recalcLocalAabb();
    shape->setMargin(kMargin);
    const btScalar mass = body.fixed || body.shape->hull_points.empty() ? 0.0f : 1.0f;
    btVector3 inertia(0, 0, 0);
    if (mass > 0) shape->calculateLocalInertia(mass, inertia);
    auto state = std::make_unique<btDefaultMotionState>(to_engine(body.placement, origin, scale));
    btRigidBody::btRigidBodyConstructionInfo info(mass, state.get(), shape.get(), inertia);
    info.m_friction = 0;
    info.m_restitution = 0;
    auto rigid = std::make_unique<btRigidBody>(info);
    rigid->setActivationState(DISABLE_DEACTIVATION);
    if (!body.turns) rigid->setAngularFactor(0);
    if (body.shape->hull_points.empty())
      rigid->setCollisionFlags(rigid->getCollisionFlags() |
                               btCollisionObject::CF_NO_CONTACT_RESPONSE);
    w.world.addRigidBody(rigid.get());
    handles.push_back(rigid.get());
    w.shapes.push_back(std::move(shape));
    w.states.push_back(std::move(state));
    w.bodies.push_back(std::move(rigid));
  }
  std::vector<btTransform> start;
  for (btRigidBody* b : handles) start.push_back(b->getWorldTransform());
  for (int s = 0; s < steps; ++s) {
    w.world.stepSimulation(kStep, 0);
    for (btRigidBody* b : handles) {
      b->setLinearVelocity(btVector3(0, 0, 0));
      b->setAngularVelocity(btVector3(0, 0, 0));
    }
  }
  std::vector<Similarity> placed;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    Similarity p = bodies[i].placement;
    const btTransform& now = handles[i]->getWorldTransform();
    const btVector3 moved = now.getOrigin() - start[i].getOrigin();
    const btMatrix3x3 turned = now.getBasis() * start[i].getBasis().transpose();
    if (!(now.getOrigin() == start[i].getOrigin()) || !(now.getBasis() == start[i].getBasis())) {
      Eigen::Matrix3d turn;
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) turn(r, c) = static_cast<double>(turned[r][c]);
      // Re-orthonormalise the float rotation before it turns a double placement.
      const Eigen::JacobiSVD<Eigen::Matrix3d> svd(turn, Eigen::ComputeFullU | Eigen::ComputeFullV);
      turn = svd.matrixU() * svd.matrixV().transpose();
      p.linear = turn * p.linear;
      p.translation +=
          geometry::Vec3(static_cast<double>(moved.x()), static_cast<double>(moved.y()),
                         static_cast<double>(moved.z())) *
          unit;
    }
    placed.push_back(p);
  }
  return placed;
}

}  // namespace shapeproc::methods
