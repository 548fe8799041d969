// gq::fcl on invalid input, one test per row of the bad-input table (docs/fcl.md). FCL 0.7 validates almost nothing:
// it returns NaN contacts, aborts on libccd/Eigen assertions (NaN poses) or crashes (null objects, empty or
// unfinished BVHModels). gq::fcl follows FCL's own convention for a pair it cannot answer (an unsupported pair):
// collide adds no contact and returns 0, distance writes nothing and returns std::numeric_limits<S>::max(). Results
// already holding answers stay bit for bit as they were; nothing throws and no NaN is written.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include <random>
#include <utility>
#include <vector>

#include "fcl_scenes.h"
#include "gq/fcl/fcl.h"

namespace {

using ::fcl::Vector3d;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNothing = std::numeric_limits<double>::max();  // FCL's distance for a pair it does not answer

::fcl::Transform3d at(double x, double y, double z) {
  ::fcl::Transform3d tf = ::fcl::Transform3d::Identity();
  tf.translation() = Vector3d(x, y, z);
  return tf;
}

using Geom = std::shared_ptr<::fcl::CollisionGeometryd>;
Geom sphere(double r) { return std::make_shared<::fcl::Sphered>(r); }
Geom box(double x, double y, double z) { return std::make_shared<::fcl::Boxd>(x, y, z); }

// A collision result holding one contact and a distance result pre-seeded as a host (MoveIt) does.
struct Seeded {
  ::fcl::CollisionResultd collision;
  ::fcl::DistanceResultd distance;
  ::fcl::Sphered other{1.0};
  Seeded() {
    collision.addContact(::fcl::Contactd(&other, &other, 3, 4, Vector3d(1, 2, 3), Vector3d(0, 0, 1), 0.25));
    distance.update(5.0, &other, &other, 7, 8, Vector3d(1, 1, 1), Vector3d(2, 2, 2));
  }
};

// Collide (boolean and with contacts) and distance (with nearest points and signed distance) on one input, checking
// FCL's "not answered" convention and that the seeded results are untouched.
void expectNothingWritten(const ::fcl::CollisionGeometryd* g1, const ::fcl::Transform3d& tf1,
                          const ::fcl::CollisionGeometryd* g2, const ::fcl::Transform3d& tf2) {
  for (const bool contact : {false, true}) {
    Seeded s;
    EXPECT_EQ(gq::fcl::collide(g1, tf1, g2, tf2, ::fcl::CollisionRequestd(4, contact), s.collision), 0u);
    ASSERT_EQ(s.collision.numContacts(), 1u);
    const ::fcl::Contactd& c = s.collision.getContact(0);
    EXPECT_EQ(c.b1, 3);
    EXPECT_EQ(c.b2, 4);
    EXPECT_EQ(c.penetration_depth, 0.25);
    EXPECT_EQ(c.pos, Vector3d(1, 2, 3));
  }
  for (const bool signedDistance : {true, false}) {  // with a depth (GJK/EPA pairs convert) and without (fast paths)
    Seeded s;
    ::fcl::DistanceRequestd request(true);
    request.enable_signed_distance = signedDistance;
    EXPECT_EQ(gq::fcl::distance(g1, tf1, g2, tf2, request, s.distance), kNothing);
    EXPECT_EQ(s.distance.min_distance, 5.0);
    EXPECT_EQ(s.distance.b1, 7);
    EXPECT_EQ(s.distance.b2, 8);
    EXPECT_EQ(s.distance.nearest_points[0], Vector3d(1, 1, 1));
    EXPECT_EQ(s.distance.nearest_points[1], Vector3d(2, 2, 2));
  }
}

// Both argument orders, so that either side being bad is covered.
void expectNothingWrittenEitherOrder(const Geom& bad, const ::fcl::Transform3d& badPose, const Geom& good,
                                     const ::fcl::Transform3d& goodPose) {
  expectNothingWritten(bad.get(), badPose, good.get(), goodPose);
  expectNothingWritten(good.get(), goodPose, bad.get(), badPose);
}

std::shared_ptr<::fcl::BVHModel<::fcl::OBBRSSd>> oneTriangleModel(bool finish) {
  auto model = std::make_shared<::fcl::BVHModel<::fcl::OBBRSSd>>();
  model->beginModel();
  model->addTriangle(Vector3d(-1, -1, 0), Vector3d(1, -1, 0), Vector3d(0, 1, 0));
  if (finish) model->endModel();
  return model;
}

TEST(FclBadInput, NaNTranslationWritesNothing) {
  // FCL: sphere-sphere adds a contact with NaN depth and normal; box-box, sphere-box, capsule-box abort (assertions
  // in libccd / Eigen); distance returns -1.
  expectNothingWrittenEitherOrder(sphere(0.5), at(kNaN, 0, 0), sphere(0.5), at(0.3, 0, 0));
  expectNothingWrittenEitherOrder(box(1, 1, 1), at(0, kNaN, 0), box(1, 1, 1), at(0.3, 0, 0));
  expectNothingWrittenEitherOrder(std::make_shared<::fcl::Capsuled>(0.3, 1), at(0, 0, kNaN), box(1, 1, 1), at(0, 0, 0));
}

TEST(FclBadInput, NaNRotationWritesNothing) {
  // FCL: sphere-box answers with a NaN normal and position; box-box aborts.
  ::fcl::Transform3d nanRotation = at(0.3, 0, 0);
  nanRotation.linear()(1, 2) = kNaN;
  expectNothingWrittenEitherOrder(box(1, 1, 1), nanRotation, box(1, 1, 1), at(0, 0, 0));
  expectNothingWrittenEitherOrder(sphere(0.5), nanRotation, box(1, 1, 1), at(0, 0, 0));  // even for a sphere
}

TEST(FclBadInput, InfiniteTranslationWritesNothing) {
  // FCL: sphere-box adds a contact with depth -inf and a NaN position.
  expectNothingWrittenEitherOrder(sphere(0.5), at(kInf, 0, 0), box(1, 1, 1), at(0, 0, 0));
  expectNothingWrittenEitherOrder(box(1, 1, 1), at(0, -kInf, 0), box(1, 1, 1), at(0, 0, 0));
}

TEST(FclBadInput, OppositeInfinitiesInTheTwoPosesWriteNothing) {
  // The finiteness test sums the two transforms' entries first: +inf and -inf at one entry sum to NaN, not to a
  // finite value.
  expectNothingWrittenEitherOrder(sphere(0.5), at(kInf, 0, 0), sphere(0.5), at(-kInf, 0, 0));
  expectNothingWrittenEitherOrder(sphere(0.5), at(0, kInf, 0), box(1, 1, 1), at(0, -kInf, 0));
}

TEST(FclBadInput, FinitePosesWhoseEntriesSumPastTheLargestDoubleAreAnswered) {
  // Valid input, though the plain sum of the entries overflows: the exact test decides, and the pair is answered.
  const Geom a = sphere(1), b = sphere(1);
  ::fcl::DistanceResultd d;
  const double answer = gq::fcl::distance(a.get(), at(1e308, 0, 0), b.get(), at(1.6e308, 0, 0),
                                          ::fcl::DistanceRequestd(true), d);
  EXPECT_NEAR(answer, 6e307, 6e307 * 1e-12);
  EXPECT_EQ(d.min_distance, answer);
  // The same for a sphere against a box and a cylinder, whose check sums the sphere's entries with the other's
  // translation.
  const Geom cylinder = std::make_shared<::fcl::Cylinderd>(0.4, 1);
  for (const Geom& other : {box(1, 1, 1), cylinder}) {
    SCOPED_TRACE(other->getNodeType() == ::fcl::GEOM_BOX ? "box" : "cylinder");
    ::fcl::DistanceResultd e;
    EXPECT_NEAR(gq::fcl::distance(a.get(), at(1e308, 0, 0), other.get(), at(1.6e308, 0, 0),
                                  ::fcl::DistanceRequestd(true), e), 6e307, 6e307 * 1e-12);
    EXPECT_NEAR(e.min_distance, 6e307, 6e307 * 1e-12);
  }
  ::fcl::CollisionResultd c;
  EXPECT_EQ(gq::fcl::collide(a.get(), at(1e308, 0, 0), b.get(), at(1e308, 0.5, 0), ::fcl::CollisionRequestd(), c), 1u);
}

TEST(FclBadInput, LinearPartThatIsNotARotationWritesNothing) {
  // A scaled or sheared "rotation" (FCL would silently scale the shape in some pairs and not in others).
  ::fcl::Transform3d scaled = at(0.3, 0, 0);
  scaled.linear() *= 2.0;
  expectNothingWrittenEitherOrder(box(1, 1, 1), scaled, box(1, 1, 1), at(0, 0, 0));
}

// Every pair of the common solids (the fast table: sphere, box, capsule, cylinder, convex; each kernel runs its
// own pose check, some after the kernel so that the check overlaps it) writes nothing when either pose has a NaN
// translation, a NaN or infinite rotation entry, or (but for a sphere, whose rotation moves nothing) a sheared or
// scaled linear part.
TEST(FclBadInput, EveryCommonSolidPairWritesNothingOnABadPose) {
  using gq::fcltest::Kind;
  std::mt19937 rng(5);
  const Kind kinds[] = {Kind::Sphere, Kind::Box, Kind::Capsule, Kind::Cylinder, Kind::Convex};
  for (const Kind badKind : kinds)
    for (const Kind goodKind : kinds) {
      const gq::fcltest::TestShape bad = gq::fcltest::makeShape(badKind, rng), good = gq::fcltest::makeShape(goodKind, rng);
      std::vector<std::pair<const char*, ::fcl::Transform3d>> poses;
      ::fcl::Transform3d p = at(0.2, 0.1, 0);
      p.translation().y() = kNaN;
      poses.push_back({"NaN translation", p});
      p = at(0.2, 0.1, 0);
      p.linear()(0, 1) = kNaN;
      poses.push_back({"NaN rotation entry", p});
      p = at(0.2, 0.1, 0);
      p.linear()(2, 2) = kInf;
      poses.push_back({"infinite rotation entry", p});
      if (badKind != Kind::Sphere) {
        p = at(0.2, 0.1, 0);
        p.linear()(1, 0) = 0.05;
        poses.push_back({"sheared", p});
        p = at(3, 0.1, 0);  // apart as read
        p.linear() *= 1.5;
        poses.push_back({"scaled, apart", p});
      }
      for (const auto& [what, pose] : poses) {
        SCOPED_TRACE(testing::Message() << gq::fcltest::name(badKind) << " (" << what << ") with "
                                        << gq::fcltest::name(goodKind));
        expectNothingWrittenEitherOrder(bad.geometry, pose, good.geometry, at(0, 0, 0));
      }
    }
}

TEST(FclBadInput, ShearedLinearPartWritesNothingWhicheverEntryIsSheared) {
  // One off-diagonal entry at a time: each makes one off-diagonal entry of R^T R non-zero (the orthonormality test
  // sums them lane by lane in double, solid_pairs.cpp). A deviation within the unit tolerance is accepted.
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col) {
      if (row == col) continue;
      SCOPED_TRACE(testing::Message() << "entry " << row << ", " << col);
      ::fcl::Transform3d sheared = at(0.3, 0, 0);
      sheared.linear()(row, col) = 0.05;
      {
        SCOPED_TRACE("box-box");
        expectNothingWrittenEitherOrder(box(1, 1, 1), sheared, box(1, 1, 1), at(0, 0, 0));
      }
      {
        SCOPED_TRACE("box-sphere");
        expectNothingWrittenEitherOrder(box(1, 1, 1), sheared, sphere(0.5), at(0, 0, 0));
      }
      ::fcl::Transform3d nearlyRotation = at(3, 0, 0);
      nearlyRotation.linear()(row, col) = 1e-6;
      ::fcl::DistanceResultd result;
      EXPECT_NEAR(gq::fcl::distance(box(1, 1, 1).get(), nearlyRotation, sphere(0.5).get(), at(0, 0, 0),
                                    ::fcl::DistanceRequestd(true), result),
                  2.0, 1e-5)
          << row << ", " << col;
    }
}

TEST(FclBadInput, ADefectInEitherOfTwoCheckedTransformsWritesNothing) {
  // Boxes, capsules, cylinders and hulls have both transforms checked in one pass, a lane each (bothRigid in
  // adapters/fcl/src/convert.h): each defect in either transform, of either shape of the pair, writes nothing. Hulls
  // also reject a reflection, which the symmetric shapes accept.
  std::mt19937 rng(5);
  std::vector<Vector3d> vertices;
  std::vector<std::vector<int>> faces;
  gq::fcltest::randomHull(rng, 30, vertices, faces);
  const Geom hull = gq::fcltest::convexGeometry(vertices, faces), cube = box(1, 1, 1);
  const Geom capsule = std::make_shared<::fcl::Capsuled>(0.3, 1), cylinder = std::make_shared<::fcl::Cylinderd>(0.4, 1);
  const std::vector<std::pair<Geom, Geom>> pairs = {
      {cube, cube}, {capsule, capsule}, {capsule, cube}, {cube, cylinder}, {hull, hull}};
  std::vector<std::pair<const char*, ::fcl::Transform3d>> defects;
  defects.emplace_back("NaN translation", at(0.3, kNaN, 0));
  defects.emplace_back("infinite translation", at(0.3, 0, -kInf));
  defects.emplace_back("NaN linear entry", at(0.3, 0, 0));
  defects.back().second.linear()(2, 0) = kNaN;
  defects.emplace_back("scaled", at(0.3, 0, 0));
  defects.back().second.linear() *= 1.01;
  defects.emplace_back("sheared", at(0.3, 0, 0));
  defects.back().second.linear()(0, 1) = 0.05;
  ::fcl::Transform3d reflected = at(0.3, 0, 0);
  reflected.linear() = Eigen::Vector3d(1, -1, 1).asDiagonal();
  for (const auto& [a, b] : pairs) {
    for (const auto& [name, bad] : defects) {
      SCOPED_TRACE(name);
      expectNothingWrittenEitherOrder(a, bad, b, at(0, 0, 0));
      expectNothingWrittenEitherOrder(b, bad, a, at(0, 0, 0));
    }
  }
  SCOPED_TRACE("reflected hull");
  expectNothingWrittenEitherOrder(hull, reflected, hull, at(0, 0, 0));
}

TEST(FclBadInput, BadInputThatOverlapsAsReadWritesNothingIntoAnEmptyResult) {
  // collide checks the closed-form pairs' input only before reporting a hit (a miss writes nothing either way, and
  // the seeded results above make every call check). Each pair overlaps as read: with the pose made valid it collides.
  ::fcl::Transform3d nanRotation = at(0.3, 0, 0);
  nanRotation.linear()(1, 2) = kNaN;
  ::fcl::Transform3d scaled = at(0.3, 0, 0);
  scaled.linear() *= 2.0;
  const Geom capsule = std::make_shared<::fcl::Capsuled>(0.3, 1);
  struct Case {
    Geom bad;
    ::fcl::Transform3d badPose;
    Geom good;
  };
  const Case cases[] = {{sphere(0.5), nanRotation, sphere(0.5)}, {sphere(0.5), nanRotation, capsule},
                        {sphere(0.5), nanRotation, box(1, 1, 1)}, {capsule, scaled, sphere(0.5)},
                        {capsule, scaled, capsule},               {capsule, scaled, box(1, 1, 1)},
                        {box(1, 1, 1), scaled, sphere(0.5)},      {box(1, 1, 1), scaled, box(1, 1, 1)}};
  for (const Case& c : cases) {
    for (const bool badFirst : {true, false}) {
      for (const bool contact : {false, true}) {
        const auto call = [&](const ::fcl::Transform3d& badPose, ::fcl::CollisionResultd& result) {
          const ::fcl::CollisionRequestd request(4, contact);
          return badFirst ? gq::fcl::collide(c.bad.get(), badPose, c.good.get(), at(0, 0, 0), request, result)
                          : gq::fcl::collide(c.good.get(), at(0, 0, 0), c.bad.get(), badPose, request, result);
        };
        ::fcl::CollisionResultd valid, bad;
        EXPECT_GE(call(at(0.3, 0, 0), valid), 1u);
        EXPECT_EQ(call(c.badPose, bad), 0u);
        EXPECT_EQ(bad.numContacts(), 0u);
      }
    }
  }
}

TEST(FclBadInput, ZeroSizeWritesNothing) {
  // FCL answers a zero-radius sphere as a point and a zero box as a point; gq has no point geometry (sizes must be
  // > 0), so the pair is not answered rather than answered with a made-up thickness.
  expectNothingWrittenEitherOrder(sphere(0.0), at(0, 0, 0), sphere(0.5), at(0.3, 0, 0));
  expectNothingWrittenEitherOrder(box(0, 0, 0), at(0, 0, 0), sphere(0.5), at(0.3, 0, 0));
  expectNothingWrittenEitherOrder(box(1, 0, 1), at(0, 0, 0), box(1, 1, 1), at(0.3, 0, 0));
  expectNothingWrittenEitherOrder(std::make_shared<::fcl::Cylinderd>(0.3, 0.0), at(0, 0, 0), box(1, 1, 1), at(0.3, 0, 0));
}

TEST(FclBadInput, NegativeSizeWritesNothing) {
  // FCL: no collision for a negative radius or side, and a positive distance measured as if the sign were absent.
  expectNothingWrittenEitherOrder(sphere(-0.5), at(0, 0, 0), sphere(0.5), at(0.3, 0, 0));
  expectNothingWrittenEitherOrder(box(-1, 1, 1), at(0, 0, 0), box(1, 1, 1), at(0.3, 0, 0));
  expectNothingWrittenEitherOrder(std::make_shared<::fcl::Capsuled>(-0.3, 1), at(0, 0, 0), box(1, 1, 1), at(0.3, 0, 0));
  expectNothingWrittenEitherOrder(std::make_shared<::fcl::Capsuled>(0.3, -1), at(0, 0, 0), box(1, 1, 1), at(0.3, 0, 0));
  expectNothingWrittenEitherOrder(std::make_shared<::fcl::Cylinderd>(-0.3, 1), at(0, 0, 0), box(1, 1, 1), at(0.3, 0, 0));
  expectNothingWrittenEitherOrder(std::make_shared<::fcl::Coned>(0.3, -1), at(0, 0, 0), box(1, 1, 1), at(0.3, 0, 0));
  expectNothingWrittenEitherOrder(std::make_shared<::fcl::Ellipsoidd>(0.3, -0.2, 0.4), at(0, 0, 0), box(1, 1, 1),
                                  at(0.3, 0, 0));
}

TEST(FclBadInput, InfiniteSizeWritesNothing) {
  // Sizes must be finite as well as positive (an infinite radius or side has no closest point).
  expectNothingWrittenEitherOrder(sphere(kInf), at(0, 0, 0), sphere(0.5), at(0.3, 0, 0));
  expectNothingWrittenEitherOrder(sphere(kInf), at(0, 0, 0), box(1, 1, 1), at(0.3, 0, 0));
  expectNothingWrittenEitherOrder(box(1, kInf, 1), at(0, 0, 0), sphere(0.5), at(0.3, 0, 0));
  expectNothingWrittenEitherOrder(std::make_shared<::fcl::Cylinderd>(0.3, kInf), at(0, 0, 0), sphere(0.5), at(0.3, 0, 0));
}

TEST(FclBadInput, NaNSizeWritesNothing) {
  // FCL: a NaN-radius sphere collides with NaN depth and position.
  expectNothingWrittenEitherOrder(sphere(kNaN), at(0, 0, 0), sphere(0.5), at(0.3, 0, 0));
  expectNothingWrittenEitherOrder(box(1, kNaN, 1), at(0, 0, 0), sphere(0.5), at(0.3, 0, 0));
  expectNothingWrittenEitherOrder(std::make_shared<::fcl::TrianglePd>(Vector3d(0, 0, 0), Vector3d(kNaN, 0, 0), Vector3d(0, 1, 0)),
                                  at(0, 0, 0), sphere(0.5), at(0.3, 0, 0));
}

TEST(FclBadInput, EmptyBvhModelWritesNothing) {
  // FCL: endModel() prints "BVH Error! endModel() called on model with no triangles and vertices."; collide and
  // distance then crash (SIGSEGV).
  auto model = std::make_shared<::fcl::BVHModel<::fcl::OBBRSSd>>();
  model->beginModel();
  model->endModel();
  expectNothingWrittenEitherOrder(model, at(0, 0, 0), sphere(0.5), at(0.3, 0, 0));
}

TEST(FclBadInput, UnfinishedBvhModelWritesNothing) {
  // beginModel() + addTriangle() without endModel(): FCL crashes (SIGSEGV; the BV tree does not exist yet).
  expectNothingWrittenEitherOrder(oneTriangleModel(false), at(0, 0, 0), sphere(0.5), at(0.3, 0, 0));
  // A model never begun.
  expectNothingWrittenEitherOrder(std::make_shared<::fcl::BVHModel<::fcl::OBBRSSd>>(), at(0, 0, 0), sphere(0.5),
                                  at(0.3, 0, 0));
  // Mesh against mesh with one side unfinished.
  expectNothingWrittenEitherOrder(oneTriangleModel(false), at(0, 0, 0), oneTriangleModel(true), at(0, 0, 0));
}

TEST(FclBadInput, DegenerateConvexWritesNothing) {
  // Four coplanar vertices: gq cannot cook a hull from them (cookConvexMesh: DegenerateMesh).
  auto vertices = std::make_shared<std::vector<Vector3d>>(
      std::vector<Vector3d>{Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(1, 1, 0), Vector3d(0, 1, 0)});
  auto faces = std::make_shared<std::vector<int>>(std::vector<int>{4, 0, 1, 2, 3, 4, 0, 3, 2, 1});
  expectNothingWrittenEitherOrder(std::make_shared<::fcl::Convexd>(vertices, 2, faces), at(0, 0, 0), sphere(0.5),
                                  at(0.3, 0, 0));
}

TEST(FclBadInput, NumMaxContactsZeroComputesNothing) {
  // FCL: prints "Warning: should stop early as num_max_contact is 0 !" and returns 0 without touching the result.
  ::fcl::Sphered a(0.5), b(0.5);
  for (const bool contact : {false, true}) {
    Seeded s;
    EXPECT_EQ(gq::fcl::collide<double>(&a, at(0, 0, 0), &b, at(0.3, 0, 0), ::fcl::CollisionRequestd(0, contact),
                                       s.collision), 0u);
    EXPECT_EQ(s.collision.numContacts(), 1u);
  }
}

TEST(FclBadInput, NullGeometryWritesNothing) {
  // FCL dereferences it (SIGSEGV).
  ::fcl::Sphered b(0.5);
  expectNothingWritten(nullptr, at(0, 0, 0), &b, at(0.3, 0, 0));
  expectNothingWritten(&b, at(0, 0, 0), nullptr, at(0.3, 0, 0));
  expectNothingWritten(nullptr, at(0, 0, 0), nullptr, at(0.3, 0, 0));
}

TEST(FclBadInput, NullCollisionObjectWritesNothing) {
  // FCL dereferences it (SIGSEGV). (A CollisionObject cannot hold a null geometry: its constructor dereferences it.)
  ::fcl::CollisionObjectd o(sphere(0.5), at(0.3, 0, 0));
  for (const auto& [o1, o2] : {std::pair<const ::fcl::CollisionObjectd*, const ::fcl::CollisionObjectd*>{nullptr, &o},
                               {&o, nullptr}, {nullptr, nullptr}}) {
    Seeded s;
    EXPECT_EQ(gq::fcl::collide(o1, o2, ::fcl::CollisionRequestd(4, true), s.collision), 0u);
    EXPECT_EQ(s.collision.numContacts(), 1u);
    EXPECT_EQ(gq::fcl::distance(o1, o2, ::fcl::DistanceRequestd(true), s.distance), kNothing);
    EXPECT_EQ(s.distance.min_distance, 5.0);
  }
}

TEST(FclBadInput, FloatNaNPoseWritesNothing) {
  ::fcl::Spheref a(0.5f), b(0.5f);
  ::fcl::Transform3f ta = ::fcl::Transform3f::Identity(), tb = ta;
  tb.translation() = ::fcl::Vector3f(std::numeric_limits<float>::quiet_NaN(), 0, 0);
  ::fcl::CollisionResultf c;
  EXPECT_EQ(gq::fcl::collide<float>(&a, ta, &b, tb, ::fcl::CollisionRequestf(1, true), c), 0u);
  EXPECT_EQ(c.numContacts(), 0u);
  ::fcl::DistanceResultf d;
  EXPECT_EQ(gq::fcl::distance<float>(&a, ta, &b, tb, ::fcl::DistanceRequestf(true), d), std::numeric_limits<float>::max());
  EXPECT_EQ(d.min_distance, std::numeric_limits<float>::max());
}

}  // namespace
