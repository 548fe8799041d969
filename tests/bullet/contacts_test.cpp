// Contacts in Bullet's conventions, checked against closed forms: normalOnB from B to A, the point on B,
// negative distance = penetration, margins as Bullet defines them, triangle ids of meshes and heightfields.
#include <gtest/gtest.h>

#include <cmath>

#include <BulletCollision/CollisionShapes/btConvexPointCloudShape.h>

#include "bullet_test_scene.h"

namespace gq::bullet::test {
namespace {

// Round-off allowance for exact answers, by precision.
const btScalar kTol = sizeof(btScalar) == 4 ? btScalar(5e-5) : btScalar(1e-9);

struct Point {
  btVector3 normalOnB, pointOnB, pointOnA;
  btScalar distance;
  int partB, indexB;
};

// Collects contactPairTest points, re-expressed with A = the first object passed.
struct Collect : btCollisionWorld::ContactResultCallback {
  const btCollisionObject* a = nullptr;
  std::vector<Point> points;
  btScalar addSingleResult(btManifoldPoint& cp, const btCollisionObjectWrapper* w0, int part0, int index0,
                           const btCollisionObjectWrapper*, int part1, int index1) override {
    const bool swapped = w0->getCollisionObject() != a;
    Point p;
    p.distance = cp.getDistance();
    p.normalOnB = swapped ? -cp.m_normalWorldOnB : cp.m_normalWorldOnB;
    p.pointOnB = swapped ? cp.getPositionWorldOnA() : cp.getPositionWorldOnB();
    p.pointOnA = swapped ? cp.getPositionWorldOnB() : cp.getPositionWorldOnA();
    p.partB = swapped ? part0 : part1;
    p.indexB = swapped ? index0 : index1;
    points.push_back(p);
    return 0;
  }
};

class QueryWorld {
 public:
  QueryWorld() : dispatcher_(&config_), world_(&dispatcher_, &broadphase_, &config_) {}
  ~QueryWorld() {
    for (auto& o : objects_) world_.removeCollisionObject(o.get());
  }
  btCollisionObject* add(btCollisionShape* shape, const btVector3& origin,
                         const btQuaternion& rotation = btQuaternion::getIdentity()) {
    objects_.push_back(std::make_unique<btCollisionObject>());
    objects_.back()->setCollisionShape(shape);
    objects_.back()->setWorldTransform(btTransform(rotation, origin));
    world_.addCollisionObject(objects_.back().get());
    return objects_.back().get();
  }
  std::vector<Point> contacts(btCollisionObject* a, btCollisionObject* b, btScalar closestThreshold = 0) {
    Collect c;
    c.a = a;
    c.m_closestDistanceThreshold = closestThreshold;
    world_.contactPairTest(a, b, c);
    return c.points;
  }

 private:
  CollisionConfiguration config_;
  CollisionDispatcher dispatcher_;
  btDbvtBroadphase broadphase_;
  CollisionWorld world_;
  std::vector<std::unique_ptr<btCollisionObject>> objects_;
};

void expectVec(const btVector3& got, const btVector3& want, btScalar tol) {
  EXPECT_NEAR(got.x(), want.x(), tol);
  EXPECT_NEAR(got.y(), want.y(), tol);
  EXPECT_NEAR(got.z(), want.z(), tol);
}

TEST(BulletContacts, SphereSphereNormalPointsFromBToAWithNegativeDepth) {
  QueryWorld w;
  btSphereShape s(1);
  auto* a = w.add(&s, btVector3(0, 0, 0));
  auto* b = w.add(&s, btVector3(1.5, 0, 0));
  const auto pts = w.contacts(a, b);
  ASSERT_EQ(pts.size(), 1u);
  EXPECT_NEAR(pts[0].distance, -0.5, kTol);
  expectVec(pts[0].normalOnB, btVector3(-1, 0, 0), kTol);
  expectVec(pts[0].pointOnB, btVector3(0.5, 0, 0), kTol);
  expectVec(pts[0].pointOnA, btVector3(1, 0, 0), kTol);  // pointOnA = pointOnB + normalOnB * distance
}

TEST(BulletContacts, BoxOnBoxGivesItsFourFaceCornersAtOnce) {
  QueryWorld w;
  btBoxShape big(btVector3(1, 1, 1)), small(btVector3(0.5, 0.5, 0.5));
  auto* top = w.add(&small, btVector3(0.2, 1.49, -0.1));
  auto* bottom = w.add(&big, btVector3(0, 0, 0));
  const auto pts = w.contacts(top, bottom);
  ASSERT_EQ(pts.size(), 4u);
  for (const Point& p : pts) {
    EXPECT_NEAR(p.distance, -0.01, kTol);
    expectVec(p.normalOnB, btVector3(0, 1, 0), kTol);
    EXPECT_NEAR(p.pointOnB.y(), 1, kTol);
    EXPECT_NEAR(std::abs(p.pointOnB.x() - 0.2), 0.5, kTol);
    EXPECT_NEAR(std::abs(p.pointOnB.z() + 0.1), 0.5, kTol);
  }
}

TEST(BulletContacts, TiltedBoxOnBoxGivesOnlyItsPenetratingCorners) {
  QueryWorld w;
  btBoxShape big(btVector3(1, 1, 1)), small(btVector3(0.5, 0.5, 0.5));
  const double tilt = 0.01;  // about z: the bottom edge at -x lies 2 mm into the top face, the one at +x ~8 mm above
  const double centreY = 1 - 0.002 + 0.5 * std::cos(tilt) + 0.5 * std::sin(tilt);
  auto* top = w.add(&small, btVector3(0.2, btScalar(centreY), -0.1), btQuaternion(btVector3(0, 0, 1), btScalar(tilt)));
  auto* bottom = w.add(&big, btVector3(0, 0, 0));
  const auto pts = w.contacts(top, bottom);
  ASSERT_EQ(pts.size(), 2u);
  for (const Point& p : pts) {
    EXPECT_NEAR(p.distance, -0.002, kTol);
    EXPECT_NEAR(p.pointOnB.y(), 1, kTol);
    EXPECT_NEAR(std::abs(p.pointOnB.z() + 0.1), 0.5, kTol);
  }
}

TEST(BulletContacts, BoxPairApartWithinTheThresholdGivesOnlyItsClosestPoint) {
  QueryWorld w;
  btBoxShape big(btVector3(1, 1, 1)), small(btVector3(0.5, 0.5, 0.5));
  auto* top = w.add(&small, btVector3(0.2, btScalar(1.505), -0.1));  // 5 mm above, face on face
  auto* bottom = w.add(&big, btVector3(0, 0, 0));
  const auto pts = w.contacts(top, bottom);
  ASSERT_EQ(pts.size(), 1u);
  EXPECT_NEAR(pts[0].distance, 0.005, kTol);
  expectVec(pts[0].normalOnB, btVector3(0, 1, 0), kTol);
  EXPECT_NEAR(pts[0].pointOnB.y(), 1, kTol);
}

TEST(BulletContacts, HullMarginIsOutsideBoxMarginInside) {
  QueryWorld w;
  ShapeStore store;
  btConvexHullShape* hull = cubeHull(store, 0.5);
  hull->setMargin(btScalar(0.1));
  btBoxShape box(btVector3(0.5, 0.5, 0.5));  // default margin 0.04, inside the half extents
  btStaticPlaneShape plane(btVector3(0, 1, 0), 0);
  auto* ground = w.add(&plane, btVector3(0, 0, 0));
  auto* h = w.add(hull, btVector3(0, 0.55, 0));
  auto* b = w.add(&box, btVector3(5, 0.49, 0));
  const auto hullPts = w.contacts(h, ground);
  ASSERT_EQ(hullPts.size(), 4u);
  for (const Point& p : hullPts) {
    EXPECT_NEAR(p.distance, -0.05, kTol);  // 0.55 - 0.5 - margin 0.1
    EXPECT_NEAR(p.pointOnB.y(), 0, kTol);
    expectVec(p.normalOnB, btVector3(0, 1, 0), kTol);
  }
  const auto boxPts = w.contacts(b, ground);
  ASSERT_EQ(boxPts.size(), 4u);
  for (const Point& p : boxPts) EXPECT_NEAR(p.distance, -0.01, kTol);
}

TEST(BulletContacts, CapsuleAxesXYZMatchClosedForm) {
  QueryWorld w;
  btCapsuleShapeX cx(0.5, 2);
  btCapsuleShape cy(0.5, 2);
  btCapsuleShapeZ cz(0.5, 2);
  btConvexShape* capsules[3] = {&cx, &cy, &cz};
  btSphereShape ball(btScalar(0.6));
  for (int k = 0; k < 3; ++k) {
    btVector3 axis(0, 0, 0);
    axis[k] = 1;
    auto* cap = w.add(capsules[k], btVector3(10 * k, 0, 0));
    auto* s = w.add(&ball, btVector3(10 * k, 0, 0) + axis * 2);
    const auto pts = w.contacts(cap, s);
    ASSERT_EQ(pts.size(), 1u) << "axis " << k;
    EXPECT_NEAR(pts[0].distance, -0.1, kTol);  // 2 - (1 + 0.5) - 0.6
    expectVec(pts[0].normalOnB, -axis, kTol);
  }
}

TEST(BulletContacts, CylinderAndConeOnPlaneMatchClosedForm) {
  QueryWorld w;
  btStaticPlaneShape plane(btVector3(0, 1, 0), 0);
  btCylinderShape cylinder(btVector3(0.5, 1, 0.5));
  btConeShape cone(0.5, 2);
  cone.setMargin(0);
  auto* ground = w.add(&plane, btVector3(0, 0, 0));
  auto* cyl = w.add(&cylinder, btVector3(0, 0.98, 0));
  auto* con = w.add(&cone, btVector3(3, 0.99, 0));
  const auto cylPts = w.contacts(cyl, ground);
  ASSERT_GE(cylPts.size(), 3u);  // the cap rim
  for (const Point& p : cylPts) {
    EXPECT_NEAR(p.distance, -0.02, kTol);
    expectVec(p.normalOnB, btVector3(0, 1, 0), kTol);
  }
  const auto conePts = w.contacts(con, ground);
  ASSERT_GE(conePts.size(), 1u);
  for (const Point& p : conePts) EXPECT_NEAR(p.distance, -0.01, kTol);
}

TEST(BulletContacts, ClosestPointThresholdOfContactTestIsHonoured) {
  QueryWorld w;
  btSphereShape s(1);
  auto* a = w.add(&s, btVector3(0, 0, 0));
  auto* b = w.add(&s, btVector3(2.5, 0, 0));
  EXPECT_TRUE(w.contacts(a, b).empty());  // gap 0.5 > contact breaking threshold
  const auto pts = w.contacts(a, b, 1);
  ASSERT_EQ(pts.size(), 1u);
  EXPECT_NEAR(pts[0].distance, 0.5, kTol);
}

TEST(BulletContacts, SphereOnBvhAndScaledMeshNamesTheTriangle) {
  QueryWorld w;
  ShapeStore store;
  btBvhTriangleMeshShape* flat = flatMesh(store, 5, 2, 1);  // y = 1, 32 triangles
  btScaledBvhTriangleMeshShape scaled(flat, btVector3(2, 0.5, 2));  // surface at y = 0.5
  btSphereShape ball(0.5);
  auto* mesh = w.add(flat, btVector3(0, 0, 0));
  auto* s = w.add(&ball, btVector3(0.3, 1.48, 0.2));
  // The triangle under the centre gives the deepest point; neighbouring triangles may add edge points (never deeper).
  const auto pts = w.contacts(s, mesh);
  ASSERT_GE(pts.size(), 1u);
  const Point* deepest = &pts[0];
  for (const Point& p : pts) {
    if (p.distance < deepest->distance) deepest = &p;
    EXPECT_GE(p.distance, -0.02 - kTol);
    EXPECT_EQ(p.partB, 0);
    EXPECT_GE(p.indexB, 0);
    EXPECT_LT(p.indexB, 32);
  }
  EXPECT_NEAR(deepest->distance, -0.02, kTol);
  expectVec(deepest->normalOnB, btVector3(0, 1, 0), kTol);
  auto* scaledMesh = w.add(&scaled, btVector3(20, 0, 0));
  auto* s2 = w.add(&ball, btVector3(20.3, 0.97, 0.2));
  const auto scaledPts = w.contacts(s2, scaledMesh);
  ASSERT_GE(scaledPts.size(), 1u);
  btScalar deepestScaled = 1;
  for (const Point& p : scaledPts) deepestScaled = std::min(deepestScaled, p.distance);
  EXPECT_NEAR(deepestScaled, -0.03, kTol);
}

// A box tilted on a mesh: a manifold gets its touching corners only (points still apart would take its places), a
// contactTest that widened its closest-distance threshold gets the corners apart too, at their exact distances.
TEST(BulletContacts, WidenedContactTestThresholdKeepsMeshPointsStillApart) {
  QueryWorld w;
  ShapeStore store;
  btBvhTriangleMeshShape* flat = flatMesh(store, 5, 2, 1);  // y = 1
  btBoxShape box(btVector3(0.5, 0.5, 0.5));
  const double tilt = 0.01;  // about z: the bottom edge at -x 2 mm into the surface, the one at +x sin(tilt) higher
  const double centreY = 1 - 0.002 + 0.5 * std::cos(tilt) + 0.5 * std::sin(tilt);
  auto* mesh = w.add(flat, btVector3(0, 0, 0));
  auto* b = w.add(&box, btVector3(0.3, btScalar(centreY), 0.2), btQuaternion(btVector3(0, 0, 1), btScalar(tilt)));
  const auto touching = w.contacts(b, mesh);
  ASSERT_GE(touching.size(), 2u);
  btScalar deepest = 1;
  for (const Point& p : touching) {
    EXPECT_LE(p.distance, kTol);  // the bottom face's part under the surface (corners, mesh vertices under it)
    deepest = std::min(deepest, p.distance);
  }
  EXPECT_NEAR(deepest, -0.002, kTol);
  const auto all = w.contacts(b, mesh, btScalar(0.05));
  btScalar highest = -1;
  for (const Point& p : all) highest = std::max(highest, p.distance);
  EXPECT_GT(all.size(), touching.size());
  EXPECT_NEAR(highest, std::sin(tilt) - 0.002, kTol);
}

// Bullet centres a heightfield on its AABB midpoint: local height = h - (minH + maxH) / 2. Heights 0.25 * x on a
// 5 x 5 grid with range [0, 1] make the plane up = 0.25 * (first horizontal axis) in the shape frame, for every
// up axis; a sphere 0.31 from it must touch at distance 0.01 along the plane normal.
TEST(BulletContacts, HeightFieldCentringAndUpAxesMatchClosedForm) {
  for (int up = 0; up < 3; ++up) {
    QueryWorld w;
    ShapeStore store;
    std::vector<float> h(25);
    for (int j = 0; j < 5; ++j)
      for (int x = 0; x < 5; ++x) h[std::size_t(j * 5 + x)] = 0.25f * float(x);
    auto* field = store.make<btHeightfieldTerrainShape>(5, 5, store.heights.emplace_back(
        std::make_unique<std::vector<float>>(h))->data(), btScalar(0), btScalar(1), up, false);
    // The horizontal axis along which the height grows (Bullet's x index) and the up axis.
    const int slopeAxis = up == 0 ? 1 : 0;
    btVector3 normal(0, 0, 0);
    normal[up] = 1;
    normal[slopeAxis] = btScalar(-0.25);
    normal.normalize();
    btVector3 onPlane(0, 0, 0);
    onPlane[slopeAxis] = btScalar(0.1);
    onPlane[up] = btScalar(0.025);
    onPlane[3 - up - slopeAxis] = btScalar(0.3);
    btSphereShape ball(btScalar(0.3));
    auto* terrain = w.add(field, btVector3(0, 0, 0));
    auto* s = w.add(&ball, onPlane + normal * btScalar(0.31));
    const auto pts = w.contacts(s, terrain);
    ASSERT_GE(pts.size(), 1u) << "up axis " << up;
    for (const Point& p : pts) {
      EXPECT_NEAR(p.distance, 0.01, kTol) << "up axis " << up;
      expectVec(p.normalOnB, normal, kTol);
    }
  }
}

// Bullet's compound algorithm dispatches each child pair through the same tables, so children reach gq.
TEST(BulletContacts, CompoundChildrenGetContactsEach) {
  QueryWorld w;
  btSphereShape ball(btScalar(0.5));
  btBoxShape brick(btVector3(0.5, 0.25, 0.5));
  btCompoundShape compound;
  compound.addChildShape(btTransform(btQuaternion::getIdentity(), btVector3(-1, 0, 0)), &ball);
  compound.addChildShape(btTransform(btQuaternion::getIdentity(), btVector3(1, btScalar(-0.26), 0)), &brick);
  btStaticPlaneShape plane(btVector3(0, 1, 0), 0);
  auto* ground = w.add(&plane, btVector3(0, 0, 0));
  auto* body = w.add(&compound, btVector3(0, btScalar(0.49), 0));
  const auto pts = w.contacts(body, ground);
  for (const Point& p : pts) std::printf("pt %f %f %f d %f\n", double(p.pointOnB.x()), double(p.pointOnB.y()), double(p.pointOnB.z()), double(p.distance));
  ASSERT_EQ(pts.size(), 5u);  // the sphere's point and the brick's four corners
  int sphereHits = 0;
  for (const Point& p : pts) {
    // sphere bottom at 0.49 - 0.5; brick bottom at 0.49 - 0.26 - 0.25
    EXPECT_NEAR(p.distance, std::abs(p.pointOnB.x() + 1) < kTol ? -0.01 : -0.02, kTol);
    expectVec(p.normalOnB, btVector3(0, 1, 0), kTol);
    if (std::abs(p.pointOnB.x() + 1) < kTol) ++sphereHits;
  }
  EXPECT_EQ(sphereHits, 1);
}

// Shapes gq does not model (here btConvexPointCloudShape) keep Bullet's own algorithms in a gq world.
TEST(BulletContacts, UnmodelledShapesFallBackToBullet) {
  QueryWorld w;
  btVector3 corners[8];
  for (int i = 0; i < 8; ++i) corners[i] = btVector3(i & 1 ? 0.5 : -0.5, i & 2 ? 0.5 : -0.5, i & 4 ? 0.5 : -0.5);
  btConvexPointCloudShape cloud(corners, 8, btVector3(1, 1, 1), false);
  cloud.setMargin(0);
  btBoxShape ground(btVector3(5, 1, 5));
  auto* g = w.add(&ground, btVector3(0, -1, 0));
  auto* p = w.add(&cloud, btVector3(0, btScalar(0.48), 0));
  const auto pts = w.contacts(p, g);
  ASSERT_GE(pts.size(), 1u);
  for (const Point& c : pts) EXPECT_NEAR(c.distance, -0.02, btScalar(1e-3));  // Bullet's GJK tolerance
}

// btMultiSphereShape is the convex hull of its spheres: two spheres of radius 0.5 at x = -0.5, 0.5 make a capsule.
// Resting 0.02 deep on a box, and hit from above at x = 0 at height 0.5 (the hull; their union would give 0).
TEST(BulletContacts, MultiSphereIsTheHullOfItsSpheres) {
  QueryWorld w;
  const btVector3 centres[3] = {btVector3(-0.5, 0, 0), btVector3(0.5, 0, 0), btVector3(0, 0, 0.3)};
  const btScalar radii[3] = {0.5, 0.5, 0.25};
  btMultiSphereShape pill(centres, radii, 3);
  btBoxShape ground(btVector3(5, 1, 5));
  auto* g = w.add(&ground, btVector3(0, -1, 0));
  auto* p = w.add(&pill, btVector3(0, btScalar(0.48), 0));
  const auto pts = w.contacts(p, g);
  ASSERT_GE(pts.size(), 1u);
  for (const Point& c : pts) EXPECT_NEAR(c.distance, -0.02, kTol);
  TestWorld world(Backend::Gq);
  world.add(&pill, 0, btVector3(0, 0, 0));
  btCollisionWorld::ClosestRayResultCallback ray(btVector3(0, 5, 0), btVector3(0, -5, 0));
  world.world().rayTest(btVector3(0, 5, 0), btVector3(0, -5, 0), ray);
  ASSERT_TRUE(ray.hasHit());
  EXPECT_NEAR(5 - 10 * ray.m_closestHitFraction, 0.5, kTol * 10);
  EXPECT_NEAR(ray.m_hitNormalWorld.y(), 1, kTol * 10);
}

}  // namespace
}  // namespace gq::bullet::test
