// DART's conventions through the gq detector: contact sets, normal from object 2 towards object 1, positive depth,
// signed distance, sorted ray hits, filters, contact limits, group-vs-group queries, triangle ids.
#include <gtest/gtest.h>

#include <dart/collision/CollisionFilter.hpp>
#include <dart/collision/CollisionObject.hpp>
#include <dart/collision/CollisionResult.hpp>
#include <dart/collision/DistanceResult.hpp>
#include <dart/collision/RaycastResult.hpp>
#include <dart/dynamics/PlaneShape.hpp>

#include "dart_scene.h"

namespace {

using namespace gqtest;

TEST(DartConventions, BoxRestingOnBoxFaceGivesFourContacts) {
  auto d = detector("gq");
  auto ground = frame(std::make_shared<dd::BoxShape>(Eigen::Vector3d(4, 4, 1)), at(Eigen::Vector3d(0, 0, -0.5)));
  auto box = frame(std::make_shared<dd::BoxShape>(Eigen::Vector3d(1, 1, 1)), at(Eigen::Vector3d(0.2, 0.1, 0.49)));
  auto group = d->createCollisionGroup(box.get(), ground.get());
  dc::CollisionResult result;
  ASSERT_TRUE(d->collide(group.get(), dc::CollisionOption(true, 100), &result));
  ASSERT_EQ(result.getNumContacts(), 4u);
  for (const dc::Contact& c : result.getContacts()) {
    const bool boxIsFirst = c.collisionObject1->getShapeFrame() == box.get();
    // From object 2 towards object 1.
    EXPECT_NEAR(c.normal.z(), boxIsFirst ? 1.0 : -1.0, 1e-9);
    EXPECT_NEAR(c.penetrationDepth, 0.01, 1e-9);
    EXPECT_NEAR(std::abs(c.point.x() - 0.2), 0.5, 1e-9);
    EXPECT_NEAR(std::abs(c.point.y() - 0.1), 0.5, 1e-9);
  }
}

TEST(DartConventions, SphereNormalPointsFromObjectTwoToObjectOne) {
  auto d = detector("gq");
  auto a = frame(std::make_shared<dd::SphereShape>(1.0), at(Eigen::Vector3d(0, 0, 0)), "a");
  auto b = frame(std::make_shared<dd::SphereShape>(1.0), at(Eigen::Vector3d(1.5, 0, 0)), "b");
  auto group = d->createCollisionGroup(a.get(), b.get());
  dc::CollisionResult result;
  ASSERT_TRUE(d->collide(group.get(), dc::CollisionOption(true, 10), &result));
  ASSERT_EQ(result.getNumContacts(), 1u);
  const dc::Contact& c = result.getContact(0);
  const Eigen::Vector3d p1 = c.collisionObject1->getTransform().translation();
  const Eigen::Vector3d p2 = c.collisionObject2->getTransform().translation();
  EXPECT_GT(c.normal.dot(p1 - p2), 0.99 * (p1 - p2).norm());
  EXPECT_NEAR(c.penetrationDepth, 0.5, 1e-9);
  EXPECT_NEAR(c.point.x(), 0.75, 1e-9);
}

TEST(DartConventions, BooleanQueryWithoutResult) {
  auto d = detector("gq");
  auto a = frame(std::make_shared<dd::SphereShape>(1.0), at(Eigen::Vector3d(0, 0, 0)), "a");
  auto b = frame(std::make_shared<dd::SphereShape>(1.0), at(Eigen::Vector3d(2.5, 0, 0)), "b");
  auto group = d->createCollisionGroup(a.get(), b.get());
  EXPECT_FALSE(d->collide(group.get()));
  b->setTranslation(Eigen::Vector3d(1.9, 0, 0));
  EXPECT_TRUE(d->collide(group.get()));
}

TEST(DartConventions, MaxNumContactsBoundsTheQuery) {
  auto d = detector("gq");
  auto ground = frame(std::make_shared<dd::BoxShape>(Eigen::Vector3d(4, 4, 1)), at(Eigen::Vector3d(0, 0, -0.5)));
  auto box = frame(std::make_shared<dd::BoxShape>(Eigen::Vector3d(1, 1, 1)), at(Eigen::Vector3d(0, 0, 0.49)));
  auto group = d->createCollisionGroup(box.get(), ground.get());
  dc::CollisionResult result;
  ASSERT_TRUE(d->collide(group.get(), dc::CollisionOption(true, 2), &result));
  EXPECT_EQ(result.getNumContacts(), 2u);
}

struct IgnoreAll : dc::CollisionFilter {
  bool ignoresCollision(const dc::CollisionObject*, const dc::CollisionObject*) const override { return true; }
};

TEST(DartConventions, CollisionFilterIsAsked) {
  auto d = detector("gq");
  auto a = frame(std::make_shared<dd::SphereShape>(1.0), at(Eigen::Vector3d(0, 0, 0)), "a");
  auto b = frame(std::make_shared<dd::SphereShape>(1.0), at(Eigen::Vector3d(1.5, 0, 0)), "b");
  auto group = d->createCollisionGroup(a.get(), b.get());
  dc::CollisionResult result;
  EXPECT_FALSE(d->collide(group.get(), dc::CollisionOption(true, 10, std::make_shared<IgnoreAll>()), &result));
  EXPECT_EQ(result.getNumContacts(), 0u);
}

TEST(DartConventions, GroupAgainstGroup) {
  auto d = detector("gq");
  auto a = frame(std::make_shared<dd::SphereShape>(1.0), at(Eigen::Vector3d(0, 0, 0)), "a");
  auto b = frame(std::make_shared<dd::SphereShape>(1.0), at(Eigen::Vector3d(1.5, 0, 0)), "b");
  auto c = frame(std::make_shared<dd::SphereShape>(1.0), at(Eigen::Vector3d(10, 0, 0)), "c");
  auto g1 = d->createCollisionGroup(a.get(), b.get());
  auto g2 = d->createCollisionGroup(c.get());
  EXPECT_FALSE(d->collide(g1.get(), g2.get()));
  c->setTranslation(Eigen::Vector3d(3.0, 0, 0));
  dc::CollisionResult result;
  ASSERT_TRUE(d->collide(g1.get(), g2.get(), dc::CollisionOption(true, 10), &result));
  ASSERT_EQ(result.getNumContacts(), 1u);
  EXPECT_EQ(result.getContact(0).collisionObject1->getShapeFrame(), b.get());
  EXPECT_EQ(result.getContact(0).collisionObject2->getShapeFrame(), c.get());
  // Distance between the groups: b to c, 0.5 apart.
  dc::DistanceResult dist;
  c->setTranslation(Eigen::Vector3d(4.0, 0, 0));
  EXPECT_NEAR(d->distance(g1.get(), g2.get(), dc::DistanceOption(true, -1e9), &dist), 0.5, 1e-9);
  EXPECT_EQ(dist.shapeFrame1, b.get());
  EXPECT_NEAR(dist.nearestPoint1.x(), 2.5, 1e-9);
  EXPECT_NEAR(dist.nearestPoint2.x(), 3.0, 1e-9);
}

TEST(DartConventions, DistanceIsSignedAndClampedByTheLowerBound) {
  auto d = detector("gq");
  auto a = frame(std::make_shared<dd::BoxShape>(Eigen::Vector3d(1, 1, 1)), at(Eigen::Vector3d(0, 0, 0)), "a");
  auto b = frame(std::make_shared<dd::SphereShape>(0.5), at(Eigen::Vector3d(1.2, 0, 0)), "b");
  auto group = d->createCollisionGroup(a.get(), b.get());
  dc::DistanceResult result;
  // Penetrating by 0.5 - 0.7 + ... : sphere centre 0.7 from the face, radius 0.5: 0.2 apart.
  EXPECT_NEAR(d->distance(group.get(), dc::DistanceOption(true, -1e9), &result), 0.2, 1e-9);
  b->setTranslation(Eigen::Vector3d(0.8, 0, 0));  // 0.2 deep
  EXPECT_NEAR(d->distance(group.get(), dc::DistanceOption(true, -1e9), &result), -0.2, 1e-9);
  EXPECT_NEAR(result.unclampedMinDistance, -0.2, 1e-9);
  // The default lower bound 0 clamps it (DART's convention), unclampedMinDistance keeps it.
  EXPECT_NEAR(d->distance(group.get(), dc::DistanceOption(false, 0.0), &result), 0.0, 1e-12);
  EXPECT_NEAR(result.unclampedMinDistance, -0.2, 1e-9);
  EXPECT_TRUE(result.found());
}

TEST(DartConventions, RayHitsAreSortedAndClosestIsFirst) {
  auto d = detector("gq");
  auto near = frame(std::make_shared<dd::SphereShape>(0.5), at(Eigen::Vector3d(2, 0, 0)), "near");
  auto far = frame(std::make_shared<dd::BoxShape>(Eigen::Vector3d(1, 1, 1)), at(Eigen::Vector3d(5, 0, 0)), "far");
  auto group = d->createCollisionGroup(far.get(), near.get());
  dc::RaycastResult result;
  ASSERT_TRUE(d->raycast(group.get(), Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(10, 0, 0), dc::RaycastOption(true, true),
                         &result));
  ASSERT_EQ(result.mRayHits.size(), 2u);
  EXPECT_NEAR(result.mRayHits[0].mFraction, 0.15, 1e-9);
  EXPECT_NEAR(result.mRayHits[1].mFraction, 0.45, 1e-9);
  EXPECT_NEAR(result.mRayHits[0].mNormal.x(), -1.0, 1e-9);
  EXPECT_EQ(result.mRayHits[1].mCollisionObject->getShapeFrame(), far.get());
  ASSERT_TRUE(d->raycast(group.get(), Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(10, 0, 0), dc::RaycastOption(),
                         &result));
  ASSERT_EQ(result.mRayHits.size(), 1u);
  EXPECT_EQ(result.mRayHits[0].mCollisionObject->getShapeFrame(), near.get());
  EXPECT_FALSE(d->raycast(group.get(), Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), dc::RaycastOption(),
                          &result));
}

TEST(DartConventions, MeshContactsCarryTriangleIds) {
  auto d = detector("gq");
  auto ground = frame(groundMesh(2.0, 4), at(Eigen::Vector3d::Zero()), "ground");
  auto box = frame(std::make_shared<dd::BoxShape>(Eigen::Vector3d(0.4, 0.4, 0.4)), at(Eigen::Vector3d(0.3, 0.3, 0.19)),
                   "box");
  auto group = d->createCollisionGroup(ground.get(), box.get());
  dc::CollisionResult result;
  ASSERT_TRUE(d->collide(group.get(), dc::CollisionOption(true, 100), &result));
  ASSERT_EQ(result.getNumContacts(), 4u);
  for (const dc::Contact& c : result.getContacts()) {
    const bool meshIsFirst = c.collisionObject1->getShapeFrame() == ground.get();
    const int tri = meshIsFirst ? c.triID1 : c.triID2;
    EXPECT_GE(tri, 0);
    EXPECT_LT(tri, 32);
    EXPECT_NEAR(c.normal.z(), meshIsFirst ? -1.0 : 1.0, 1e-9);
    EXPECT_NEAR(c.penetrationDepth, 0.01, 1e-9);
  }
}

TEST(DartConventions, SphereOnHeightmap) {
  auto d = detector("gq");
  auto ground = frame(flatHeightmap(9, 0.5, 0.0), at(Eigen::Vector3d::Zero()), "ground");
  auto ball = frame(std::make_shared<dd::SphereShape>(0.3), at(Eigen::Vector3d(0.1, 0.2, 0.25)), "ball");
  auto group = d->createCollisionGroup(ball.get(), ground.get());
  dc::CollisionResult result;
  ASSERT_TRUE(d->collide(group.get(), dc::CollisionOption(true, 100), &result));
  ASSERT_GE(result.getNumContacts(), 1u);
  const dc::Contact& c = result.getContact(0);
  const bool ballIsFirst = c.collisionObject1->getShapeFrame() == ball.get();
  EXPECT_NEAR(c.normal.z(), ballIsFirst ? 1.0 : -1.0, 1e-6);
  EXPECT_NEAR(c.penetrationDepth, 0.05, 1e-6);
}

// A surface reaches into a plane's half-space through its vertices: each vertex below the plane is a contact as deep
// as it lies below, along the plane's normal (a mesh tilted about y dips its x = +1 edge 2 * sin(0.1) / 2 below).
TEST(DartConventions, MeshOnPlaneTouchesThroughItsVerticesBelowThePlane) {
  auto d = detector("gq");
  auto plane = frame(std::make_shared<dd::PlaneShape>(Eigen::Vector3d(0, 0, 1), 0.0), at(Eigen::Vector3d::Zero()),
                     "plane");
  const double tilt = 0.1;
  auto mesh = frame(groundMesh(1.0, 4),
                    at(Eigen::Vector3d(0, 0, 0.0), Eigen::Quaterniond(Eigen::AngleAxisd(tilt, Eigen::Vector3d::UnitY()))),
                    "mesh");
  auto group = d->createCollisionGroup(plane.get(), mesh.get());
  dc::CollisionResult result;
  ASSERT_TRUE(d->collide(group.get(), dc::CollisionOption(true, 100), &result));
  ASSERT_EQ(result.getNumContacts(), 4u);
  double deepest = 0.0;
  for (const dc::Contact& c : result.getContacts()) {
    const bool meshIsFirst = c.collisionObject1->getShapeFrame() == mesh.get();
    EXPECT_NEAR(c.normal.z(), meshIsFirst ? 1.0 : -1.0, 1e-12);
    const int tri = meshIsFirst ? c.triID1 : c.triID2;
    EXPECT_GE(tri, 0);
    EXPECT_LT(tri, 32);
    EXPECT_GE(c.penetrationDepth, 0.0);
    EXPECT_NEAR(c.point.z(), -0.5 * c.penetrationDepth, 1e-12);  // midway between the vertex and the plane
    EXPECT_GE(c.point.x(), -1e-12);                                // only the half that dips below
    deepest = std::max(deepest, c.penetrationDepth);
  }
  EXPECT_NEAR(deepest, std::sin(tilt), 1e-12);
  // Lifted clear of the plane: no contact.
  auto lifted = frame(groundMesh(1.0, 4), at(Eigen::Vector3d(0, 0, 0.2)), "lifted");
  auto apart = d->createCollisionGroup(plane.get(), lifted.get());
  EXPECT_FALSE(d->collide(apart.get(), dc::CollisionOption(true, 100), nullptr));
}

TEST(DartConventions, HeightmapBelowAPlaneTouchesItAtItsSamples) {
  auto d = detector("gq");
  auto plane = frame(std::make_shared<dd::PlaneShape>(Eigen::Vector3d(0, 0, 1), 0.0), at(Eigen::Vector3d::Zero()),
                     "plane");
  auto ground = frame(flatHeightmap(5, 0.5, 0.3), at(Eigen::Vector3d(0, 0, -0.35)), "ground");
  auto group = d->createCollisionGroup(ground.get(), plane.get());
  dc::CollisionResult result;
  ASSERT_TRUE(d->collide(group.get(), dc::CollisionOption(true, 100), &result));
  ASSERT_EQ(result.getNumContacts(), 4u);
  for (const dc::Contact& c : result.getContacts()) {
    const bool groundIsFirst = c.collisionObject1->getShapeFrame() == ground.get();
    EXPECT_NEAR(c.normal.z(), groundIsFirst ? 1.0 : -1.0, 1e-12);
    EXPECT_NEAR(c.penetrationDepth, 0.05, 1e-6);  // float heights
  }
}

// A closed cube mesh 0.01 into a ground mesh or a heightmap: its side triangles cross the ground and touch along the
// ground's face normal, 0.01 deep, with both triangle ids; lifted clear, no contact.
std::shared_ptr<dd::MeshShape> cubeMesh(double half) {
  std::vector<Eigen::Vector3d> v;
  for (int i = 0; i < 8; ++i) v.emplace_back(i & 1 ? half : -half, i & 2 ? half : -half, i & 4 ? half : -half);
  const std::vector<std::array<unsigned, 3>> t = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                                                  {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return std::make_shared<dd::MeshShape>(Eigen::Vector3d::Ones(),
                                         std::shared_ptr<const aiScene>(meshScene(v, t), [](const aiScene*) {}).get());
}

TEST(DartConventions, MeshOnMeshOrHeightmapTouchesAlongTheGroundNormal) {
  auto d = detector("gq");
  auto cube = frame(cubeMesh(0.2), at(Eigen::Vector3d(0.35, 0.35, 0.19)), "cube");  // sides off the grid lines
  for (const dd::ShapePtr& groundShape : {dd::ShapePtr(groundMesh(2.0, 4)), dd::ShapePtr(flatHeightmap(9, 0.5, 0.0))}) {
    auto ground = frame(groundShape, at(Eigen::Vector3d::Zero()), "ground");
    auto group = d->createCollisionGroup(ground.get(), cube.get());
    dc::CollisionResult result;
    ASSERT_TRUE(d->collide(group.get(), dc::CollisionOption(true, 100), &result)) << groundShape->getType();
    ASSERT_GE(result.getNumContacts(), 3u) << groundShape->getType();
    for (const dc::Contact& c : result.getContacts()) {
      const bool groundIsFirst = c.collisionObject1->getShapeFrame() == ground.get();
      EXPECT_NEAR(c.normal.z(), groundIsFirst ? -1.0 : 1.0, 1e-9) << groundShape->getType();
      EXPECT_NEAR(c.penetrationDepth, 0.01, 1e-6) << groundShape->getType();
      EXPECT_GE(c.triID1, 0);
      EXPECT_GE(c.triID2, 0);
    }
    auto lifted = frame(cubeMesh(0.2), at(Eigen::Vector3d(0.35, 0.35, 0.25)), "lifted");
    auto apart = d->createCollisionGroup(ground.get(), lifted.get());
    EXPECT_FALSE(d->collide(apart.get(), dc::CollisionOption(true, 100), nullptr)) << groundShape->getType();
  }
}

}  // namespace
