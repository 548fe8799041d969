// A box pair within the contact threshold but apart gets one speculative point only while the bodies approach: two
// boxes lying still side by side hand the solver no row, a box moving towards another gets the row that slows it
// before the faces meet.
#include <gtest/gtest.h>

#include "bullet_test_scene.h"

namespace gq::bullet::test {
namespace {

// Points in the manifold of the pair (a, b) after the last step (0 when the pair has none).
int pairPoints(btDiscreteDynamicsWorld& world, const btCollisionObject* a, const btCollisionObject* b) {
  btDispatcher* d = world.getDispatcher();
  for (int i = 0; i < d->getNumManifolds(); ++i) {
    const btPersistentManifold* m = d->getManifoldByIndexInternal(i);
    if ((m->getBody0() == a && m->getBody1() == b) || (m->getBody0() == b && m->getBody1() == a))
      return m->getNumContacts();
  }
  return 0;
}

// Two unit boxes, without gravity, their facing sides 5 mm apart (inside the contact threshold of ~3.5 cm); the
// left one moves towards the right one at `speed`.
struct BoxesApart {
  ShapeStore store;
  TestWorld w{Backend::Gq};
  btRigidBody *left, *right;
  explicit BoxesApart(btScalar speed) {
    w.world().setGravity(btVector3(0, 0, 0));
    auto* box = store.make<btBoxShape>(btVector3(0.5, 0.5, 0.5));
    left = w.add(box, 1, btVector3(btScalar(-0.5025), 0, 0));
    right = w.add(box, 1, btVector3(btScalar(0.5025), 0, 0));
    left->setLinearVelocity(btVector3(speed, 0, 0));
  }
  btScalar gap() const {
    return right->getWorldTransform().getOrigin().x() - left->getWorldTransform().getOrigin().x() - 1;
  }
};

TEST(BulletSpeculativePoints, BoxesLyingStillApartGetNoPoint) {
  BoxesApart s(0);
  s.w.step(3);
  EXPECT_EQ(pairPoints(s.w.world(), s.left, s.right), 0);
  EXPECT_NEAR(s.gap(), 0.005, 1e-6);
}

// At 1 m/s the left box would travel 16.7 mm in the step: it gets the speculative point (apart by the gap) and the
// solver slows it before the faces meet (without a point it would end 11.7 mm into the right box).
TEST(BulletSpeculativePoints, ApproachingBoxGetsAPointBeforeTheFacesMeet) {
  BoxesApart s(1);
  s.w.step(1);
  btDispatcher* d = s.w.world().getDispatcher();
  ASSERT_EQ(d->getNumManifolds(), 1);
  const btPersistentManifold* m = d->getManifoldByIndexInternal(0);
  ASSERT_EQ(m->getNumContacts(), 1);
  EXPECT_NEAR(m->getContactPoint(0).getDistance(), 0.005, 1e-5);
  EXPECT_LT(s.left->getLinearVelocity().x(), btScalar(0.95));
  EXPECT_GT(s.gap(), btScalar(-0.0117) + btScalar(1e-3));
}

}  // namespace
}  // namespace gq::bullet::test
