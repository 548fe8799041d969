// The adapter's only shared state is the cooked-shape cache: worlds on several threads sharing one hull and one
// mesh shape get the same contacts as one thread (Debian's Bullet has no parallel task scheduler, so this is how
// btCollisionDispatcherMt's concurrency reaches the adapter).
#include <gtest/gtest.h>

#include <thread>

#include "bullet_test_scene.h"

namespace gq::bullet::test {
namespace {

struct DeepestDistance : btCollisionWorld::ContactResultCallback {
  btScalar distance = BT_LARGE_FLOAT;
  btScalar addSingleResult(btManifoldPoint& cp, const btCollisionObjectWrapper*, int, int,
                           const btCollisionObjectWrapper*, int, int) override {
    distance = std::min(distance, cp.getDistance());
    return 0;
  }
};

// Deepest distances of a hull dropped at a few heights onto the shared mesh, in a world of the calling thread.
std::vector<btScalar> hullOnMesh(btCollisionShape* hull, btCollisionShape* mesh) {
  CollisionConfiguration config;
  CollisionDispatcher dispatcher(&config);
  btDbvtBroadphase broadphase;
  CollisionWorld world(&dispatcher, &broadphase, &config);
  btCollisionObject ground, body;
  ground.setCollisionShape(mesh);
  body.setCollisionShape(hull);
  world.addCollisionObject(&ground);
  world.addCollisionObject(&body);
  std::vector<btScalar> out;
  for (int i = 0; i < 50; ++i) {
    body.setWorldTransform(btTransform(btQuaternion(btVector3(0, 1, 0), btScalar(0.1 * i)),
                                       btVector3(btScalar(0.05 * i), btScalar(0.9 + 0.002 * i), 0)));
    DeepestDistance cb;
    world.contactPairTest(&body, &ground, cb);
    out.push_back(cb.distance);
  }
  world.removeCollisionObject(&body);
  world.removeCollisionObject(&ground);
  return out;
}

TEST(BulletThreads, WorldsOnFourThreadsShareCookedShapes) {
  ShapeStore store;
  btConvexHullShape* hull = cubeHull(store, btScalar(0.4));
  btBvhTriangleMeshShape* mesh = flatMesh(store, 9, 4, btScalar(0.5));
  clearShapeCache();  // every thread races to cook the same two shapes
  std::vector<std::vector<btScalar>> results(4);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) threads.emplace_back([&, t] { results[std::size_t(t)] = hullOnMesh(hull, mesh); });
  for (auto& th : threads) th.join();
  const std::vector<btScalar> single = hullOnMesh(hull, mesh);
  for (const auto& r : results) EXPECT_EQ(r, single);
  // The closed form at the first pose: hull bottom 0.9 - 0.4 - margin 0.04 above the floor at 0.5.
  EXPECT_NEAR(single.front(), -0.04, sizeof(btScalar) == 4 ? 5e-5 : 1e-9);
}

}  // namespace
}  // namespace gq::bullet::test
