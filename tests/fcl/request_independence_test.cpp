// FCL 0.7's observable behaviour that does not depend on the request's flags: DistanceResult::nearest_points is
// written for every shape pair whatever enable_nearest_points says; the collide boolean is the same with and without
// enable_contact; a BVHModel reaching a solid answers FCL's -1 without enable_signed_distance whichever path answers.
#include <gtest/gtest.h>

#include <memory>
#include <random>

#include "fcl_scenes.h"
#include "gq/fcl/fcl.h"

namespace {

using gq::fcltest::Kind;
using ::fcl::Vector3d;

::fcl::Transform3d at(double x, double y, double z) {
  ::fcl::Transform3d tf = ::fcl::Transform3d::Identity();
  tf.translation() = Vector3d(x, y, z);
  return tf;
}

const Kind kSolids[] = {Kind::Sphere,    Kind::Box,    Kind::Capsule,   Kind::Cylinder,
                        Kind::Cone,      Kind::Ellipsoid, Kind::Convex, Kind::TriangleP};

TEST(FclRequestIndependence, NearestPointsAreWrittenWhateverEnableNearestPointsSays) {
  std::mt19937 rng(4201);
  int pairs = 0;
  for (Kind ka : kSolids) {
    for (Kind kb : kSolids) {
      const gq::fcltest::TestShape a = gq::fcltest::makeShape(ka, rng), b = gq::fcltest::makeShape(kb, rng);
      for (int i = 0; i < 40; ++i) {
        const ::fcl::Transform3d pa = gq::fcltest::randomPose(rng, 1.5), pb = gq::fcltest::randomPose(rng, 1.5);
        for (bool signedDistance : {false, true}) {
          SCOPED_TRACE(testing::Message() << gq::fcltest::name(ka) << "-" << gq::fcltest::name(kb) << " pose " << i
                                          << " signed " << signedDistance);
          ::fcl::DistanceRequestd without(false), with(true);
          without.enable_signed_distance = with.enable_signed_distance = signedDistance;
          ::fcl::DistanceResultd r0, r1;
          const Vector3d stale(7, 7, 7);
          r0.nearest_points[0] = r0.nearest_points[1] = stale;
          gq::fcl::distance(a.geometry.get(), pa, b.geometry.get(), pb, without, r0);
          gq::fcl::distance(a.geometry.get(), pa, b.geometry.get(), pb, with, r1);
          ASSERT_NE(r0.o1, nullptr);
          EXPECT_EQ(r0.min_distance, r1.min_distance);
          EXPECT_NE(r0.nearest_points[0], stale);
          EXPECT_NE(r0.nearest_points[1], stale);
          EXPECT_EQ(r0.nearest_points[0], r1.nearest_points[0]);
          EXPECT_EQ(r0.nearest_points[1], r1.nearest_points[1]);
          ++pairs;
        }
      }
    }
  }
  EXPECT_EQ(pairs, 8 * 8 * 40 * 2);
}

TEST(FclRequestIndependence, FclAlsoWritesNearestPointsWithoutTheFlag) {
  // The behaviour followed: FCL 0.7's shape traversal passes its solver's points to update() in every mode.
  ::fcl::Sphered a(0.5);
  ::fcl::Boxd b(1, 1, 1);
  ::fcl::DistanceRequestd without(false);
  ::fcl::DistanceResultd fcl, gq;
  fcl.nearest_points[0] = fcl.nearest_points[1] = gq.nearest_points[0] = gq.nearest_points[1] = Vector3d(7, 7, 7);
  ::fcl::distance(&a, at(0, 0, 0), &b, at(2, 0, 0), without, fcl);
  gq::fcl::distance(&a, at(0, 0, 0), &b, at(2, 0, 0), without, gq);
  for (int i : {0, 1}) {
    EXPECT_NEAR((fcl.nearest_points[i] - gq.nearest_points[i]).norm(), 0, 1e-6) << i;
  }
  EXPECT_NEAR((gq.nearest_points[0] - Vector3d(0.5, 0, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR((gq.nearest_points[1] - Vector3d(1.5, 0, 0)).norm(), 0, 1e-12);
}

// Separated pairs: gq's nearest points are FCL's (FCL's closed forms exactly; its GJK within how far libccd's GJK
// stops from the exact pair), both written without enable_nearest_points.
TEST(FclRequestIndependence, NearestPointsOfSeparatedPairsAreFcls) {
  std::mt19937 rng(4205);
  const Kind kinds[] = {Kind::Sphere, Kind::Box, Kind::Capsule, Kind::Cylinder, Kind::Convex};
  int compared = 0;
  for (Kind ka : kinds) {
    for (Kind kb : kinds) {
      const gq::fcltest::TestShape a = gq::fcltest::makeShape(ka, rng), b = gq::fcltest::makeShape(kb, rng);
      // FCL's closed forms: sphere against sphere, box, capsule and cylinder; capsule-capsule. The rest is libccd's
      // GJK, which stops short of the exact pair (points up to a few 1e-2 off on curved shapes; its distance is an
      // upper bound of gq's exact one).
      const bool sphere = ka == Kind::Sphere || kb == Kind::Sphere, convex = ka == Kind::Convex || kb == Kind::Convex;
      const bool closedForm = (sphere && !convex) || (ka == Kind::Capsule && kb == Kind::Capsule);
      const double tolerance = closedForm ? 1e-6 : 5e-2;
      for (int i = 0; i < 40; ++i) {
        const ::fcl::Transform3d pa = gq::fcltest::randomPose(rng, 3), pb = gq::fcltest::randomPose(rng, 3);
        const ::fcl::DistanceRequestd request(false);
        ::fcl::DistanceResultd gq, fcl;
        gq::fcl::distance(a.geometry.get(), pa, b.geometry.get(), pb, request, gq);
        ::fcl::distance(a.geometry.get(), pa, b.geometry.get(), pb, request, fcl);
        if (!(gq.min_distance > 0.05) || !(fcl.min_distance > 0.05)) continue;
        SCOPED_TRACE(testing::Message() << gq::fcltest::name(ka) << "-" << gq::fcltest::name(kb) << " pose " << i);
        EXPECT_NEAR(gq.min_distance, fcl.min_distance, tolerance);
        EXPECT_LE(gq.min_distance, fcl.min_distance + request.distance_tolerance);  // gq stops within it
        EXPECT_NEAR((gq.nearest_points[0] - fcl.nearest_points[0]).norm(), 0, tolerance);
        EXPECT_NEAR((gq.nearest_points[1] - fcl.nearest_points[1]).norm(), 0, tolerance);
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 300);
}

TEST(FclRequestIndependence, TouchingEllipsoidsCollideWithAndWithoutContacts) {
  // Exact distance 0: two ellipsoids touching at (1, 0, 0). libccd's MPR reports no contact there; gq's boolean
  // decides in both modes and the contact is gq's exact one (depth 0, normal +x).
  ::fcl::Ellipsoidd a(1, 0.5, 0.5), b(1, 0.5, 0.5);
  for (bool contact : {false, true}) {
    ::fcl::CollisionRequestd request(1, contact);
    ::fcl::CollisionResultd result;
    EXPECT_EQ(gq::fcl::collide(&a, at(0, 0, 0), &b, at(2, 0, 0), request, result), 1u) << contact;
    if (contact && result.numContacts() == 1) {
      const ::fcl::Contactd& c = result.getContact(0);
      EXPECT_NEAR(c.penetration_depth, 0, 1e-6);
      EXPECT_NEAR((c.normal - Vector3d(1, 0, 0)).norm(), 0, 1e-4);
      EXPECT_NEAR((c.pos - Vector3d(1, 0, 0)).norm(), 0, 1e-4);
    }
  }
}

TEST(FclRequestIndependence, TheBooleanDoesNotDependOnEnableContact) {
  std::mt19937 rng(4202);
  for (Kind ka : kSolids) {
    for (Kind kb : kSolids) {
      const gq::fcltest::TestShape a = gq::fcltest::makeShape(ka, rng), b = gq::fcltest::makeShape(kb, rng);
      for (int i = 0; i < 60; ++i) {
        const ::fcl::Transform3d pa = gq::fcltest::randomPose(rng, 1.5), pb = gq::fcltest::randomPose(rng, 1.5);
        ::fcl::CollisionResultd withoutContact, withContact;
        gq::fcl::collide(a.geometry.get(), pa, b.geometry.get(), pb, ::fcl::CollisionRequestd(1, false),
                         withoutContact);
        gq::fcl::collide(a.geometry.get(), pa, b.geometry.get(), pb, ::fcl::CollisionRequestd(1, true), withContact);
        EXPECT_EQ(withoutContact.isCollision(), withContact.isCollision())
            << gq::fcltest::name(ka) << "-" << gq::fcltest::name(kb) << " pose " << i;
      }
    }
  }
}

std::shared_ptr<::fcl::BVHModel<::fcl::OBBRSSd>> square() {
  auto model = std::make_shared<::fcl::BVHModel<::fcl::OBBRSSd>>();
  model->beginModel();
  model->addTriangle(Vector3d(-1, -1, 0), Vector3d(1, -1, 0), Vector3d(1, 1, 0));
  model->addTriangle(Vector3d(-1, -1, 0), Vector3d(1, 1, 0), Vector3d(-1, 1, 0));
  model->endModel();
  return model;
}

TEST(FclRequestIndependence, APenetratingMeshAnswersFclsMinusOneWithoutSignedDistance) {
  const auto mesh = square();
  ::fcl::Boxd box(0.5, 0.5, 0.5);
  ::fcl::Sphered sphere(0.3);
  const ::fcl::DistanceRequestd request(true);
  for (const ::fcl::CollisionGeometryd* shape : {static_cast<const ::fcl::CollisionGeometryd*>(&box),
                                                 static_cast<const ::fcl::CollisionGeometryd*>(&sphere)}) {
    ::fcl::DistanceResultd meshFirst, shapeFirst;
    EXPECT_EQ(gq::fcl::distance(mesh.get(), at(0, 0, 0), shape, at(0.1, 0, 0.05), request, meshFirst), -1.0);
    EXPECT_EQ(gq::fcl::distance(shape, at(0.1, 0, 0.05), mesh.get(), at(0, 0, 0), request, shapeFirst), -1.0);
    EXPECT_EQ(meshFirst.nearest_points[0], Vector3d::Zero());
    EXPECT_EQ(meshFirst.nearest_points[1], Vector3d::Zero());
  }
  // FCL's own answer for the box (GJK per triangle): the same -1.
  ::fcl::DistanceResultd fcl;
  EXPECT_EQ(::fcl::distance(mesh.get(), at(0, 0, 0), &box, at(0.1, 0, 0.05), request, fcl), -1.0);
  // With enable_signed_distance the depth is reported (negative, not FCL's -1 marker).
  ::fcl::DistanceRequestd signedRequest(true);
  signedRequest.enable_signed_distance = true;
  ::fcl::DistanceResultd deep;
  const double d = gq::fcl::distance(mesh.get(), at(0, 0, 0), &box, at(0.1, 0, 0.05), signedRequest, deep);
  EXPECT_NEAR(d, -0.2, 1e-9);  // the box leaves the square by moving up 0.2
  // Separated: the distance, as before.
  ::fcl::DistanceResultd apart;
  EXPECT_NEAR(gq::fcl::distance(mesh.get(), at(0, 0, 0), &box, at(0, 0, 1.25), request, apart), 1.0, 1e-9);
}

}  // namespace
