#pragma once
// Piles stepped by the quality tests and by bench_bullet_adapter, built the same way for stock Bullet and gq:
// Bullet's BasicDemo (a 5x5x5 grid of boxes dropped on a ground box) and a 200-body mixed pile (boxes, spheres,
// capsules, cylinders, 30-vertex hulls) on a triangle-mesh ground; and the measures that say how well a scene
// comes to rest.
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "bullet_test_scene.h"

namespace gq::bullet::test {

struct PileScene {
  std::vector<btRigidBody*> bodies;  // the dynamic bodies
  btScalar groundY = 0;              // the ground's top surface
};

// Bullet's BasicDemo: 125 boxes of half extent 0.1 in a 5x5x5 grid (touching), released 2 m above a 50 m ground box.
inline PileScene basicDemoGrid(TestWorld& w, ShapeStore& store) {
  PileScene s;
  w.add(store.make<btBoxShape>(btVector3(50, 50, 50)), 0, btVector3(0, -50, 0));
  auto* box = store.make<btBoxShape>(btVector3(btScalar(0.1), btScalar(0.1), btScalar(0.1)));
  for (int k = 0; k < 5; ++k)
    for (int i = 0; i < 5; ++i)
      for (int j = 0; j < 5; ++j)
        s.bodies.push_back(w.add(box, 1, btVector3(btScalar(0.2 * i), btScalar(2 + 0.2 * k), btScalar(0.2 * j))));
  return s;
}

// A convex hull of `n` points on an ellipsoid of semi-axes `axes` (seeded: the same hull in every world).
inline btConvexHullShape* randomHull(ShapeStore& store, int n, const btVector3& axes, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g(0, 1);
  auto* hull = store.make<btConvexHullShape>();
  for (int i = 0; i < n; ++i) {
    btVector3 d(btScalar(g(rng)), btScalar(g(rng)), btScalar(g(rng)));
    d.normalize();
    hull->addPoint(d * axes, i + 1 == n);
  }
  return hull;
}

// 200 bodies (40 each of boxes, spheres, capsules, cylinders and 30-vertex hulls, ~0.5 m across) in 2 layers of
// 10x10, 1 m apart, released 0.6 m and 1.4 m above a flat triangle-mesh ground (24 x 24 m, 1 m quads) at y = 0; the
// upper layer is shifted by half a cell in x and z, so its bodies fall into the gaps of the lower layer (a body
// released exactly above an identical one balances on it and rolls off at a time set by round-off).
// Rolling friction keeps round bodies from rolling forever on the flat ground, in both worlds.
inline PileScene mixedPile(TestWorld& w, ShapeStore& store) {
  PileScene s;
  w.add(flatMesh(store, 25, 12, 0), 0, btVector3(0, 0, 0));
  btCollisionShape* shapes[5] = {
      store.make<btBoxShape>(btVector3(btScalar(0.25), btScalar(0.2), btScalar(0.15))),
      store.make<btSphereShape>(btScalar(0.25)),
      store.make<btCapsuleShape>(btScalar(0.15), btScalar(0.4)),
      store.make<btCylinderShape>(btVector3(btScalar(0.2), btScalar(0.25), btScalar(0.2))),
      randomHull(store, 30, btVector3(btScalar(0.3), btScalar(0.2), btScalar(0.25)), 11),
  };
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> angle(-3.14159, 3.14159);
  for (int i = 0; i < 200; ++i) {
    const int layer = i / 100, cell = i % 100;
    const double offset = 0.5 * layer;  // the upper layer over the gaps of the lower one, not balanced on its bodies
    const btVector3 at(btScalar(-4.5 + offset + (cell % 10)), btScalar(0.6 + 0.8 * layer),
                       btScalar(-4.5 + offset + (cell / 10)));
    const btQuaternion q(btVector3(btScalar(angle(rng)), 1, btScalar(angle(rng))).normalized(),
                         btScalar(angle(rng)));
    btRigidBody* b = w.add(shapes[i % 5], 1, at, q);
    b->setRollingFriction(btScalar(0.02));
    b->setSpinningFriction(btScalar(0.02));
    s.bodies.push_back(b);
  }
  return s;
}

// The largest linear speed of the scene's bodies.
inline btScalar maxSpeed(const PileScene& s) {
  btScalar v = 0;
  for (const btRigidBody* b : s.bodies) v = std::max(v, b->getLinearVelocity().length());
  return v;
}

// How far the lowest body reaches below the ground's top (0 when none does): each body's lowest point is its
// convex shape's support point (margin included) along -y. Resting bodies sink by the solver's allowed penetration.
inline btScalar deepestBelowGround(const PileScene& s) {
  btScalar below = 0;
  for (const btRigidBody* b : s.bodies) {
    const auto* shape = static_cast<const btConvexShape*>(b->getCollisionShape());
    const btTransform& t = b->getWorldTransform();
    const btVector3 down = btVector3(0, -1, 0) * t.getBasis();  // -y in the body frame
    const btScalar bottom = (t * shape->localGetSupportingVertex(down)).y();
    below = std::max(below, s.groundY - bottom);
  }
  return below;
}

}  // namespace gq::bullet::test
