// How well stepped scenes come to rest with gq's contacts: the 10-box stack against stock Bullet stepping the same
// world, Bullet's BasicDemo box grid, 30-vertex hulls and a 200-body mixed pile on a triangle-mesh ground (how deep
// they rest), and a box resting on a box face gets 4 contacts at its corners (the clipping itself:
// tests/core/contact_set_clipping_test.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "pile_scenes.h"

namespace gq::bullet::test {
namespace {

// The contacts a pair's manifold holds after a step.
int manifoldContacts(btDiscreteDynamicsWorld& world, const btCollisionObject* a, const btCollisionObject* b,
                     std::vector<btVector3>& pointsOnA) {
  btDispatcher* d = world.getDispatcher();
  for (int i = 0; i < d->getNumManifolds(); ++i) {
    btPersistentManifold* m = d->getManifoldByIndexInternal(i);
    if (!((m->getBody0() == a && m->getBody1() == b) || (m->getBody0() == b && m->getBody1() == a))) continue;
    for (int k = 0; k < m->getNumContacts(); ++k)
      pointsOnA.push_back(m->getBody0() == a ? m->getContactPoint(k).getPositionWorldOnA()
                                             : m->getContactPoint(k).getPositionWorldOnB());
    return m->getNumContacts();
  }
  return 0;
}

TEST(BulletRestQuality, BoxRestingOnABoxFaceHasFourContactsAtItsCorners) {
  ShapeStore store;
  TestWorld w(Backend::Gq);
  w.add(store.make<btBoxShape>(btVector3(2, 1, 2)), 0, btVector3(0, -1, 0));
  btRigidBody* box = w.add(store.make<btBoxShape>(btVector3(0.5, 0.25, 0.4)), 1, btVector3(0, btScalar(0.25), 0),
                           btQuaternion(btVector3(0, 1, 0), btScalar(0.4)));
  w.step(30);
  std::vector<btVector3> points;
  ASSERT_EQ(manifoldContacts(w.world(), box, w.world().getCollisionObjectArray()[0], points), 4);
  const btTransform t = box->getWorldTransform();
  for (const btVector3& p : points) {
    const btVector3 local = t.invXform(p);
    EXPECT_NEAR(std::abs(local.x()), 0.5, 1e-3);
    EXPECT_NEAR(local.y(), -0.25, 1e-3);
    EXPECT_NEAR(std::abs(local.z()), 0.4, 1e-3);
  }
}

// The stack's boxes each rest on the one below at the spacing stock Bullet gives them. Both worlds let each
// contact sink by the solver's resting penetration (up to ~3 mm per box here, the same boxes in both), so the
// spacings are compared with stock Bullet's, within 0.1 mm, and with the exact size, within 5 mm.
TEST(BulletRestQuality, StackRestsAsStockAndNoFaster) {
  btScalar speed[2] = {0, 0};
  std::vector<btScalar> spacing[2];
  for (Backend backend : {Backend::Bullet, Backend::Gq}) {
    ShapeStore store;
    TestWorld w(backend);
    w.add(store.make<btBoxShape>(btVector3(20, 1, 20)), 0, btVector3(0, -1, 0));
    auto* box = store.make<btBoxShape>(btVector3(0.5, 0.5, 0.5));
    PileScene s;
    for (int i = 0; i < 10; ++i) s.bodies.push_back(w.add(box, 1, btVector3(0, btScalar(0.5 + i), 0)));
    w.step(300);
    speed[int(backend)] = maxSpeed(s);
    btScalar below = 0;
    for (int i = 0; i < 10; ++i) {
      const btScalar y = s.bodies[i]->getWorldTransform().getOrigin().y();
      spacing[int(backend)].push_back(y - below);
      below = y;
    }
    if (backend == Backend::Gq) {
      EXPECT_LT(deepestBelowGround(s), btScalar(1e-3));
    }
  }
  for (int i = 0; i < 10; ++i) {
    EXPECT_NEAR(spacing[1][i], spacing[0][i], 1e-4) << "box " << i;
    EXPECT_NEAR(spacing[1][i], i == 0 ? 0.5 : 1.0, 5e-3) << "box " << i;
  }
  EXPECT_LE(speed[1], speed[0] + btScalar(1e-3));
}

// Hulls dropped on a triangle-mesh ground at rest: each one's lowest point (the exact support point of its hull
// along -y at its pose, margin included; the ground's top is y = 0) lies within 1 mm of the ground. A resting contact
// sinks by the solver's resting penetration only (0.3 mm for the stack's lowest box, the same solver and step); a
// supporting vertex missing from the manifold lets the hull sink by several mm.
TEST(BulletRestQuality, HullsRestingOnAMeshSinkNoMoreThanTheRestingPenetration) {
  ShapeStore store;
  TestWorld w(Backend::Gq);
  w.add(flatMesh(store, 25, 12, 0), 0, btVector3(0, 0, 0));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> angle(-3.14159, 3.14159), offset(0, 1);
  PileScene s;
  for (int i = 0; i < 25; ++i) {
    auto* hull = randomHull(store, 30, btVector3(btScalar(0.3), btScalar(0.2), btScalar(0.25)), unsigned(100 + i));
    // Over a different place of the ground's 1 m quads each (vertices near the triangles' shared edges).
    const btVector3 at(btScalar(-8 + 4 * (i % 5) + offset(rng)), btScalar(0.5),
                       btScalar(-8 + 4 * (i / 5) + offset(rng)));
    const btQuaternion q(btVector3(btScalar(angle(rng)), 1, btScalar(angle(rng))).normalized(), btScalar(angle(rng)));
    btRigidBody* b = w.add(hull, 1, at, q);
    b->setRollingFriction(btScalar(0.02));
    s.bodies.push_back(b);
  }
  w.step(300);
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    PileScene one;
    one.bodies = {s.bodies[i]};
    EXPECT_LT(deepestBelowGround(one), btScalar(1e-3)) << "hull " << i;
  }
  EXPECT_LT(maxSpeed(s), btScalar(0.01));
}

// A pile after 5 s: nothing fell through the ground (the lowest point of every body within 2 cm of the ground's
// top: the smallest body is 20 cm across) and at least 95 % of the bodies rest (slower than 0.1 m/s).
void checkPile(PileScene (*build)(TestWorld&, ShapeStore&)) {
  ShapeStore store;
  TestWorld w(Backend::Gq);
  const PileScene s = build(w, store);
  w.step(300);
  EXPECT_LT(deepestBelowGround(s), btScalar(0.02));
  std::size_t moving = 0;
  for (const btRigidBody* b : s.bodies) moving += b->getLinearVelocity().length() >= btScalar(0.1);
  EXPECT_LE(moving * 20, s.bodies.size()) << moving << " of " << s.bodies.size() << " bodies still move";
}

TEST(BulletRestQuality, BoxGridPileComesToRest) { checkPile(basicDemoGrid); }
TEST(BulletRestQuality, MixedPileComesToRest) { checkPile(mixedPile); }

// The mixed pile (its upper layer falls into the gaps of the lower one, so no body balances on another and rolls
// off late) is at rest after 5 s in both worlds: its fastest body then is no faster with gq than with stock Bullet,
// and slower than 1 cm/s.
TEST(BulletRestQuality, MixedPileIsAtRestAfterFiveSecondsNoFasterThanStock) {
  btScalar speed[2] = {0, 0};
  for (Backend backend : {Backend::Bullet, Backend::Gq}) {
    ShapeStore store;
    TestWorld w(backend);
    const PileScene s = mixedPile(w, store);
    w.step(300);
    speed[int(backend)] = maxSpeed(s);
  }
  EXPECT_LE(speed[1], speed[0] + btScalar(1e-3)) << "stock " << speed[0];
  EXPECT_LT(speed[1], btScalar(0.01));
}

// The mixed pile at rest after 5 s: its lowest point lies within 1 mm of the ground's top (exact: every body's
// support point along -y at y = 0). Each resting contact sinks by the solver's resting penetration only (0.3 mm for
// the stack's lowest box, the same solver and step); a body's deepest point missing from its manifold lets it sink
// by several mm.
TEST(BulletRestQuality, MixedPileSinksNoMoreThanTheRestingPenetration) {
  ShapeStore store;
  TestWorld w(Backend::Gq);
  const PileScene s = mixedPile(w, store);
  w.step(300);
  EXPECT_LT(deepestBelowGround(s), btScalar(1e-3));
}

}  // namespace
}  // namespace gq::bullet::test
