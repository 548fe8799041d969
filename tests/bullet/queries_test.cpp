// rayTest, convexSweepTest and contactTest of the gq world against closed forms and against stock Bullet, on
// shapes without an outside margin (sphere, box, capsule, triangle mesh, heightfield).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "bullet_test_scene.h"

namespace gq::bullet::test {
namespace {

// gq answers exactly (round-off); Bullet's convex casts converge to ~1e-4 of the shape size.
const btScalar kExactTol = sizeof(btScalar) == 4 ? btScalar(5e-5) : btScalar(1e-9);
constexpr btScalar kBulletTol = btScalar(2e-3);
constexpr btScalar kSweepAgreement = btScalar(0.03);

// A unit sphere at the origin, a rotated box, a Y capsule, a flat mesh at y = -3 and a sloped heightfield.
struct QueryScene {
  ShapeStore store;
  TestWorld world;
  std::vector<btRigidBody*> targets;  // sphere, box, capsule
  explicit QueryScene(Backend backend) : world(backend) {
    targets.push_back(world.add(store.make<btSphereShape>(btScalar(1)), 0, btVector3(0, 0, 0)));
    targets.push_back(world.add(store.make<btBoxShape>(btVector3(1, 0.5, 2)), 0, btVector3(5, 0, 0),
                                btQuaternion(btVector3(0, 1, 0), btScalar(0.5))));
    targets.push_back(world.add(store.make<btCapsuleShape>(btScalar(0.5), btScalar(2)), 0, btVector3(-5, 0, 0)));
    world.add(flatMesh(store, 9, 12, -3), 0, btVector3(0, 0, 0));
    std::vector<float> h(25);
    for (int j = 0; j < 5; ++j)
      for (int x = 0; x < 5; ++x) h[std::size_t(j * 5 + x)] = 0.25f * float(x);
    world.add(heightField(store, 5, h, 0, 1), 0, btVector3(0, 0, 20));  // surface y = 0.25 * (x - 0) near z = 20
  }
};

struct RayOut {
  bool hit = false;
  btScalar fraction = 1;
  btVector3 normal;
};

RayOut castRay(TestWorld& w, const btVector3& from, const btVector3& to) {
  btCollisionWorld::ClosestRayResultCallback cb(from, to);
  w.world().rayTest(from, to, cb);
  return RayOut{cb.hasHit(), cb.m_closestHitFraction, cb.m_hitNormalWorld};
}

// Exact first hit of a downward ray (x, z) with the scene, in long double: sphere, rotated box (slabs), capsule
// (hemisphere cap or side), floor.
long double exactDownHit(long double x, long double z) {
  long double best = -3;  // the floor
  const long double rho2 = x * x + z * z;
  if (rho2 <= 1) best = std::max(best, std::sqrt(1 - rho2));
  // Box centre (5, 0, 0), half (1, 0.5, 2), rotated by 0.5 about Y: local = R^T (p - c).
  const long double c = std::cos(0.5L), s = std::sin(0.5L), dx = x - 5, dz = z;
  const long double lx = c * dx - s * dz, lz = s * dx + c * dz;
  if (std::abs(lx) <= 1 && std::abs(lz) <= 2) best = std::max(best, 0.5L);
  const long double cr2 = (x + 5) * (x + 5) + z * z;  // capsule axis x = -5, z = 0, y in [-1, 1], radius 0.5
  if (cr2 <= 0.25L) best = std::max(best, 1 + std::sqrt(0.25L - cr2));
  return best;
}

TEST(BulletQueries, RayTestHitsClosedFormsAndAgreesWithBullet) {
  QueryScene gq(Backend::Gq), bt(Backend::Bullet);
  int rays = 0, agree = 0;
  for (int i = 0; i <= 64; ++i) {
    for (int k = 0; k <= 8; ++k) {
      const btScalar x = btScalar(-8 + 0.25 * i + 0.013), z = btScalar(-3 + 0.75 * k + 0.007);
      const btVector3 from(x, 10, z), to(x, -10, z);
      const RayOut g = castRay(gq.world, from, to), b = castRay(bt.world, from, to);
      ASSERT_TRUE(g.hit) << x << " " << z;  // the mesh floor catches every ray
      EXPECT_NEAR(10 - 20 * g.fraction, btScalar(exactDownHit(x, z)), kExactTol * 20) << x << " " << z;
      ++rays;
      if (b.hit && std::abs(g.fraction - b.fraction) * 20 <= kBulletTol) ++agree;
    }
  }
  // Bullet's GJK ray cast misses by up to ~1 cm next to box edges; everywhere else it agrees with gq.
  EXPECT_GE(agree, rays - rays / 50) << agree << " of " << rays;
}

TEST(BulletQueries, RayTestOnHeightFieldFollowsBulletCentring) {
  QueryScene gq(Backend::Gq), bt(Backend::Bullet);
  for (int i = 0; i < 16; ++i) {
    const btScalar x = btScalar(-1.9 + 0.25 * i), z = btScalar(20.3);
    const RayOut g = castRay(gq.world, btVector3(x, 10, z), btVector3(x, -2.5, z));
    const RayOut b = castRay(bt.world, btVector3(x, 10, z), btVector3(x, -2.5, z));
    ASSERT_TRUE(g.hit);
    EXPECT_NEAR(10 - btScalar(12.5) * g.fraction, 0.25 * x, kExactTol * 10) << x;  // plane y = 0.25 x
    EXPECT_NEAR(g.fraction * btScalar(12.5), b.fraction * btScalar(12.5), kBulletTol);
  }
}

TEST(BulletQueries, ConvexSweepTestMatchesClosedFormsAndBullet) {
  QueryScene gq(Backend::Gq), bt(Backend::Bullet);
  btSphereShape ball(btScalar(0.25));
  btBoxShape cube(btVector3(0.25, 0.25, 0.25));
  for (int i = 0; i <= 32; ++i) {
    const btScalar x = btScalar(-8 + 0.5 * i + 0.011), z = btScalar(0.3);
    const btTransform from(btQuaternion::getIdentity(), btVector3(x, 10, z));
    const btTransform to(btQuaternion::getIdentity(), btVector3(x, -10, z));
    for (btConvexShape* shape : {static_cast<btConvexShape*>(&ball), static_cast<btConvexShape*>(&cube)}) {
      btCollisionWorld::ClosestConvexResultCallback g(from.getOrigin(), to.getOrigin()),
          b(from.getOrigin(), to.getOrigin());
      gq.world.convexSweepTest(shape, from, to, g);
      bt.world.convexSweepTest(shape, from, to, b);
      ASSERT_TRUE(g.hasHit());
      ASSERT_TRUE(b.hasHit());
      const btScalar yStop = 10 - 20 * g.m_closestHitFraction;
      if (shape == &ball && x * x + z * z < 1.25 * 1.25) {
        EXPECT_NEAR(yStop, std::sqrt(1.5625 - x * x - z * z), kExactTol * 100) << x;
      }
      if (std::abs(x) > 7.5) {
        EXPECT_NEAR(yStop, -2.75, kExactTol * 100) << x;  // rests on the floor
      }
      // Bullet's convex cast stops up to ~2.5% of the shape size off the contact next to edges; gq's is exact
      // (checked above against the closed forms).
      EXPECT_NEAR(g.m_closestHitFraction * 20, b.m_closestHitFraction * 20, kSweepAgreement) << x;
      EXPECT_GT(g.m_hitNormalWorld.dot(b.m_hitNormalWorld), 0.99) << x;
    }
  }
}

// Rays against a compound go to its children through gq (each child's index reported as Bullet does).
struct ChildRay : btCollisionWorld::ClosestRayResultCallback {
  using ClosestRayResultCallback::ClosestRayResultCallback;
  int child = -2;
  btScalar addSingleResult(btCollisionWorld::LocalRayResult& r, bool normalInWorldSpace) override {
    child = r.m_localShapeInfo ? r.m_localShapeInfo->m_triangleIndex : -1;
    return ClosestRayResultCallback::addSingleResult(r, normalInWorldSpace);
  }
};

TEST(BulletQueries, RayTestReachesCompoundChildren) {
  ShapeStore store;
  auto* compound = store.make<btCompoundShape>();
  compound->addChildShape(btTransform(btQuaternion::getIdentity(), btVector3(-1, 0, 0)),
                          store.make<btSphereShape>(btScalar(0.5)));
  compound->addChildShape(btTransform(btQuaternion::getIdentity(), btVector3(1, 0, 0)),
                          store.make<btBoxShape>(btVector3(0.5, 0.25, 0.5)));
  const btScalar angle = btScalar(0.3);
  TestWorld gq(Backend::Gq), bt(Backend::Bullet);
  for (TestWorld* w : {&gq, &bt}) w->add(compound, 0, btVector3(0, 0, 0), btQuaternion(btVector3(0, 1, 0), angle));
  const long double c = std::cos(0.3L), s = std::sin(0.3L);
  int hits = 0, agree = 0;
  for (int i = 0; i <= 40; ++i) {
    const btScalar x = btScalar(-1.9 + 0.095 * i), z = btScalar(0.1 + 0.01 * (i % 7));
    ChildRay g(btVector3(x, 5, z), btVector3(x, -5, z)), b(btVector3(x, 5, z), btVector3(x, -5, z));
    gq.world().rayTest(btVector3(x, 5, z), btVector3(x, -5, z), g);
    bt.world().rayTest(btVector3(x, 5, z), btVector3(x, -5, z), b);
    // Closed forms in the compound frame: local = R^T p with R the rotation by 0.3 about Y.
    const long double lx = c * x - s * z, lz = s * x + c * z;
    long double expected = -1;  // no hit
    int child = -1;
    const long double rho2 = (lx + 1) * (lx + 1) + lz * lz;
    if (rho2 <= 0.25L) expected = std::sqrt(0.25L - rho2), child = 0;
    if (std::abs(lx - 1) <= 0.5L && std::abs(lz) <= 0.5L) expected = 0.25L, child = 1;
    ASSERT_EQ(g.hasHit(), expected >= 0) << x << " " << z;
    if (!g.hasHit()) continue;
    ++hits;
    EXPECT_NEAR(5 - 10 * g.m_closestHitFraction, btScalar(expected), kExactTol * 20) << x;
    EXPECT_EQ(g.child, child) << x;
    if (b.hasHit() && std::abs(b.m_closestHitFraction - g.m_closestHitFraction) * 10 <= kBulletTol) ++agree;
  }
  EXPECT_GE(hits, 15);
  // A sphere swept down onto the box child stops with its bottom on the box top (y = 0.25 + 0.5).
  btSphereShape ball(btScalar(0.5));
  const btVector3 over = btVector3(std::cos(angle), 0, -std::sin(angle)) * btScalar(1.1);  // box child centre
  btCollisionWorld::ClosestConvexResultCallback sweepCb(over + btVector3(0, 5, 0), over - btVector3(0, 5, 0));
  gq.convexSweepTest(&ball, btTransform(btQuaternion::getIdentity(), over + btVector3(0, 5, 0)),
                     btTransform(btQuaternion::getIdentity(), over - btVector3(0, 5, 0)), sweepCb);
  ASSERT_TRUE(sweepCb.hasHit());
  EXPECT_NEAR(5 - 10 * sweepCb.m_closestHitFraction, 0.75, kExactTol * 20);
  // Bullet's GJK ray cast strays by up to ~1.6 cm near the sphere's silhouette (gq matches the closed form there).
  EXPECT_GE(agree, hits - hits / 5);
}

struct MinDistance : btCollisionWorld::ContactResultCallback {
  btScalar distance = BT_LARGE_FLOAT;
  int points = 0;
  btScalar addSingleResult(btManifoldPoint& cp, const btCollisionObjectWrapper*, int, int,
                           const btCollisionObjectWrapper*, int, int) override {
    distance = std::min(distance, cp.getDistance());
    ++points;
    return 0;
  }
};

// Signed distance from a probe sphere (radius 0.5) centred at p to the scene's sphere, box and capsule, in
// long double (closed forms: point-sphere, point-OBB from outside, point-segment).
long double exactProbeDistance(int target, long double px, long double py, long double pz) {
  if (target == 0) return std::sqrt(px * px + py * py + pz * pz) - 1.5L;
  if (target == 1) {
    const long double c = std::cos(0.5L), s = std::sin(0.5L), dx = px - 5, dz = pz;
    const long double l[3] = {c * dx - s * dz, py, s * dx + c * dz}, h[3] = {1, 0.5L, 2};
    long double d2 = 0;
    for (int k = 0; k < 3; ++k) d2 += std::pow(std::max(std::abs(l[k]) - h[k], 0.0L), 2);
    return std::sqrt(d2) - 0.5L;
  }
  const long double y = std::clamp(py, -1.0L, 1.0L);
  return std::sqrt((px + 5) * (px + 5) + (py - y) * (py - y) + pz * pz) - 1.0L;
}

TEST(BulletQueries, ContactTestAndPairTestDistancesMatchClosedFormsAndBullet) {
  btSphereShape probeShape(btScalar(0.5));
  QueryScene gq(Backend::Gq), bt(Backend::Bullet);
  int compared = 0;
  for (int i = 0; i < 60; ++i) {
    const int target = i % 3;
    const btScalar angle = btScalar(0.37 * i), reach = btScalar(1.3 + 0.1 * (i % 4));
    const btVector3 dir = btVector3(std::cos(angle), btScalar(0.3) * std::sin(2 * angle), std::sin(angle)).normalized();
    const btVector3 centre(btScalar(target == 0 ? 0 : target == 1 ? 5 : -5), 0, 0);
    const btVector3 p = centre + dir * reach;
    const long double expected = exactProbeDistance(target, p.x(), p.y(), p.z());
    if (expected < -0.2L || expected > 0.3L) continue;  // near contacts only (and the probe centre outside)
    btScalar got[2];
    for (QueryScene* scene : {&gq, &bt}) {
      btCollisionObject probe;
      probe.setCollisionShape(&probeShape);
      probe.setWorldTransform(btTransform(btQuaternion::getIdentity(), p));
      MinDistance cb;
      cb.m_closestDistanceThreshold = 1;
      // contactTest visits broadphase (AABB) overlaps only: separated probes go through contactPairTest.
      if (expected < 0)
        scene->world.world().contactTest(&probe, cb);
      else
        scene->world.world().contactPairTest(&probe, scene->targets[std::size_t(target)], cb);
      ASSERT_GT(cb.points, 0) << name(scene->world.backend()) << " probe " << i;
      got[scene == &gq ? 0 : 1] = cb.distance;
    }
    EXPECT_NEAR(got[0], btScalar(expected), kExactTol * 20) << "probe " << i;
    EXPECT_NEAR(got[1], got[0], kBulletTol) << "probe " << i;
    ++compared;
  }
  EXPECT_GE(compared, 20);
}

}  // namespace
}  // namespace gq::bullet::test
