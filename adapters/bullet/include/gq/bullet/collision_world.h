#pragma once
// Bullet worlds whose scene queries go through gq, with Bullet's callback classes:
//  - rayTest: gq raycasts against every shape gq models (a hull's or cone's margin is honoured by sweeping a sphere
//    of that radius); other shapes (compounds and the shapes Bullet keeps, see docs/bullet.md) through Bullet's own
//    per-object test. Triangle meshes and heightfields are hit from both sides unless the callback's m_flags has
//    btTriangleRaycastCallback::kF_FilterBackfaces.
//  - convexSweepTest: gq sweeps (the cast shape keeps the `from` rotation; margins become a rounded inflation).
//    It hides btCollisionWorld::convexSweepTest (which is not virtual): call it through the gq world type.
//  - contactTest / contactPairTest: Bullet's own, whose closest-point algorithms the gq configuration provides.
// Use with gq::bullet::CollisionConfiguration / CollisionDispatcher for gq contacts as well.
#include <btBulletDynamicsCommon.h>

namespace gq::bullet {

class CollisionWorld : public btCollisionWorld {
 public:
  CollisionWorld(btDispatcher* dispatcher, btBroadphaseInterface* broadphase, btCollisionConfiguration* config)
      : btCollisionWorld(dispatcher, broadphase, config) {}
  void rayTest(const btVector3& rayFromWorld, const btVector3& rayToWorld,
               RayResultCallback& resultCallback) const override;
  void convexSweepTest(const btConvexShape* castShape, const btTransform& from, const btTransform& to,
                       ConvexResultCallback& resultCallback, btScalar allowedCcdPenetration = btScalar(0)) const;
};

class DiscreteDynamicsWorld : public btDiscreteDynamicsWorld {
 public:
  DiscreteDynamicsWorld(btDispatcher* dispatcher, btBroadphaseInterface* broadphase,
                        btConstraintSolver* solver, btCollisionConfiguration* config)
      : btDiscreteDynamicsWorld(dispatcher, broadphase, solver, config) {}
  void rayTest(const btVector3& rayFromWorld, const btVector3& rayToWorld,
               RayResultCallback& resultCallback) const override;
  void convexSweepTest(const btConvexShape* castShape, const btTransform& from, const btTransform& to,
                       ConvexResultCallback& resultCallback, btScalar allowedCcdPenetration = btScalar(0)) const;
};

// The per-world implementations, for hosts with their own btCollisionWorld subclass.
void gqRayTest(const btCollisionWorld& world, const btVector3& rayFromWorld, const btVector3& rayToWorld,
               btCollisionWorld::RayResultCallback& resultCallback);
void gqConvexSweepTest(const btCollisionWorld& world, const btConvexShape* castShape, const btTransform& from,
                       const btTransform& to, btCollisionWorld::ConvexResultCallback& resultCallback,
                       btScalar allowedCcdPenetration);

}  // namespace gq::bullet
