// The collision configuration: pool element size, which pairs reach gq, and that hosts may still re-register.
#include <gtest/gtest.h>

#include <LinearMath/btPoolAllocator.h>

#include "bullet_test_scene.h"

namespace gq::bullet::test {
namespace {

TEST(BulletConfiguration, AlgorithmFitsDispatcherPoolElement) {
  CollisionConfiguration config;
  EXPECT_LE(contactAlgorithmSize(), std::size_t(config.getCollisionAlgorithmPool()->getElementSize()));
  btDefaultCollisionConstructionInfo small;
  small.m_customCollisionAlgorithmMaxElementSize = 8;
  CollisionConfiguration configured(small);
  EXPECT_LE(contactAlgorithmSize(), std::size_t(configured.getCollisionAlgorithmPool()->getElementSize()));
}

TEST(BulletConfiguration, RoutesModelledPairsAndKeepsBulletForOthers) {
  EXPECT_TRUE(CollisionConfiguration::routesToGq(SPHERE_SHAPE_PROXYTYPE, BOX_SHAPE_PROXYTYPE));
  EXPECT_TRUE(CollisionConfiguration::routesToGq(CONVEX_HULL_SHAPE_PROXYTYPE, TERRAIN_SHAPE_PROXYTYPE));
  EXPECT_TRUE(CollisionConfiguration::routesToGq(TRIANGLE_MESH_SHAPE_PROXYTYPE, CYLINDER_SHAPE_PROXYTYPE));
  EXPECT_TRUE(CollisionConfiguration::routesToGq(STATIC_PLANE_PROXYTYPE, CONE_SHAPE_PROXYTYPE));
  EXPECT_FALSE(CollisionConfiguration::routesToGq(TRIANGLE_MESH_SHAPE_PROXYTYPE, TERRAIN_SHAPE_PROXYTYPE));
  EXPECT_FALSE(CollisionConfiguration::routesToGq(COMPOUND_SHAPE_PROXYTYPE, SPHERE_SHAPE_PROXYTYPE));
  EXPECT_TRUE(CollisionConfiguration::routesToGq(MULTI_SPHERE_SHAPE_PROXYTYPE, BOX_SHAPE_PROXYTYPE));
  EXPECT_FALSE(CollisionConfiguration::routesToGq(CONVEX_POINT_CLOUD_SHAPE_PROXYTYPE, BOX_SHAPE_PROXYTYPE));

  CollisionConfiguration config;
  btDefaultCollisionConfiguration stock;
  // Unrouted pairs get exactly Bullet's algorithm; routed pairs get gq's.
  EXPECT_EQ(config.getCollisionAlgorithmCreateFunc(COMPOUND_SHAPE_PROXYTYPE, SPHERE_SHAPE_PROXYTYPE),
            config.bulletCreateFunc(COMPOUND_SHAPE_PROXYTYPE, SPHERE_SHAPE_PROXYTYPE, false));
  EXPECT_NE(config.getCollisionAlgorithmCreateFunc(SPHERE_SHAPE_PROXYTYPE, SPHERE_SHAPE_PROXYTYPE),
            config.bulletCreateFunc(SPHERE_SHAPE_PROXYTYPE, SPHERE_SHAPE_PROXYTYPE, false));
}

// A host that registers its own create function (or near callback) after construction keeps Bullet's behaviour.
TEST(BulletConfiguration, HostMayReRegisterCreateFuncsAndNearCallback) {
  CollisionConfiguration config;
  CollisionDispatcher dispatcher(&config);
  dispatcher.registerCollisionCreateFunc(SPHERE_SHAPE_PROXYTYPE, SPHERE_SHAPE_PROXYTYPE,
                                         config.bulletCreateFunc(SPHERE_SHAPE_PROXYTYPE, SPHERE_SHAPE_PROXYTYPE, false));
  static int calls = 0;
  calls = 0;
  dispatcher.setNearCallback([](btBroadphasePair& pair, btCollisionDispatcher& d, const btDispatcherInfo& info) {
    ++calls;
    btCollisionDispatcher::defaultNearCallback(pair, d, info);
  });
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &config);
  world.setGravity(btVector3(0, -10, 0));
  btSphereShape sphere(btScalar(0.5));
  btBoxShape ground(btVector3(5, 1, 5));
  btDefaultMotionState groundState(btTransform(btQuaternion::getIdentity(), btVector3(0, -1, 0)));
  btRigidBody groundBody(btRigidBody::btRigidBodyConstructionInfo(0, &groundState, &ground));
  btVector3 inertia;
  sphere.calculateLocalInertia(1, inertia);
  btDefaultMotionState ballState(btTransform(btQuaternion::getIdentity(), btVector3(0, 2, 0)));
  btRigidBody ball(btRigidBody::btRigidBodyConstructionInfo(1, &ballState, &sphere, inertia));
  world.addRigidBody(&groundBody);
  world.addRigidBody(&ball);
  for (int i = 0; i < 120; ++i) world.stepSimulation(btScalar(1) / 60, 10);
  EXPECT_GT(calls, 0);
  EXPECT_NEAR(ball.getWorldTransform().getOrigin().y(), 0.5, 0.02);  // rests on the box top (y = 0)
  world.removeRigidBody(&ball);
  world.removeRigidBody(&groundBody);
}

}  // namespace
}  // namespace gq::bullet::test
