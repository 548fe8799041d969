// A pair whose relative pose stays within the reuse tolerance of its last exact frame keeps its manifold's points
// (each on the same two features, depth refreshed); a pair that moved further, or whose shape changed, gets its
// contacts recomputed. Checked on a box resting on a ground box through the pair's algorithm, called as Bullet's
// dispatcher calls it each frame.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h>

#include "bullet_test_scene.h"

namespace gq::bullet::test {
namespace {

const btScalar kTol = sizeof(btScalar) == 4 ? btScalar(5e-5) : btScalar(1e-9);
const btVector3 kHalf(btScalar(0.5), btScalar(0.5), btScalar(0.5));

// A unit box (A) resting 1 cm into the top face (y = 0) of a ground box (B), and gq's algorithm for the pair.
class RestingBox : public ::testing::Test {
 protected:
  RestingBox()
      : world_(Backend::Gq),
        box_(kHalf),
        ground_(btVector3(4, 1, 4)),
        wa_(nullptr, &box_, &a_, a_.getWorldTransform(), -1, -1),
        wb_(nullptr, &ground_, &b_, b_.getWorldTransform(), -1, -1) {
    a_.setCollisionShape(&box_);
    b_.setCollisionShape(&ground_);
    place(btTransform(btQuaternion(btVector3(0, 1, 0), btScalar(0.4)), btVector3(0, btScalar(0.49), 0)));
    b_.setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(0, -1, 0)));
    algorithm_ = world_.world().getDispatcher()->findAlgorithm(&wa_, &wb_, nullptr, BT_CONTACT_POINT_ALGORITHMS);
  }
  ~RestingBox() override {
    algorithm_->~btCollisionAlgorithm();
    world_.world().getDispatcher()->freeCollisionAlgorithm(algorithm_);
  }
  void place(const btTransform& t) { a_.setWorldTransform(t); }
  // One frame of the pair; the manifold after it.
  const btPersistentManifold& frame() {
    btManifoldResult result(&wa_, &wb_);
    algorithm_->processCollision(&wa_, &wb_, world_.world().getDispatchInfo(), &result);
    return *result.getPersistentManifold();
  }
  // Every point is a corner of A, its depth is the corner's height above the ground's top face (the exact answer
  // for a corner on a face), its normal is +y and its point on B lies on the face, under the corner within
  // `lateral` (a kept point stays where it was on B: up to the reuse tolerance away).
  void expectCornersOnTheGround(const btPersistentManifold& m, btScalar lateral = kTol) {
    ASSERT_EQ(m.getNumContacts(), 4);
    const bool aIsBody0 = m.getBody0() == &a_;
    for (int i = 0; i < m.getNumContacts(); ++i) {
      const btManifoldPoint& p = m.getContactPoint(i);
      const btVector3 onA = aIsBody0 ? p.getPositionWorldOnA() : p.getPositionWorldOnB();
      const btVector3 onB = aIsBody0 ? p.getPositionWorldOnB() : p.getPositionWorldOnA();
      const btVector3 local = a_.getWorldTransform().invXform(onA);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(std::abs(local[k]), kHalf[k], kTol) << "point " << i;
      EXPECT_NEAR(p.getDistance(), onA.y(), kTol) << "point " << i;
      EXPECT_NEAR(std::abs(p.m_normalWorldOnB.y()), 1, kTol) << "point " << i;
      EXPECT_NEAR(onB.y(), 0, kTol) << "point " << i;
      EXPECT_NEAR(onB.x(), onA.x(), lateral) << "point " << i;
      EXPECT_NEAR(onB.z(), onA.z(), lateral) << "point " << i;
    }
  }

  TestWorld world_;  // its configuration and dispatcher
  btBoxShape box_, ground_;
  btCollisionObject a_, b_;
  btCollisionObjectWrapper wa_, wb_;
  btCollisionAlgorithm* algorithm_ = nullptr;
};

TEST_F(RestingBox, ContactsKeptUnderSubToleranceMotionHaveExactDepths) {
  expectCornersOnTheGround(frame());
  // 0.1 mm sideways, 0.05 mm down and 0.1 mrad of tilt: within the tolerance (1e-3 of the box's size, 1e-3 rad).
  const btTransform start = a_.getWorldTransform();
  place(btTransform(btQuaternion(btVector3(1, 0, 0), btScalar(1e-4)), btVector3(btScalar(1e-4), btScalar(-5e-5), 0)) *
        start);
  expectCornersOnTheGround(frame(), btScalar(2e-4));
  place(start);
  expectCornersOnTheGround(frame());
}

TEST_F(RestingBox, PairMovedBeyondTheToleranceGetsFreshContacts) {
  expectCornersOnTheGround(frame());
  const btTransform start = a_.getWorldTransform();
  place(btTransform(btQuaternion(btVector3(0, 1, 0), btScalar(0.3)), btVector3(btScalar(0.3), btScalar(-0.004), 0)) *
        start);
  expectCornersOnTheGround(frame());
  // Tilted by 0.05 rad: one edge sinks, the points follow the new corners.
  place(btTransform(btQuaternion(btVector3(1, 0, 0), btScalar(0.05)), btVector3(0, 0, 0)) * start);
  const btPersistentManifold& m = frame();
  ASSERT_GE(m.getNumContacts(), 2);
  for (int i = 0; i < m.getNumContacts(); ++i) {
    const btManifoldPoint& p = m.getContactPoint(i);
    const btVector3 onA = m.getBody0() == &a_ ? p.getPositionWorldOnA() : p.getPositionWorldOnB();
    EXPECT_NEAR(p.getDistance(), onA.y(), kTol) << "point " << i;
  }
}

TEST_F(RestingBox, ShapeEditedInPlaceGetsFreshContacts) {
  expectCornersOnTheGround(frame());
  // Same poses, a box 2 % larger: its corners reach 1 cm deeper (the manifold's deepest point; Bullet's manifold
  // may keep an older point beside the new ones until its refresh drops it).
  box_.setLocalScaling(btVector3(btScalar(1.02), btScalar(1.02), btScalar(1.02)));
  const btPersistentManifold& m = frame();
  ASSERT_GE(m.getNumContacts(), 1);
  btScalar deepest = 0;
  for (int i = 0; i < m.getNumContacts(); ++i) deepest = std::min(deepest, m.getContactPoint(i).getDistance());
  EXPECT_NEAR(deepest, -0.02, kTol);
}


// A box above an empty spot of a BVH mesh has no contact; triangles added under it afterwards (new buffer contents
// and counts, so the mesh is cooked anew) reach the pair's existing algorithm on its next frame.
TEST(MeshSide, TrianglesAddedToTheMeshReachAnExistingPair) {
  TestWorld world(Backend::Gq);
  btBoxShape box(kHalf);
  btTriangleMesh triangles;
  triangles.addTriangle(btVector3(10, 0, 10), btVector3(11, 0, 10), btVector3(10, 0, 11));
  btBvhTriangleMeshShape mesh(&triangles, true);
  btCollisionObject a, b;
  a.setCollisionShape(&box);
  b.setCollisionShape(&mesh);
  a.setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(0, btScalar(0.49), 0)));
  btCollisionObjectWrapper wa(nullptr, &box, &a, a.getWorldTransform(), -1, -1);
  btCollisionObjectWrapper wb(nullptr, &mesh, &b, b.getWorldTransform(), -1, -1);
  btDispatcher* dispatcher = world.world().getDispatcher();
  btCollisionAlgorithm* algorithm = dispatcher->findAlgorithm(&wa, &wb, nullptr, BT_CONTACT_POINT_ALGORITHMS);
  const auto frame = [&]() -> const btPersistentManifold* {
    btManifoldResult result(&wa, &wb);
    algorithm->processCollision(&wa, &wb, world.world().getDispatchInfo(), &result);
    return result.getPersistentManifold();
  };
  const btPersistentManifold* before = frame();
  EXPECT_TRUE(before == nullptr || before->getNumContacts() == 0);
  triangles.addTriangle(btVector3(-2, 0, -2), btVector3(-2, 0, 2), btVector3(2, 0, -2));
  triangles.addTriangle(btVector3(2, 0, -2), btVector3(-2, 0, 2), btVector3(2, 0, 2));
  const btPersistentManifold* after = frame();
  ASSERT_NE(after, nullptr);
  ASSERT_GE(after->getNumContacts(), 1);
  btScalar deepest = 0;
  for (int i = 0; i < after->getNumContacts(); ++i) deepest = std::min(deepest, after->getContactPoint(i).getDistance());
  EXPECT_NEAR(deepest, -0.01, kTol);
  algorithm->~btCollisionAlgorithm();
  dispatcher->freeCollisionAlgorithm(algorithm);
}

}  // namespace
}  // namespace gq::bullet::test
