// FCL's conventions as gq::fcl keeps them, the opt-in corrections (FCL bugs fcl#545 and fcl#628), the geometry cache's
// re-conversion rule and the fallback to FCL. Expected values are closed forms.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <set>
#include <thread>
#include <vector>

#include "gq/fcl/fcl.h"

namespace {

using ::fcl::Vector3d;
constexpr int kNone = -1;  // ::fcl::Contact::NONE (declared without a definition: not odr-usable)

::fcl::Transform3d at(double x, double y, double z) {
  ::fcl::Transform3d tf = ::fcl::Transform3d::Identity();
  tf.translation() = Vector3d(x, y, z);
  return tf;
}

std::shared_ptr<::fcl::BVHModel<::fcl::OBBRSSd>> twoTriangles() {
  auto model = std::make_shared<::fcl::BVHModel<::fcl::OBBRSSd>>();
  model->beginModel();
  model->addTriangle(Vector3d(-1, -1, 0), Vector3d(1, -1, 0), Vector3d(0, 1, 0));      // id 0, at z = 0
  model->addTriangle(Vector3d(9, -1, 0), Vector3d(11, -1, 0), Vector3d(10, 1, 0));     // id 1, around x = 10
  model->endModel();
  return model;
}

TEST(FclConventions, ResultsAreAppendedNotCleared) {
  ::fcl::Sphered a(1), b(1);
  ::fcl::CollisionRequestd request(10, true);
  ::fcl::CollisionResultd result;
  gq::fcl::collide(&a, at(0, 0, 0), &b, at(1.5, 0, 0), request, result);
  const std::size_t n = gq::fcl::collide(&a, at(0, 0, 0), &b, at(0, 1.5, 0), request, result);
  EXPECT_EQ(n, 2u);
  EXPECT_EQ(result.numContacts(), 2u);
}

TEST(FclConventions, NormalPointsFromO1ToO2WithPositiveDepthAndWorldPosition) {
  ::fcl::Sphered a(1), b(1);
  ::fcl::CollisionRequestd request(1, true);
  ::fcl::CollisionResultd result;
  ASSERT_EQ(gq::fcl::collide(&a, at(2, 0, 0), &b, at(3.5, 0, 0), request, result), 1u);
  const ::fcl::Contactd& c = result.getContact(0);
  EXPECT_NEAR(c.penetration_depth, 0.5, 1e-12);
  EXPECT_NEAR((c.normal - Vector3d::UnitX()).norm(), 0, 1e-12);
  EXPECT_NEAR((c.pos - Vector3d(2.75, 0, 0)).norm(), 0, 1e-12);  // midway between the deepest points 3 and 2.5
  EXPECT_EQ(c.b1, kNone);
  EXPECT_EQ(c.o1, &a);
  EXPECT_EQ(c.o2, &b);
}

TEST(FclConventions, WithoutEnableContactAPairAddsOneContactWithoutGeometry) {
  ::fcl::Sphered a(1), b(1);
  ::fcl::CollisionRequestd request;  // 1 contact, no contact data
  ::fcl::CollisionResultd result;
  EXPECT_EQ(gq::fcl::collide(&a, at(0, 0, 0), &b, at(1.9, 0, 0), request, result), 1u);
  ::fcl::CollisionResultd apart;
  EXPECT_EQ(gq::fcl::collide(&a, at(0, 0, 0), &b, at(2.1, 0, 0), request, apart), 0u);
}

TEST(FclConventions, CapsuleCylinderAndConeRunAlongLocalZWithFullLength) {
  ::fcl::Capsuled capsule(0.1, 2);  // segment z in [-1, 1]
  ::fcl::Cylinderd cylinder(0.1, 2);
  ::fcl::Coned cone(0.5, 2);  // apex at z = +1, base at z = -1
  ::fcl::Sphered probe(0.1);
  ::fcl::CollisionRequestd request;
  const auto hits = [&](const ::fcl::CollisionGeometryd& g, double x, double y, double z) {
    ::fcl::CollisionResultd r;
    return gq::fcl::collide(&g, at(0, 0, 0), &probe, at(x, y, z), request, r) > 0;
  };
  EXPECT_TRUE(hits(capsule, 0, 0, 1.15));   // tip at 1.1, probe from 1.05
  EXPECT_FALSE(hits(capsule, 0, 0, 1.25));  // gap 0.05
  EXPECT_FALSE(hits(capsule, 1.15, 0, 0));  // the axis is not X
  EXPECT_TRUE(hits(cylinder, 0, 0, 1.05));
  EXPECT_FALSE(hits(cylinder, 0, 0, 1.15));
  EXPECT_TRUE(hits(cone, 0, 0, 1.05));      // apex
  EXPECT_FALSE(hits(cone, 0.3, 0, 0.9));    // the side at z = 0.9 is at radius 0.025: gap ~0.17
  EXPECT_TRUE(hits(cone, 0.55, 0, -0.95));  // near the base rim
}

TEST(FclConventions, MinDistanceOnlyChangesWhenSmaller) {
  ::fcl::Sphered a(1), b(1);
  ::fcl::DistanceRequestd request(true);
  ::fcl::DistanceResultd result;
  result.min_distance = 0.1;  // pre-seeded (as MoveIt does)
  EXPECT_DOUBLE_EQ(gq::fcl::distance(&a, at(0, 0, 0), &b, at(3, 0, 0), request, result), 0.1);
  EXPECT_DOUBLE_EQ(result.min_distance, 0.1);
  EXPECT_EQ(result.o1, nullptr);
  EXPECT_NEAR(gq::fcl::distance(&a, at(0, 0, 0), &b, at(2.05, 0, 0), request, result), 0.05, 1e-12);
  EXPECT_EQ(result.o1, &a);
  EXPECT_NEAR((result.nearest_points[0] - Vector3d(1, 0, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR((result.nearest_points[1] - Vector3d(1.05, 0, 0)).norm(), 0, 1e-12);
}

TEST(FclConventions, SignedDistanceIsMinusThePenetrationDepth) {
  ::fcl::Boxd a(2, 2, 2), b(2, 2, 2);
  ::fcl::DistanceRequestd request(true);
  request.enable_signed_distance = true;
  ::fcl::DistanceResultd result;
  EXPECT_NEAR(gq::fcl::distance(&a, at(0, 0, 0), &b, at(1.7, 0.2, 0), request, result), -0.3, 1e-12);
}

// Without enable_signed_distance (nearest points requested), gq::fcl and FCL both answer the overlapping pair with -1
// and both nearest points at the origin.
void expectMinusOneWithPointsAtTheOriginAsFcl(const ::fcl::CollisionGeometryd* g1, const ::fcl::Transform3d& tf1,
                                              const ::fcl::CollisionGeometryd* g2, const ::fcl::Transform3d& tf2) {
  const ::fcl::DistanceRequestd unsignedRequest(true);
  ::fcl::DistanceResultd gqResult, fclResult;
  EXPECT_EQ(gq::fcl::distance(g1, tf1, g2, tf2, unsignedRequest, gqResult), -1.0);
  ::fcl::distance(g1, tf1, g2, tf2, unsignedRequest, fclResult);
  EXPECT_EQ(fclResult.min_distance, -1.0);
  for (int i : {0, 1}) {
    EXPECT_EQ(gqResult.nearest_points[i], fclResult.nearest_points[i]);
    EXPECT_EQ(gqResult.nearest_points[i], Vector3d::Zero());
  }
}

// Without enable_signed_distance FCL answers a penetrating GJK pair with -1 and nearest points at the origin (its
// GJK path stops at the overlap); gq::fcl does the same instead of running EPA. A cylinder (radius 1, length 2)
// 0.25 into a box face: the exact depth is 0.25 (signed request).
TEST(FclConventions, WithoutSignedDistanceAPenetratingGjkPairIsMinusOneAsFcl) {
  ::fcl::Cylinderd cylinder(1, 2);
  ::fcl::Boxd box(2, 2, 2);
  expectMinusOneWithPointsAtTheOriginAsFcl(&cylinder, at(0, 0, 0), &box, at(0, 0, 1.75));
  const ::fcl::DistanceRequestd unsignedRequest(true);
  ::fcl::DistanceRequestd signedRequest(true);
  signedRequest.enable_signed_distance = true;
  ::fcl::DistanceResultd withDepth;
  EXPECT_NEAR(gq::fcl::distance(&cylinder, at(0, 0, 0), &box, at(0, 0, 1.75), signedRequest, withDepth), -0.25, 1e-6);
  ::fcl::DistanceResultd apart;  // separated: the distance, signed request or not
  EXPECT_NEAR(gq::fcl::distance(&cylinder, at(0, 0, 0), &box, at(0, 0, 2.5), unsignedRequest, apart), 0.5, 1e-6);
}

// The same for two Convex cubes (sides 2): centres 1.75 apart overlap (their inscribed balls do, which answers
// without GJK), 2.5 and 4 apart are 0.5 and 2 apart (GJK; the second also beyond their circumscribed balls).
TEST(FclConventions, WithoutSignedDistanceOverlappingConvexHullsAreMinusOneAsFcl) {
  auto corners = std::make_shared<std::vector<Vector3d>>();
  for (int i = 0; i < 8; ++i) corners->emplace_back(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
  // Quads counter-clockwise from outside: -x, +x, -y, +y, -z, +z.
  auto faces = std::make_shared<std::vector<int>>(std::vector<int>{4, 0, 4, 6, 2, 4, 1, 3, 7, 5, 4, 0, 1, 5, 4,
                                                                   4, 2, 6, 7, 3, 4, 0, 2, 3, 1, 4, 4, 5, 7, 6});
  const ::fcl::Convexd cube(corners, 6, faces);
  expectMinusOneWithPointsAtTheOriginAsFcl(&cube, at(0, 0, 0), &cube, at(0, 0, 1.75));
  const ::fcl::DistanceRequestd unsignedRequest(true);
  for (const double gap : {0.5, 2.0}) {
    ::fcl::DistanceResultd apart;
    EXPECT_NEAR(gq::fcl::distance(&cube, at(0, 0, 0), &cube, at(0, 0, 2 + gap), unsignedRequest, apart), gap, 1e-9);
  }
}

// Boxes as FCL 0.7 (libccd's GJK on them): overlapping without the request is -1 with nearest points at the origin
// (their witnesses would cost a search); with it, the exact depth; separated, the distance either way.
TEST(FclConventions, WithoutSignedDistanceOverlappingBoxesAreMinusOneAsFcl) {
  ::fcl::Boxd a(2, 2, 2), b(2, 2, 2);
  expectMinusOneWithPointsAtTheOriginAsFcl(&a, at(0, 0, 0), &b, at(1.7, 0.2, 0));
  const ::fcl::DistanceRequestd unsignedRequest(true);
  ::fcl::DistanceRequestd signedRequest(true);
  signedRequest.enable_signed_distance = true;
  ::fcl::DistanceResultd withDepth;
  EXPECT_NEAR(gq::fcl::distance(&a, at(0, 0, 0), &b, at(1.7, 0.2, 0), signedRequest, withDepth), -0.3, 1e-12);
  ::fcl::DistanceResultd apart;
  EXPECT_NEAR(gq::fcl::distance(&a, at(0, 0, 0), &b, at(2.5, 0.2, 0), unsignedRequest, apart), 0.5, 1e-12);
}

// Closed-form pairs other than two boxes give their exact signed distance without the request: it costs them
// nothing more.
TEST(FclConventions, WithoutSignedDistanceClosedFormPairsStillGiveTheDepth) {
  ::fcl::Sphered a(1), b(1);
  ::fcl::DistanceResultd result;
  EXPECT_NEAR(gq::fcl::distance(&a, at(0, 0, 0), &b, at(1.5, 0, 0), ::fcl::DistanceRequestd(true), result), -0.5, 1e-12);
}

TEST(FclConventions, MeshContactsCarryTriangleIdsOnTheMeshSide) {
  auto mesh = twoTriangles();
  ::fcl::Sphered sphere(0.5);
  ::fcl::CollisionRequestd request(4, true);
  gq::fcl::Options exact;
  exact.minimumTranslation = true;
  ::fcl::CollisionResultd meshFirst, meshSecond;
  gq::fcl::collide<double>(mesh.get(), at(0, 0, 0), &sphere, at(10, 0, 0.3), request, meshFirst, exact);
  gq::fcl::collide<double>(&sphere, at(10, 0, 0.3), mesh.get(), at(0, 0, 0), request, meshSecond, exact);
  ASSERT_EQ(meshFirst.numContacts(), 1u);
  ASSERT_EQ(meshSecond.numContacts(), 1u);
  EXPECT_EQ(meshFirst.getContact(0).b1, 1);
  EXPECT_EQ(meshFirst.getContact(0).b2, kNone);
  EXPECT_EQ(meshSecond.getContact(0).b2, 1);
  EXPECT_NEAR(meshFirst.getContact(0).penetration_depth, 0.2, 1e-9);  // r - height
  EXPECT_NEAR((meshFirst.getContact(0).normal - Vector3d::UnitZ()).norm(), 0, 1e-9);   // mesh -> sphere
  EXPECT_NEAR((meshSecond.getContact(0).normal + Vector3d::UnitZ()).norm(), 0, 1e-9);  // sphere -> mesh
}

TEST(FclConventions, NumMaxContactsCapsMeshContacts) {
  // A fan of 6 triangles around the origin; a sphere at the centre touches all of them.
  auto fan = std::make_shared<::fcl::BVHModel<::fcl::OBBRSSd>>();
  fan->beginModel();
  for (int k = 0; k < 6; ++k) {
    const double a0 = k * M_PI / 3, a1 = (k + 1) * M_PI / 3;
    fan->addTriangle(Vector3d(0, 0, 0), Vector3d(std::cos(a0), std::sin(a0), 0), Vector3d(std::cos(a1), std::sin(a1), 0));
  }
  fan->endModel();
  ::fcl::Sphered sphere(0.2);
  ::fcl::CollisionResultd all, two;
  gq::fcl::collide<double>(fan.get(), at(0, 0, 0), &sphere, at(0, 0, 0.1), ::fcl::CollisionRequestd(100, false), all);
  gq::fcl::collide<double>(fan.get(), at(0, 0, 0), &sphere, at(0, 0, 0.1), ::fcl::CollisionRequestd(2, false), two);
  EXPECT_EQ(all.numContacts(), 6u);
  EXPECT_EQ(two.numContacts(), 2u);
  // The cap counts contacts already in the result (appended, not cleared): one there, cap 5 -> four more. The
  // adapter fetches only as many candidate triangles as there is room for; each must still be a distinct one.
  for (const std::size_t cap : {1u, 5u}) {
    ::fcl::CollisionResultd result;
    result.addContact(::fcl::Contactd(&sphere, &sphere, kNone, kNone));
    gq::fcl::collide<double>(fan.get(), at(0, 0, 0), &sphere, at(0, 0, 0.1), ::fcl::CollisionRequestd(cap, false), result);
    ASSERT_EQ(result.numContacts(), cap) << "cap " << cap;
    std::set<int> ids;
    for (std::size_t i = 1; i < cap; ++i) ids.insert(result.getContact(i).b1);
    EXPECT_EQ(ids.size(), cap - 1) << "cap " << cap;
  }
}

// Two BVHModels with the corrections: core's mesh contacts, one per crossing triangle pair, each pushing the shallower
// triangle out through the other's face. A vertical triangle dips 0.1 below a flat plate of two triangles: pushed
// up through the plate's face by 0.1 (through its own face the plate would move 2), at its lowest vertex moved half
// the depth up; both plate triangles cross it.
TEST(FclCorrections, MeshMeshContactsPushTheShallowerTriangleOutThroughTheOthersFace) {
  auto plate = std::make_shared<::fcl::BVHModel<::fcl::OBBRSSd>>();
  plate->beginModel();
  plate->addTriangle(Vector3d(-2, -2, 0), Vector3d(2, -2, 0), Vector3d(2, 2, 0));
  plate->addTriangle(Vector3d(-2, -2, 0), Vector3d(2, 2, 0), Vector3d(-2, 2, 0));
  plate->endModel();
  auto fin = std::make_shared<::fcl::BVHModel<::fcl::OBBRSSd>>();
  fin->beginModel();
  fin->addTriangle(Vector3d(0, -0.5, -0.1), Vector3d(0, 0.5, -0.1), Vector3d(0, 0, 1));
  fin->endModel();
  gq::fcl::Options options;
  options.minimumTranslation = true;
  ::fcl::CollisionResultd result;
  gq::fcl::collide<double>(plate.get(), at(0, 0, 0), fin.get(), at(0, 0, 0), ::fcl::CollisionRequestd(10, true), result,
                           options);
  ASSERT_EQ(result.numContacts(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const ::fcl::Contactd& c = result.getContact(i);
    EXPECT_EQ(c.b1, int(i));  // sorted by triangle ids
    EXPECT_EQ(c.b2, 0);
    EXPECT_NEAR(c.penetration_depth, 0.1, 1e-12);
    EXPECT_NEAR((c.normal - Vector3d::UnitZ()).norm(), 0, 1e-12);  // from the plate (o1) to the fin (o2)
    EXPECT_NEAR((c.pos - Vector3d(0, -0.5, -0.05)).norm(), 0, 1e-12);
  }
}

// FCL bug fcl#545: a small cube centred on the big cube's diagonal near its corner. The exact MTD pushes the small
// cube out through one face: its far face at 0.2 must pass the big cube's face at 0.5, 0.3 along an axis; FCL's MPR
// path returns the diagonal direction, sqrt(3) x deeper (0.52).
TEST(FclCorrections, MinimumTranslationGivesTheTrueDepthOfFclIssue545) {
  ::fcl::Boxd big(1, 1, 1);
  auto vertices = std::make_shared<std::vector<Vector3d>>();
  for (int i = 0; i < 8; ++i) vertices->emplace_back(i & 1 ? 0.2 : -0.2, i & 2 ? 0.2 : -0.2, i & 4 ? 0.2 : -0.2);
  auto faces = std::make_shared<std::vector<int>>(std::vector<int>{4, 0, 2, 3, 1, 4, 4, 5, 7, 6, 4, 0, 1, 5, 4,
                                                                   4, 2, 6, 7, 3, 4, 0, 4, 6, 2, 4, 1, 3, 7, 5});
  ::fcl::Convexd small(vertices, 6, faces);
  const ::fcl::Transform3d pose = at(0.4, 0.4, 0.4);
  ::fcl::CollisionRequestd request(1, true);
  ::fcl::CollisionResultd fromFcl, byDefault, corrected;
  ::fcl::collide<double>(&big, at(0, 0, 0), &small, pose, request, fromFcl);
  gq::fcl::collide<double>(&big, at(0, 0, 0), &small, pose, request, byDefault);
  gq::fcl::Options options;
  options.minimumTranslation = true;
  gq::fcl::collide<double>(&big, at(0, 0, 0), &small, pose, request, corrected, options);
  ASSERT_EQ(fromFcl.numContacts(), 1u);
  ASSERT_EQ(byDefault.numContacts(), 1u);
  ASSERT_EQ(corrected.numContacts(), 1u);
  std::cout << "FCL bug fcl#545 case: FCL depth " << fromFcl.getContact(0).penetration_depth << ", exact 0.3\n";
  // Default: FCL's own numbers.
  EXPECT_EQ(byDefault.getContact(0).penetration_depth, fromFcl.getContact(0).penetration_depth);
  EXPECT_NEAR(corrected.getContact(0).penetration_depth, 0.3, 1e-12);
  const Vector3d n = corrected.getContact(0).normal;
  EXPECT_NEAR(n.cwiseAbs().maxCoeff(), 1.0, 1e-12);  // a face normal of the big cube
  EXPECT_NEAR(n.sum(), 1.0, 1e-12);                  // pointing from the big cube out towards the small one
}

// FCL bug fcl#628: box B = [0,1] x [0.8,1] x [0,1] inside box A = [0,1]^3 with touching faces. The exact MTD moves B by
// 0.2 along +y whatever the boxes' length along z; FCL reports 1.0, or 0 once both are stretched along z.
TEST(FclCorrections, ExactContainedBoxDepthOfFclIssue628) {
  gq::fcl::Options options;
  options.exactContainedBoxDepth = true;
  for (double lengthZ : {1.0, 2.0}) {
    ::fcl::Boxd a(1, 1, lengthZ), b(1, 0.2, lengthZ);
    ::fcl::CollisionRequestd request(1, true);
    ::fcl::CollisionResultd fromFcl, corrected;
    ::fcl::collide<double>(&a, at(0.5, 0.5, lengthZ / 2), &b, at(0.5, 0.9, lengthZ / 2), request, fromFcl);
    gq::fcl::collide<double>(&a, at(0.5, 0.5, lengthZ / 2), &b, at(0.5, 0.9, lengthZ / 2), request, corrected, options);
    ASSERT_EQ(corrected.numContacts(), 1u);
    std::cout << "FCL bug fcl#628 case (length z " << lengthZ << "): FCL depth "
              << (fromFcl.numContacts() ? fromFcl.getContact(0).penetration_depth : -1.0) << ", exact 0.2\n";
    EXPECT_NEAR(corrected.getContact(0).penetration_depth, 0.2, 1e-12);
    EXPECT_NEAR((corrected.getContact(0).normal - Vector3d::UnitY()).norm(), 0, 1e-12);
  }
}

TEST(FclCache, AnEditedBvhModelIsReconverted) {
  auto mesh = twoTriangles();
  ::fcl::Sphered sphere(0.5);
  ::fcl::CollisionRequestd request;
  ::fcl::CollisionResultd before, after;
  EXPECT_EQ(gq::fcl::collide<double>(mesh.get(), at(0, 0, 0), &sphere, at(0, 0, 0.3), request, before), 1u);
  // Lift triangle 0 by 5 in place (replace mode keeps the arrays): the sampled vertices change the fingerprint.
  mesh->beginReplaceModel();
  mesh->replaceTriangle(Vector3d(-1, -1, 5), Vector3d(1, -1, 5), Vector3d(0, 1, 5));
  mesh->replaceTriangle(Vector3d(9, -1, 0), Vector3d(11, -1, 0), Vector3d(10, 1, 0));
  mesh->endReplaceModel();
  EXPECT_EQ(gq::fcl::collide<double>(mesh.get(), at(0, 0, 0), &sphere, at(0, 0, 0.3), request, after), 0u);
  EXPECT_EQ(gq::fcl::collide<double>(mesh.get(), at(0, 0, 0), &sphere, at(0, 0, 5.3), request, after), 1u);
}

// A Convex destroyed and another built at the same address (placement new into one buffer) with different
// vertices: the cache keeps the first one's vertex vector alive, so the second has a different vector and is
// re-cooked without forgetGeometry (docs/fcl.md, re-conversion rule).
TEST(FclCache, ANewConvexAtAReusedAddressIsReconverted) {
  const auto cube = [](double h) {
    auto v = std::make_shared<std::vector<Vector3d>>();
    for (int i = 0; i < 8; ++i) v->emplace_back(i & 1 ? h : -h, i & 2 ? h : -h, i & 4 ? h : -h);
    auto f = std::make_shared<std::vector<int>>(std::vector<int>{
        4, 0, 2, 3, 1, 4, 4, 5, 7, 6, 4, 0, 1, 5, 4, 4, 2, 6, 7, 3, 4, 0, 4, 6, 2, 4, 1, 3, 7, 5});
    return std::make_pair(v, f);
  };
  alignas(::fcl::Convexd) unsigned char storage[sizeof(::fcl::Convexd)];
  ::fcl::Sphered sphere(0.5);
  const auto distanceTo = [&](const ::fcl::Convexd* convex) {
    ::fcl::DistanceResultd result;
    return gq::fcl::distance<double>(convex, at(0, 0, 0), &sphere, at(3, 0, 0), ::fcl::DistanceRequestd(true), result);
  };
  auto [v1, f1] = cube(0.5);
  auto* first = new (storage) ::fcl::Convexd(v1, 6, f1);
  EXPECT_NEAR(distanceTo(first), 2.0, 1e-9);  // 3 - 0.5 - 0.5
  first->~Convex();
  v1.reset();
  auto [v2, f2] = cube(1.0);
  auto* second = new (storage) ::fcl::Convexd(v2, 6, f2);
  ASSERT_EQ(static_cast<void*>(first), static_cast<void*>(second));
  EXPECT_NEAR(distanceTo(second), 1.5, 1e-9);  // 3 - 1 - 0.5
  second->~Convex();
}

TEST(FclFallback, PlanePairsRunThroughFclAndMeshPlaneIsAnsweredByGq) {
  ::fcl::Halfspaced h1(Vector3d::UnitZ(), 0), h2(-Vector3d::UnitZ(), -1);
  ::fcl::Planed plane(Vector3d::UnitX(), 0);  // crosses triangle 0
  auto mesh = twoTriangles();
  ::fcl::CollisionRequestd request;
  gq::fcl::resetAdapterCounters();
  ::fcl::CollisionResultd r1, r2, f1, f2;
  gq::fcl::collide<double>(&h1, at(0, 0, 0), &h2, at(0, 0, 0), request, r1);
  ::fcl::collide<double>(&h1, at(0, 0, 0), &h2, at(0, 0, 0), request, f1);
  gq::fcl::collide<double>(mesh.get(), at(0, 0, 0), &plane, at(0, 0, 0), request, r2);
  ::fcl::collide<double>(mesh.get(), at(0, 0, 0), &plane, at(0, 0, 0), request, f2);
  EXPECT_EQ(gq::fcl::adapterCounters().fallback, 1u);  // the half-space pair; the mesh-plane pair is gq's
  EXPECT_EQ(gq::fcl::adapterCounters().gq, 1u);
  EXPECT_EQ(r1.isCollision(), f1.isCollision());
  EXPECT_EQ(r2.isCollision(), f2.isCollision());
}

// FCL's collide preamble, before any shape is read: num_max_contacts 0 returns 0 and computes nothing, and a result
// already satisfied (a collision, num_max_contacts reached, no cost sources) returns its count unchanged. Pairs of
// each of collide's paths: two common solids (their table entry), a cone (classified by node type) and a mesh.
TEST(FclConventions, ZeroMaxContactsAndASatisfiedResultComputeNothing) {
  ::fcl::Sphered s(1);
  ::fcl::Coned cone(1, 2);
  auto mesh = twoTriangles();
  const std::vector<std::pair<const ::fcl::CollisionGeometryd*, const ::fcl::CollisionGeometryd*>> pairs = {
      {&s, &s}, {&cone, &s}, {mesh.get(), &s}};
  for (const auto& [g1, g2] : pairs) {
    gq::fcl::resetAdapterCounters();
    ::fcl::CollisionRequestd none;
    none.num_max_contacts = 0;
    ::fcl::CollisionResultd empty;
    EXPECT_EQ(gq::fcl::collide<double>(g1, at(0, 0, 0), g2, at(0.5, 0, 0), none, empty), 0u);
    EXPECT_EQ(empty.numContacts(), 0u);
    ::fcl::CollisionRequestd one;  // num_max_contacts 1
    ::fcl::CollisionResultd full, fclFull;
    full.addContact(::fcl::Contactd(g1, g2, kNone, kNone));
    fclFull.addContact(::fcl::Contactd(g1, g2, kNone, kNone));
    EXPECT_EQ(gq::fcl::collide<double>(g1, at(0, 0, 0), g2, at(0.5, 0, 0), one, full), 1u);
    EXPECT_EQ(::fcl::collide<double>(g1, at(0, 0, 0), g2, at(0.5, 0, 0), one, fclFull), 1u);
    EXPECT_EQ(full.numContacts(), 1u);
    // Satisfied before anything is read: a NaN pose is not looked at either (FCL's order).
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(gq::fcl::collide<double>(g1, at(nan, 0, 0), g2, at(0.5, 0, 0), one, full), 1u);
    EXPECT_EQ(full.numContacts(), 1u);
    EXPECT_EQ(gq::fcl::adapterCounters().gq + gq::fcl::adapterCounters().fallback, 0u);
  }
}

// Cost sources (enable_cost) are FCL's: the pair runs through ::fcl::collide and the result is FCL's, contacts and
// cost sources alike.
TEST(FclFallback, CostSourcesRunThroughFcl) {
  ::fcl::Boxd a(1, 1, 1), b(1, 1, 1);
  ::fcl::CollisionRequestd request(1, false, 5, true);  // one contact, no geometry, 5 cost sources
  gq::fcl::resetAdapterCounters();
  ::fcl::CollisionResultd r, f;
  const std::size_t count = gq::fcl::collide<double>(&a, at(0, 0, 0), &b, at(0.5, 0.2, 0), request, r);
  EXPECT_EQ(count, ::fcl::collide<double>(&a, at(0, 0, 0), &b, at(0.5, 0.2, 0), request, f));
  EXPECT_EQ(gq::fcl::adapterCounters().fallback, 1u);
  EXPECT_EQ(gq::fcl::adapterCounters().gq, 0u);
  EXPECT_EQ(r.numContacts(), f.numContacts());
  ASSERT_GT(f.numCostSources(), 0u);
  ASSERT_EQ(r.numCostSources(), f.numCostSources());
  std::vector<::fcl::CostSourced> rc, fc;
  r.getCostSources(rc);
  f.getCostSources(fc);
  for (std::size_t i = 0; i < rc.size(); ++i) {
    EXPECT_EQ(rc[i].aabb_min, fc[i].aabb_min);
    EXPECT_EQ(rc[i].aabb_max, fc[i].aabb_max);
    EXPECT_EQ(rc[i].total_cost, fc[i].total_cost);
  }
}

TEST(FclConventions, PrimitivePairsAreAnsweredByGq) {
  ::fcl::Sphered s(1);
  ::fcl::Boxd b(1, 1, 1);
  ::fcl::Ellipsoidd e(1, 0.5, 0.3);
  gq::fcl::resetAdapterCounters();
  ::fcl::CollisionResultd r;
  ::fcl::DistanceResultd d;
  gq::fcl::collide<double>(&s, at(0, 0, 0), &b, at(1, 0, 0), ::fcl::CollisionRequestd(), r);
  gq::fcl::distance<double>(&e, at(0, 0, 0), &b, at(3, 0, 0), ::fcl::DistanceRequestd(), d);
  EXPECT_EQ(gq::fcl::adapterCounters().gq, 2u);
  EXPECT_EQ(gq::fcl::adapterCounters().fallback, 0u);
  EXPECT_NEAR(d.min_distance, 1.5, 1e-9);  // ellipsoid tip at x = 1, box face at x = 2.5
}

// A host's own subclass of an FCL shape has another type_info than the class: the type_info fast path does not know
// it, and the node type classifies it (a sphere stays a sphere, answered by gq exactly as the class itself).
struct HostSphere : ::fcl::Sphered {
  using ::fcl::Sphered::Sphered;
};
struct HostBox : ::fcl::Boxd {
  using ::fcl::Boxd::Boxd;
};

TEST(FclConventions, SubclassesOfFclShapesAreAnsweredAsTheirNodeType) {
  HostSphere hostSphere(0.5);
  HostBox hostBox(2, 2, 2);
  ::fcl::Sphered sphere(0.5);
  ::fcl::Boxd box(2, 2, 2);
  gq::fcl::resetAdapterCounters();
  ::fcl::DistanceResultd hostDistance, classDistance;
  gq::fcl::distance<double>(&hostSphere, at(3, 0.2, 0), &hostBox, at(0, 0, 0), ::fcl::DistanceRequestd(true),
                            hostDistance);
  gq::fcl::distance<double>(&sphere, at(3, 0.2, 0), &box, at(0, 0, 0), ::fcl::DistanceRequestd(true), classDistance);
  ::fcl::CollisionResultd hostContact;
  gq::fcl::collide<double>(&hostSphere, at(1.2, 0, 0), &hostBox, at(0, 0, 0), ::fcl::CollisionRequestd(1, true),
                           hostContact);
  EXPECT_EQ(gq::fcl::adapterCounters().gq, 3u);
  EXPECT_EQ(gq::fcl::adapterCounters().fallback, 0u);
  EXPECT_NEAR(hostDistance.min_distance, 1.5, 1e-12);  // centre 3 - half extent 1 - radius 0.5
  EXPECT_EQ(hostDistance.min_distance, classDistance.min_distance);
  EXPECT_EQ(hostDistance.nearest_points[0], classDistance.nearest_points[0]);
  EXPECT_EQ(hostDistance.nearest_points[1], classDistance.nearest_points[1]);
  ASSERT_EQ(hostContact.numContacts(), 1u);
  EXPECT_NEAR(hostContact.getContact(0).penetration_depth, 0.3, 1e-12);  // 1 + 0.5 - 1.2
}

TEST(FclConventions, NonFinitePoseWritesNothingAndDoesNotThrow) {
  ::fcl::Sphered a(1), b(1);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  ::fcl::CollisionResultd result;
  ::fcl::DistanceResultd distance;
  EXPECT_EQ(gq::fcl::collide<double>(&a, at(nan, 0, 0), &b, at(0, 0, 0), ::fcl::CollisionRequestd(1, true), result), 0u);
  EXPECT_EQ(result.numContacts(), 0u);
  gq::fcl::distance<double>(&a, at(nan, 0, 0), &b, at(0, 0, 0), ::fcl::DistanceRequestd(true), distance);
  EXPECT_EQ(distance.min_distance, std::numeric_limits<double>::max());
}

TEST(FclConventions, FloatOverloadsAnswerInFloat) {
  ::fcl::Spheref a(1), b(0.5f);
  ::fcl::Transform3f ta = ::fcl::Transform3f::Identity(), tb = ::fcl::Transform3f::Identity();
  tb.translation() = ::fcl::Vector3f(2, 0, 0);
  ::fcl::DistanceResultf d;
  EXPECT_NEAR(gq::fcl::distance<float>(&a, ta, &b, tb, ::fcl::DistanceRequestf(true), d), 0.5f, 1e-6f);
  ::fcl::CollisionResultf c;
  tb.translation() = ::fcl::Vector3f(1.4f, 0, 0);
  ::fcl::CollisionObjectf oa(std::make_shared<::fcl::Spheref>(1), ta), ob(std::make_shared<::fcl::Spheref>(0.5f), tb);
  EXPECT_EQ(gq::fcl::collide<float>(&oa, &ob, ::fcl::CollisionRequestf(1, true), c), 1u);
  EXPECT_NEAR(c.getContact(0).penetration_depth, 0.1f, 1e-6f);
}

}  // namespace

namespace {

// Threads querying shared Convex and BVHModel geometry while another thread forgets and clears the cache: every
// answer equals the single-threaded one (the per-thread tables hold their entries alive; a forget only makes them
// look the geometry up again).
TEST(FclCache, ConcurrentQueriesAndForgetsGiveTheSingleThreadedAnswers) {
  auto vertices = std::make_shared<std::vector<Vector3d>>();
  for (int i = 0; i < 8; ++i) vertices->emplace_back(i & 1 ? 0.5 : -0.5, i & 2 ? 0.5 : -0.5, i & 4 ? 0.5 : -0.5);
  auto faces = std::make_shared<std::vector<int>>(std::vector<int>{
      4, 0, 2, 3, 1, 4, 4, 5, 7, 6, 4, 0, 1, 5, 4, 4, 2, 6, 7, 3, 4, 0, 4, 6, 2, 4, 1, 3, 7, 5});
  const ::fcl::Convexd convex(vertices, 6, faces);
  const auto mesh = twoTriangles();
  ::fcl::Sphered sphere(0.5);
  const auto query = [&](int k) {
    ::fcl::DistanceResultd a, b;
    const double x = 2.0 + 0.01 * (k % 50);
    gq::fcl::distance<double>(&convex, at(0, 0, 0), &sphere, at(x, 0, 0), ::fcl::DistanceRequestd(true), a);
    gq::fcl::distance<double>(mesh.get(), at(0, 0, 0), &sphere, at(0, 0, x), ::fcl::DistanceRequestd(true), b);
    return std::make_pair(a.min_distance, b.min_distance);
  };
  std::vector<std::pair<double, double>> expected;
  for (int k = 0; k < 50; ++k) expected.push_back(query(k));
  EXPECT_NEAR(expected[0].first, 1.0, 1e-9);   // 2 - 0.5 - 0.5
  EXPECT_NEAR(expected[0].second, 1.5, 1e-9);  // 2 - 0.5
  std::atomic<bool> stop{false};
  std::atomic<int> wrong{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < 3; ++t)
    threads.emplace_back([&, t] {
      for (int k = 0; k < 3000; ++k)
        if (query(k + t) != expected[std::size_t((k + t) % 50)]) ++wrong;
    });
  std::thread forgetter([&] {
    for (int k = 0; !stop; ++k) {
      if (k % 2) gq::fcl::forgetGeometry<double>(&convex);
      else gq::fcl::clearGeometryCache();
      std::this_thread::yield();
    }
  });
  for (auto& t : threads) t.join();
  stop = true;
  forgetter.join();
  EXPECT_EQ(wrong.load(), 0);
}

}  // namespace
