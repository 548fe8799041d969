// Bad input through gq::bullet, one test per row of the table in docs/bullet.md. Bullet itself mostly does not
// validate (btAssert is compiled out): its convention is "no contact, no hit, callbacks not called". gq keeps it on
// every row and never crashes, throws or hands out a NaN, where stock Bullet reports NaN contacts for infinite
// sizes, segfaults on a hull without points and reads outside the buffer of an absurd heightfield.
// Built against float Bullet (float.*) and Bullet's float64 build (double.*).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <string>

#include <BulletCollision/CollisionShapes/btTriangleIndexVertexArray.h>
#include <BulletCollision/CollisionShapes/btUniformScalingShape.h>

#include "bullet_test_scene.h"

namespace gq::bullet::test {
namespace {

const btScalar kNaN = std::numeric_limits<btScalar>::quiet_NaN();
const btScalar kInf = std::numeric_limits<btScalar>::infinity();

bool finite(const btVector3& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); }

btTransform at(const btVector3& origin) { return btTransform(btQuaternion::getIdentity(), origin); }

// Counts every callback call and every non-finite number handed to it.
struct ContactCounter : btCollisionWorld::ContactResultCallback {
  int calls = 0, nonFinite = 0;
  btScalar addSingleResult(btManifoldPoint& cp, const btCollisionObjectWrapper*, int, int,
                           const btCollisionObjectWrapper*, int, int) override {
    ++calls;
    if (!finite(cp.m_positionWorldOnB) || !finite(cp.m_normalWorldOnB) || !std::isfinite(cp.getDistance()))
      ++nonFinite;
    return 0;
  }
};

struct RayCounter : btCollisionWorld::RayResultCallback {
  int calls = 0, nonFinite = 0;
  btScalar addSingleResult(btCollisionWorld::LocalRayResult& r, bool) override {
    ++calls;
    if (!std::isfinite(r.m_hitFraction) || !finite(r.m_hitNormalLocal)) ++nonFinite;
    m_closestHitFraction = r.m_hitFraction;
    return r.m_hitFraction;
  }
};

struct SweepCounter : btCollisionWorld::ConvexResultCallback {
  int calls = 0, nonFinite = 0;
  btScalar addSingleResult(btCollisionWorld::LocalConvexResult& r, bool) override {
    ++calls;
    if (!std::isfinite(r.m_hitFraction) || !finite(r.m_hitNormalLocal) || !finite(r.m_hitPointLocal)) ++nonFinite;
    m_closestHitFraction = r.m_hitFraction;
    return r.m_hitFraction;
  }
};

int manifoldPoints(btCollisionWorld& world) {
  int n = 0;
  for (int i = 0; i < world.getDispatcher()->getNumManifolds(); ++i)
    n += world.getDispatcher()->getManifoldByIndexInternal(i)->getNumContacts();
  return n;
}

constexpr int kSteps = 3;
const btVector3 kBallStart(0, btScalar(0.9), 0);  // a dynamic ball of radius 0.5 resting into the shape at the origin

// Height of the ball after kSteps in a world without the shape: free fall, computed by the same stepping.
btScalar freeFallHeight() {
  TestWorld w(Backend::Gq);
  btSphereShape ball(btScalar(0.5));
  btRigidBody* body = w.add(&ball, 1, kBallStart);
  w.step(kSteps);
  return body->getWorldTransform().getOrigin().y();
}

// The shape (static, at `pose`) in a gq world with the ball: contacts by stepping, contactTest and
// contactPairTest, a ray and a sphere sweep through the shape's centre, and the shape swept itself (if convex and
// the shape is the bad input). Bad input must give no callback call, no manifold point, the ball falling as if the
// shape were absent and the shape's object where it was put.
void expectSilent(btCollisionShape* shape, const btTransform& pose = at(btVector3(0, 0, 0)), bool sweepShape = true) {
  TestWorld w(Backend::Gq);
  btRigidBody* body = w.add(shape, 0, pose.getOrigin(), pose.getRotation());
  body->setWorldTransform(pose);
  btSphereShape ballShape(btScalar(0.5));
  btRigidBody* ball = w.add(&ballShape, 1, kBallStart);

  RayCounter ray;
  w.world().rayTest(btVector3(0, 0, 5), btVector3(0, 0, -5), ray);
  EXPECT_EQ(ray.calls, 0);
  EXPECT_EQ(ray.m_closestHitFraction, btScalar(1));
  btSphereShape small(btScalar(0.1));
  SweepCounter sweep;
  w.convexSweepTest(&small, at(btVector3(0, 0, 5)), at(btVector3(0, 0, -5)), sweep);
  EXPECT_EQ(sweep.calls, 0);
  if (sweepShape && shape->isConvex()) {
    SweepCounter cast;  // the bad shape swept through the ball
    w.convexSweepTest(static_cast<btConvexShape*>(shape), at(btVector3(0, 0.9, 5)), at(btVector3(0, 0.9, -5)), cast);
    EXPECT_EQ(cast.calls, 0);
  }
  ContactCounter test, pair;
  w.world().contactTest(body, test);
  w.world().contactPairTest(body, ball, pair);
  EXPECT_EQ(test.calls, 0);
  EXPECT_EQ(pair.calls, 0);

  w.step(kSteps);
  EXPECT_EQ(manifoldPoints(w.world()), 0);
  EXPECT_EQ(ball->getWorldTransform().getOrigin().y(), freeFallHeight());
  EXPECT_EQ(std::memcmp(&body->getWorldTransform(), &pose, sizeof pose), 0);
}

// Runs `check` for each value with the value in the failure trace.
void forEach(std::initializer_list<btScalar> values, const std::function<void(btScalar)>& check) {
  for (btScalar v : values) {
    SCOPED_TRACE(testing::Message() << "value " << v);
    check(v);
  }
}

TEST(BulletBadInput, NaNOrInfInABodyTransformGivesNoContactOrHit) {
  btSphereShape sphere(1);
  btBoxShape box(btVector3(1, 1, 1));
  forEach({kNaN, kInf, -kInf}, [&](btScalar bad) {
    expectSilent(&sphere, at(btVector3(bad, 0, 0)), false);
    expectSilent(&box, at(btVector3(0, 0, bad)), false);
    btTransform rotated = at(btVector3(0, 0, 0));
    rotated.getBasis()[0][1] = bad;  // stock Bullet still reports sphere contacts (it ignores a sphere's rotation)
    expectSilent(&sphere, rotated, false);
    expectSilent(&box, rotated, false);
  });
}

TEST(BulletBadInput, NaNOrInfShapeSizesGiveNoContactOrHit) {
  forEach({kNaN, kInf}, [](btScalar bad) {
    btSphereShape sphere(bad);  // Inf: stock Bullet reports NaN contacts and the ball's position becomes NaN
    expectSilent(&sphere);
    btBoxShape box(btVector3(1, bad, 1));
    expectSilent(&box);
    btCapsuleShape capsuleRadius(bad, 1), capsuleHeight(btScalar(0.5), bad);
    expectSilent(&capsuleRadius);
    expectSilent(&capsuleHeight);
    btCylinderShape cylinder(btVector3(bad, 1, bad));
    expectSilent(&cylinder);
    btConeShape cone(bad, 1);
    expectSilent(&cone);
    const btVector3 centre(0, 0, 0);
    const btScalar radius = bad;
    btMultiSphereShape multi(&centre, &radius, 1);
    expectSilent(&multi);
  });
}

TEST(BulletBadInput, ZeroOrNegativeSizesGiveNoContactOrHit) {
  forEach({btScalar(0), btScalar(-1)}, [](btScalar bad) {
    btSphereShape sphere(bad);
    expectSilent(&sphere);
    btBoxShape box(btVector3(1, bad, 1));  // stock Bullet: half extent 0 is a flat box it collides with
    expectSilent(&box);
    btCapsuleShape capsule(bad, 1);
    expectSilent(&capsule);
    btCylinderShape cylinder(btVector3(bad, 1, bad));
    expectSilent(&cylinder);
    btConeShape cone(bad, 1);  // stock Bullet: a cone of radius -1 is a cone of radius 1
    expectSilent(&cone);
    const btVector3 centre(0, 0, 0);
    const btScalar radius = bad;
    btMultiSphereShape multi(&centre, &radius, 1);
    expectSilent(&multi);
  });
  btCapsuleShape negativeHeight(btScalar(0.5), -1);
  expectSilent(&negativeHeight);
}

TEST(BulletBadInput, ZeroOrNonFiniteLocalScalingGivesNoContactOrHit) {
  ShapeStore store;
  forEach({btScalar(0), kNaN, kInf}, [&](btScalar bad) {
    btSphereShape sphere(1);
    sphere.setLocalScaling(btVector3(bad, bad, bad));
    expectSilent(&sphere);
    btBoxShape box(btVector3(1, 1, 1));
    box.setLocalScaling(btVector3(1, bad, 1));
    expectSilent(&box);
    btConvexHullShape* hull = cubeHull(store, 1);
    hull->setLocalScaling(btVector3(bad, 1, 1));
    expectSilent(hull);
    btBvhTriangleMeshShape* mesh = flatMesh(store, 3, 2, 0);
    btScaledBvhTriangleMeshShape scaled(mesh, btVector3(1, bad, 1));
    expectSilent(&scaled);
    btHeightfieldTerrainShape* field = heightField(store, 3, std::vector<float>(9, 0.f), -1, 1);
    field->setLocalScaling(btVector3(1, 1, bad));
    expectSilent(field);
  });
}

TEST(BulletBadInput, NonFiniteHullPointGivesNoContactOrHit) {
  forEach({kNaN, kInf}, [](btScalar bad) {
    btConvexHullShape hull;
    for (int i = 0; i < 8; ++i) hull.addPoint(btVector3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? bad : -1), i == 7);
    expectSilent(&hull);
  });
}

TEST(BulletBadInput, HullWithoutPointsGivesNoContactOrHit) {
  btConvexHullShape hull;  // stock Bullet segfaults in its GJK on this shape (contactPairTest, rays, sweeps)
  expectSilent(&hull);
}

// A hull of 1 or 2 points is a valid Bullet shape (a sphere or capsule of the margin radius) that gq does not
// cook: Bullet's own algorithms answer, exactly as in a stock world, and finitely.
TEST(BulletBadInput, HullOfOneOrTwoPointsIsAnsweredByBulletAsInAStockWorld) {
  for (int points = 1; points <= 2; ++points) {
    SCOPED_TRACE(testing::Message() << points << " points");
    btConvexHullShape hull;
    for (int i = 0; i < points; ++i) hull.addPoint(btVector3(0, btScalar(i), 0), i + 1 == points);
    RayCounter rays[2];
    SweepCounter sweeps[2];
    ContactCounter pairs[2];
    for (Backend backend : {Backend::Bullet, Backend::Gq}) {
      TestWorld w(backend);
      btRigidBody* body = w.add(&hull, 0, btVector3(0, 0, 0));
      const int k = int(backend);
      w.world().rayTest(btVector3(0, 0, 5), btVector3(0, 0, -5), rays[k]);
      btSphereShape small(btScalar(0.1));
      w.convexSweepTest(&small, at(btVector3(0, 0, 5)), at(btVector3(0, 0, -5)), sweeps[k]);
      btSphereShape ballShape(btScalar(0.5));
      btCollisionObject ball;  // outside the world: contactPairTest needs no broadphase
      ball.setCollisionShape(&ballShape);
      ball.setWorldTransform(at(btVector3(0, btScalar(0.52), 0)));
      w.world().contactPairTest(body, &ball, pairs[k]);
    }
    EXPECT_EQ(rays[1].calls, rays[0].calls);
    EXPECT_EQ(rays[1].m_closestHitFraction, rays[0].m_closestHitFraction);
    EXPECT_EQ(sweeps[1].calls, sweeps[0].calls);
    EXPECT_EQ(sweeps[1].m_closestHitFraction, sweeps[0].m_closestHitFraction);
    EXPECT_EQ(pairs[1].calls, pairs[0].calls);
    // The ray along z through the origin meets the margin sphere (radius 0.04) around the point at the origin.
    EXPECT_EQ(rays[1].calls, 1);
    EXPECT_NEAR(rays[1].m_closestHitFraction, btScalar(0.496), btScalar(2e-3));
    EXPECT_EQ(rays[1].nonFinite + sweeps[1].nonFinite + pairs[1].nonFinite, 0);
  }
}

TEST(BulletBadInput, NonFiniteMeshVertexGivesNoContactOrHit) {
  forEach({kNaN, kInf}, [](btScalar bad) {
    btTriangleMesh mesh;
    mesh.addTriangle(btVector3(-5, 0, -5), btVector3(-5, 0, 5), btVector3(5, bad, -5));
    mesh.addTriangle(btVector3(5, 0, -5), btVector3(-5, 0, 5), btVector3(5, 0, 5));
    btBvhTriangleMeshShape shape(&mesh, true);
    expectSilent(&shape);
  });
}

TEST(BulletBadInput, EmptyTriangleMeshGivesNoContactOrHit) {
  btTriangleMesh mesh;
  btBvhTriangleMeshShape shape(&mesh, true, false);  // Bullet's own BVH build segfaults on zero triangles
  expectSilent(&shape);
}

TEST(BulletBadInput, AllDegenerateTriangleMeshGivesNoContactOrHit) {
  btTriangleMesh mesh;
  mesh.addTriangle(btVector3(-1, 0, 0), btVector3(0, 0, 0), btVector3(1, 0, 0));    // collinear
  mesh.addTriangle(btVector3(0, 0, 0), btVector3(0, 0, 0), btVector3(0, 0, 0));     // one point
  mesh.addTriangle(btVector3(0, 0, -1), btVector3(0, 0, -1), btVector3(0, 0, 1));   // repeated vertex
  btBvhTriangleMeshShape shape(&mesh, true);
  expectSilent(&shape);
}

// An index equal to the vertex count: the buffer holds a 4th vertex so Bullet's own AABB pass reads valid memory,
// but the mesh declares 3 vertices and gq refuses the index.
TEST(BulletBadInput, MeshIndexPastTheVertexCountGivesNoContactOrHit) {
  btScalar vertices[12] = {-5, 0, -5, -5, 0, 5, 5, 0, -5, 5, 0, 5};
  int indices[6] = {0, 1, 2, 2, 1, 3};
  btTriangleIndexVertexArray array(2, indices, 3 * int(sizeof(int)), 3, vertices, 3 * int(sizeof(btScalar)));
  btBvhTriangleMeshShape shape(&array, true);
  expectSilent(&shape);
}

TEST(BulletBadInput, PlaneWithZeroOrNonFiniteNormalOrConstantGivesNoContactOrHit) {
  forEach({btScalar(0), kNaN, kInf}, [](btScalar bad) {
    btStaticPlaneShape normal(btVector3(0, bad, 0), 0);
    expectSilent(&normal);
  });
  forEach({kNaN, kInf}, [](btScalar bad) {
    btStaticPlaneShape constant(btVector3(0, 1, 0), bad);  // Inf: stock Bullet's contactTest reports NaN points
    expectSilent(&constant);
  });
}

TEST(BulletBadInput, HeightFieldWithNonFiniteHeightGivesNoContactOrHit) {
  ShapeStore store;
  forEach({kNaN, kInf}, [&](btScalar bad) {
    std::vector<float> h(25, 0.f);
    h[12] = float(bad);
    expectSilent(heightField(store, 5, h, -1, 1));
  });
}

TEST(BulletBadInput, HeightFieldWithFewerThanTwoByTwoSamplesGivesNoContactOrHit) {
  std::vector<float> heights(100, 0.f);
  for (auto [width, length] : {std::pair{0, 0}, {1, 5}, {5, 1}, {-5, 5}, {5, -5}}) {
    SCOPED_TRACE(testing::Message() << width << " x " << length);
    btHeightfieldTerrainShape field(width, length, heights.data(), 1, -1, 1, 1, PHY_FLOAT, false);
    expectSilent(&field);
  }
}

// Bullet trusts the dimensions and reads outside the caller's buffer (segfault): gq refuses more samples than
// kMaxHeightFieldSamples before reading any, and up axes outside 0..2.
TEST(BulletBadInput, HeightFieldWithAbsurdDimensionsOrUpAxisGivesNoContactOrHit) {
  std::vector<float> heights(100, 0.f);
  for (int side : {65536, 100000, 1 << 30}) {
    SCOPED_TRACE(testing::Message() << side << " x " << side);
    btHeightfieldTerrainShape field(side, side, heights.data(), 1, -1, 1, 1, PHY_FLOAT, false);
    expectSilent(&field);
  }
  for (int up : {-1, 3, 7}) {
    SCOPED_TRACE(testing::Message() << "up axis " << up);
    btHeightfieldTerrainShape field(10, 10, heights.data(), 1, -1, 1, up, PHY_FLOAT, false);
    expectSilent(&field);
  }
  btHeightfieldTerrainShape noData(10, 10, nullptr, 1, -1, 1, 1, PHY_FLOAT, false);
  expectSilent(&noData);
}

TEST(BulletBadInput, RayWithNonFiniteEndsOrNoLengthReportsNoHit) {
  ShapeStore store;
  TestWorld w(Backend::Gq);
  w.add(store.make<btSphereShape>(btScalar(1)), 0, btVector3(0, 0, 0));
  w.add(flatMesh(store, 5, 10, -3), 0, btVector3(0, 0, 0));
  const btScalar huge = std::numeric_limits<btScalar>::max() / 2;
  const std::pair<btVector3, btVector3> rays[] = {
      {btVector3(kNaN, 5, 0), btVector3(0, -5, 0)},      {btVector3(0, 5, 0), btVector3(0, kNaN, 0)},
      {btVector3(0, 5, 0), btVector3(0, -kInf, 0)},      {btVector3(kInf, 5, 0), btVector3(0, -5, 0)},
      {btVector3(0, huge, 0), btVector3(0, -huge, 0)},   // the length overflows
      {btVector3(0, 0.5, 0), btVector3(0, 0.5, 0)},      // from == to inside the sphere
      {btVector3(0, 5, 0), btVector3(0, 5, 0)}};         // from == to in the open
  for (const auto& [from, to] : rays) {
    SCOPED_TRACE(testing::Message() << "from " << from.y() << " to " << to.y());
    RayCounter counter;
    btCollisionWorld::ClosestRayResultCallback closest(from, to);
    btCollisionWorld::AllHitsRayResultCallback all(from, to);
    w.world().rayTest(from, to, counter);
    w.world().rayTest(from, to, closest);
    w.world().rayTest(from, to, all);
    EXPECT_EQ(counter.calls, 0);
    EXPECT_FALSE(closest.hasHit());
    EXPECT_EQ(closest.m_closestHitFraction, btScalar(1));
    EXPECT_EQ(all.m_collisionObjects.size(), 0);
  }
}

TEST(BulletBadInput, SweepWithNonFinitePosesOrNoCastShapeReportsNoHit) {
  ShapeStore store;
  TestWorld w(Backend::Gq);
  w.add(store.make<btSphereShape>(btScalar(1)), 0, btVector3(0, 0, 0));
  w.add(flatMesh(store, 5, 10, -3), 0, btVector3(0, 0, 0));
  btSphereShape sphere(btScalar(0.2));
  btBoxShape box(btVector3(0.2, 0.2, 0.2));
  btTransform nanRotation = at(btVector3(0, 5, 0));
  nanRotation.getBasis()[1][1] = kNaN;
  const std::pair<btTransform, btTransform> poses[] = {{at(btVector3(kNaN, 5, 0)), at(btVector3(0, -5, 0))},
                                                       {at(btVector3(0, 5, 0)), at(btVector3(0, kNaN, 0))},
                                                       {at(btVector3(0, 5, 0)), at(btVector3(0, -kInf, 0))},
                                                       {nanRotation, at(btVector3(0, -5, 0))}};
  for (const auto& [from, to] : poses) {
    for (btConvexShape* cast : {static_cast<btConvexShape*>(&sphere), static_cast<btConvexShape*>(&box)}) {
      SweepCounter counter;
      btCollisionWorld::ClosestConvexResultCallback closest(from.getOrigin(), to.getOrigin());
      w.convexSweepTest(cast, from, to, counter);
      w.convexSweepTest(cast, from, to, closest);
      EXPECT_EQ(counter.calls, 0);
      EXPECT_FALSE(closest.hasHit());
      EXPECT_EQ(closest.m_closestHitFraction, btScalar(1));
    }
  }
  SweepCounter counter;
  w.convexSweepTest(nullptr, at(btVector3(0, 5, 0)), at(btVector3(0, -5, 0)), counter);
  EXPECT_EQ(counter.calls, 0);
}

TEST(BulletBadInput, SweepFromEqualToToReportsNoHitAsStockBullet) {
  ShapeStore store;
  TestWorld w(Backend::Gq);
  w.add(store.make<btSphereShape>(btScalar(1)), 0, btVector3(0, 0, 0));
  btSphereShape sphere(btScalar(0.2));
  for (const btVector3& p : {btVector3(0, btScalar(0.5), 0), btVector3(0, 5, 0)}) {
    SweepCounter counter;
    w.convexSweepTest(&sphere, at(p), at(p), counter);
    EXPECT_EQ(counter.calls, 0);
  }
}

// Bullet's contactTest and contactPairTest do not need the objects in the world (it tests the object's bounds
// against the broadphase): gq answers the same way, exactly.
TEST(BulletBadInput, ContactTestOnAnObjectOutsideTheWorldReportsItsContacts) {
  ShapeStore store;
  TestWorld w(Backend::Gq);
  w.add(store.make<btSphereShape>(btScalar(1)), 0, btVector3(0, 0, 0));
  btSphereShape sphere(1);
  btCollisionObject outside, other;
  outside.setCollisionShape(&sphere);
  outside.setWorldTransform(at(btVector3(0, btScalar(1.5), 0)));
  other.setCollisionShape(&sphere);
  other.setWorldTransform(at(btVector3(0, btScalar(3.25), 0)));
  ContactCounter test, pair;
  w.world().contactTest(&outside, test);
  w.world().contactPairTest(&outside, &other, pair);
  EXPECT_EQ(test.calls, 1);  // unit spheres 1.5 apart: depth 0.5
  EXPECT_EQ(pair.calls, 1);  // 1.75 apart: depth 0.25
  EXPECT_EQ(test.nonFinite + pair.nonFinite, 0);
  btSphereShape bad(kNaN);
  outside.setCollisionShape(&bad);
  ContactCounter badTest;
  w.world().contactTest(&outside, badTest);
  EXPECT_EQ(badTest.calls, 0);
}

// btUniformScalingShape is a shape gq leaves to Bullet: around an infinite sphere, stock Bullet's sweep reports a
// NaN hit. The gq world passes Bullet's per-object answers on only when finite.
TEST(BulletBadInput, NonFiniteAnswersOfShapesBulletKeepsNeverReachTheCallback) {
  btSphereShape inner(kInf);
  btUniformScalingShape scaled(&inner, 1);
  SweepCounter sweeps[2];
  RayCounter rays[2];
  for (Backend backend : {Backend::Bullet, Backend::Gq}) {
    TestWorld w(backend);
    w.add(&scaled, 0, btVector3(0, 0, 0));
    btSphereShape small(btScalar(0.1));
    w.convexSweepTest(&small, at(btVector3(0, 0, 5)), at(btVector3(0, 0, -5)), sweeps[int(backend)]);
    w.world().rayTest(btVector3(0, 0, 5), btVector3(0, 0, -5), rays[int(backend)]);
  }
  EXPECT_GT(sweeps[0].nonFinite, 0);  // the premise: stock Bullet 3.24 hands out a NaN hit here
  EXPECT_EQ(sweeps[1].nonFinite, 0);
  EXPECT_EQ(rays[1].nonFinite, 0);
}

// A shape edited into bad input after it touched something: its old contacts are dropped, none is added.
TEST(BulletBadInput, ShapeMadeInvalidAfterContactDropsItsContacts) {
  TestWorld w(Backend::Gq);
  btBoxShape ground(btVector3(5, 1, 5));
  w.add(&ground, 0, btVector3(0, -1, 0));
  btSphereShape ballShape(btScalar(0.5));
  w.add(&ballShape, 1, btVector3(0, btScalar(0.49), 0));
  w.step(5);
  ASSERT_GT(manifoldPoints(w.world()), 0);
  ground.setLocalScaling(btVector3(1, kNaN, 1));
  w.step(1);
  EXPECT_EQ(manifoldPoints(w.world()), 0);
}

// A compound with a bad child (radius 0: finite bounds, so Bullet's compound algorithm still visits its children):
// the good child answers rays and contacts, the bad one nothing.
TEST(BulletBadInput, CompoundWithABadChildAnswersForTheOtherChildren) {
  btCompoundShape compound;
  btSphereShape bad(0);
  btBoxShape good(btVector3(1, 1, 1));
  compound.addChildShape(at(btVector3(-3, 0, 0)), &bad);
  compound.addChildShape(at(btVector3(3, 0, 0)), &good);
  TestWorld w(Backend::Gq);
  btRigidBody* body = w.add(&compound, 0, btVector3(0, 0, 0));
  btCollisionWorld::ClosestRayResultCallback toGood(btVector3(3, 5, 0), btVector3(3, -5, 0));
  w.world().rayTest(btVector3(3, 5, 0), btVector3(3, -5, 0), toGood);
  ASSERT_TRUE(toGood.hasHit());
  EXPECT_NEAR(toGood.m_closestHitFraction, btScalar(0.4), btScalar(1e-5));  // the box top y = 1
  RayCounter toBad;
  w.world().rayTest(btVector3(-3, 5, 0), btVector3(-3, -5, 0), toBad);
  EXPECT_EQ(toBad.calls, 0);
  btSphereShape probe(btScalar(0.5));
  btCollisionObject nearBad, nearGood;
  nearBad.setCollisionShape(&probe);
  nearBad.setWorldTransform(at(btVector3(-3, btScalar(0.2), 0)));
  nearGood.setCollisionShape(&probe);
  nearGood.setWorldTransform(at(btVector3(3, btScalar(1.4), 0)));
  ContactCounter badPair, goodPair;
  w.world().contactPairTest(body, &nearBad, badPair);
  w.world().contactPairTest(body, &nearGood, goodPair);
  EXPECT_EQ(badPair.calls, 0);
  EXPECT_GE(goodPair.calls, 1);
  EXPECT_EQ(goodPair.nonFinite, 0);
}

}  // namespace
}  // namespace gq::bullet::test
