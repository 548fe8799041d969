// Scene mutation and bad input: every rejected call returns a clear Status and changes nothing; rejected queries
// write no output.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "gq/scene.h"
#include "scene_test_support.h"

namespace gq {
namespace {

using test::Rng;

template <class T> class SceneInput : public ::testing::Test {};
TYPED_TEST_SUITE(SceneInput, test::Scalars);

template <class T> T nan() { return std::numeric_limits<T>::quiet_NaN(); }

template <class T> Scene<T> twoSpheres() {
  Scene<T> s;
  EXPECT_TRUE(s.add(10, SphereGeometry<T>(T(1)), Transform<T>(Vec3<T>(T(0), T(0), T(0)))).ok());
  EXPECT_TRUE(s.add(20, SphereGeometry<T>(T(1)), Transform<T>(Vec3<T>(T(5), T(0), T(0)))).ok());
  return s;
}

TYPED_TEST(SceneInput, AddRejectsNanPoseDuplicateIdInvalidGeometryAndEmptyShape) {
  using T = TypeParam;
  Scene<T> s = twoSpheres<T>();
  Transform<T> bad(Vec3<T>(nan<T>(), T(0), T(0)));
  Status st = s.add(30, SphereGeometry<T>(T(1)), bad);
  EXPECT_EQ(st.code, StatusCode::InvalidArgument);
  EXPECT_STREQ(st.message(), "pose is not finite");
  Transform<T> unnormalized(Vec3<T>::Zero(), Quat<T>(T(2), T(0), T(0), T(0)));
  EXPECT_EQ(s.add(30, SphereGeometry<T>(T(1)), unnormalized).code, StatusCode::InvalidArgument);
  st = s.add(10, SphereGeometry<T>(T(2)), Transform<T>());
  EXPECT_EQ(st.code, StatusCode::InvalidArgument);
  EXPECT_STREQ(st.message(), "an instance with this id is already in the scene");
  EXPECT_EQ(s.add(30, SphereGeometry<T>(T(-1)), Transform<T>()).code, StatusCode::InvalidArgument);
  EXPECT_EQ(s.add(30, Shape<T>(), Transform<T>()).code, StatusCode::InvalidArgument);
  EXPECT_EQ(s.size(), 2u);
  EXPECT_FALSE(s.contains(30));
  // The first sphere kept its radius: a ray stops at x = -1.
  SceneRaycastHit<T> hit;
  bool has = false;
  ASSERT_TRUE(s.raycastClosest(Vec3<T>(T(-3), T(0), T(0)), Vec3<T>::UnitX(), T(10), hit, has).ok());
  ASSERT_TRUE(has);
  EXPECT_EQ(hit.id, 10u);
  EXPECT_NEAR(double(hit.hit.distance), 2.0, 1e-5);
}

TYPED_TEST(SceneInput, RemoveTwiceAndUnknownIdsAreErrorsThatChangeNothing) {
  using T = TypeParam;
  Scene<T> s = twoSpheres<T>();
  ASSERT_TRUE(s.remove(10).ok());
  Status st = s.remove(10);
  EXPECT_EQ(st.code, StatusCode::InvalidArgument);
  EXPECT_STREQ(st.message(), "no instance with this id in the scene");
  EXPECT_EQ(s.setPose(99, Transform<T>()).code, StatusCode::InvalidArgument);
  EXPECT_EQ(s.setMask(99, 1u).code, StatusCode::InvalidArgument);
  Transform<T> p;
  EXPECT_EQ(s.pose(99, p).code, StatusCode::InvalidArgument);
  Bounds3<T> b;
  EXPECT_EQ(s.bounds(99, b).code, StatusCode::InvalidArgument);
  EXPECT_EQ(s.size(), 1u);
  std::vector<InstanceId> ids;
  ASSERT_TRUE(s.ids(ids).ok());
  EXPECT_EQ(ids, std::vector<InstanceId>{20});
}

TYPED_TEST(SceneInput, SetPoseRejectsNanAndKeepsTheOldPose) {
  using T = TypeParam;
  Scene<T> s = twoSpheres<T>();
  Transform<T> before;
  ASSERT_TRUE(s.pose(20, before).ok());
  EXPECT_EQ(s.setPose(20, Transform<T>(Vec3<T>(T(1), nan<T>(), T(0)))).code, StatusCode::InvalidArgument);
  Transform<T> after;
  ASSERT_TRUE(s.pose(20, after).ok());
  EXPECT_EQ(after.p, before.p);
  std::vector<InstanceId> ids;
  ASSERT_TRUE(s.overlapAll(Geometry<T>(SphereGeometry<T>(T(0.5))), Transform<T>(Vec3<T>(T(5), T(0), T(0))), ids).ok());
  EXPECT_EQ(ids, std::vector<InstanceId>{20});
}

TYPED_TEST(SceneInput, QueriesRejectBadInputAndWriteNothing) {
  using T = TypeParam;
  const Scene<T> s = twoSpheres<T>();
  SceneRaycastHit<T> hit;
  hit.id = 777;
  bool has = true;
  const Vec3<T> o(T(-3), T(0), T(0));
  const Vec3<T> x = Vec3<T>::UnitX();
  EXPECT_EQ(s.raycastClosest(Vec3<T>(nan<T>(), T(0), T(0)), x, T(10), hit, has).code, StatusCode::InvalidArgument);
  EXPECT_EQ(s.raycastClosest(o, Vec3<T>(T(2), T(0), T(0)), T(10), hit, has).code, StatusCode::InvalidArgument);
  EXPECT_EQ(s.raycastAny(o, x, T(-1), hit, has).code, StatusCode::InvalidArgument);
  EXPECT_EQ(s.raycastClosest(o, x, nan<T>(), hit, has).code, StatusCode::InvalidArgument);
  std::uint32_t count = 5;
  SceneRaycastHit<T> hits[2];
  EXPECT_EQ(s.raycastAll(o, x, T(10), kDefaultHitFlags, 0u, hits, count).code, StatusCode::InvalidArgument);
  EXPECT_EQ(s.raycastAll(o, x, T(10), kDefaultHitFlags, 2u, nullptr, count).code, StatusCode::InvalidArgument);
  EXPECT_EQ(count, 5u);
  EXPECT_EQ(hit.id, 777u);
  EXPECT_TRUE(has);

  const Geometry<T> ball = SphereGeometry<T>(T(0.5));
  const Transform<T> nanPose(Vec3<T>(T(0), T(0), nan<T>()));
  std::vector<InstanceId> ids{42};
  EXPECT_EQ(s.overlapAll(ball, nanPose, ids).code, StatusCode::InvalidArgument);
  EXPECT_EQ(s.overlapAll(Geometry<T>(SphereGeometry<T>(T(-1))), Transform<T>(), ids).code, StatusCode::InvalidArgument);
  EXPECT_EQ(ids, std::vector<InstanceId>{42});
  SceneDistanceResult<T> near;
  near.id = 777;
  bool found = true;
  EXPECT_EQ(s.nearest(ball, Transform<T>(), nan<T>(), near, found).code, StatusCode::InvalidArgument);
  EXPECT_EQ(s.nearest(ball, nanPose, T(1), near, found).code, StatusCode::InvalidArgument);
  SceneSweepHit<T> sh;
  sh.id = 777;
  EXPECT_EQ(s.sweepClosest(Vec3<T>(T(0.5), T(0), T(0)), T(1), ball, Transform<T>(), sh, has).code,
            StatusCode::InvalidArgument);
  EXPECT_EQ(s.sweepClosest(x, T(1), ball, Transform<T>(), sh, has, kDefaultHitFlags, T(-1)).code,
            StatusCode::InvalidArgument);
  EXPECT_EQ(near.id, 777u);
  EXPECT_EQ(sh.id, 777u);
  EXPECT_TRUE(found);
  EXPECT_TRUE(has);
}

TYPED_TEST(SceneInput, EmptySceneAnswersNothing) {
  using T = TypeParam;
  const Scene<T> s;
  SceneRaycastHit<T> hit;
  bool has = true;
  ASSERT_TRUE(s.raycastClosest(Vec3<T>::Zero(), Vec3<T>::UnitX(), T(10), hit, has).ok());
  EXPECT_FALSE(has);
  std::vector<ScenePair> pairs{{1, 2}};
  ASSERT_TRUE(s.overlappingPairs(pairs).ok());
  EXPECT_TRUE(pairs.empty());
  EXPECT_EQ(s.treeDepth(), 0u);
}

TYPED_TEST(SceneInput, NearestHonoursTheBoundAndTiesGoToTheSmallerId) {
  using T = TypeParam;
  Scene<T> s;
  ASSERT_TRUE(s.add(9, SphereGeometry<T>(T(1)), Transform<T>(Vec3<T>(T(4), T(0), T(0)))).ok());
  ASSERT_TRUE(s.add(3, SphereGeometry<T>(T(1)), Transform<T>(Vec3<T>(T(-4), T(0), T(0)))).ok());
  const Geometry<T> ball = SphereGeometry<T>(T(1));
  SceneDistanceResult<T> r;
  bool found = false;
  ASSERT_TRUE(s.nearest(ball, Transform<T>(), T(1.5), r, found).ok());
  EXPECT_FALSE(found);
  ASSERT_TRUE(s.nearest(ball, Transform<T>(), T(2), r, found).ok());
  ASSERT_TRUE(found);
  EXPECT_EQ(r.id, 3u);
  EXPECT_EQ(r.result.distance, T(2));
  ASSERT_TRUE(s.setMask(3, 2u).ok());
  SceneFilter f;
  f.mask = 1u;
  ASSERT_TRUE(s.nearest(ball, Transform<T>(), std::numeric_limits<T>::infinity(), r, found, f).ok());
  ASSERT_TRUE(found);
  EXPECT_EQ(r.id, 9u);
}

TYPED_TEST(SceneInput, RaycastAllSortsHitsAcrossInstances) {
  using T = TypeParam;
  Scene<T> s;
  for (int i = 0; i < 5; ++i) {
    ASSERT_TRUE(
        s.add(InstanceId(100 - i), SphereGeometry<T>(T(0.25)), Transform<T>(Vec3<T>(T(2 * i), T(0), T(0)))).ok());
  }
  SceneRaycastHit<T> hits[3];
  std::uint32_t count = 0;
  ASSERT_TRUE(
      s.raycastAll(Vec3<T>(T(-1), T(0), T(0)), Vec3<T>::UnitX(), T(100), kDefaultHitFlags, 3u, hits, count).ok());
  ASSERT_EQ(count, 3u);
  EXPECT_EQ(hits[0].id, 100u);
  EXPECT_EQ(hits[1].id, 99u);
  EXPECT_EQ(hits[2].id, 98u);
  EXPECT_LT(hits[0].hit.distance, hits[1].hit.distance);
}

TYPED_TEST(SceneInput, ClearEmptiesAndTheSceneIsReusable) {
  using T = TypeParam;
  Scene<T> s = twoSpheres<T>();
  s.clear();
  EXPECT_EQ(s.size(), 0u);
  EXPECT_TRUE(s.add(10, SphereGeometry<T>(T(1)), Transform<T>()).ok());
  Scene<T> moved = std::move(s);
  EXPECT_TRUE(moved.contains(10));
}

// The example of docs/core.md, "Scenes".
TEST(SceneDocs, ExampleAnswersAsDocumented) {
  Scene<double> scene;
  Status s = scene.add(7, SphereGeometry<double>(0.5), Transform<double>(Vec3<double>(2, 0, 0)));
  ASSERT_TRUE(s.ok());
  s = scene.add(8, BoxGeometry<double>(1, 1, 1), Transform<double>(Vec3<double>(6, 0, 0)), 0x2);
  ASSERT_TRUE(s.ok());
  s = scene.setPose(8, Transform<double>(Vec3<double>(5, 0, 0)));
  ASSERT_TRUE(s.ok());
  SceneRaycastHit<double> hit;
  bool hasHit = false;
  s = scene.raycastClosest(Vec3<double>::Zero(), Vec3<double>::UnitX(), 100.0, hit, hasHit);
  ASSERT_TRUE(s.ok());
  ASSERT_TRUE(hasHit);
  EXPECT_EQ(hit.id, 7u);
  EXPECT_EQ(hit.hit.distance, 1.5);
  SceneFilter onlyMask2;
  onlyMask2.mask = 0x2;
  std::vector<InstanceId> ids;
  s = scene.overlapAll(SphereGeometry<double>(1.0), Transform<double>(Vec3<double>(4.5, 0, 0)), ids, onlyMask2);
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(ids, std::vector<InstanceId>{8});
  // The mask hides the box from a query with mask 0x1; the sphere (mask all ones) still shows.
  SceneFilter onlyMask1;
  onlyMask1.mask = 0x1;
  s = scene.overlapAll(SphereGeometry<double>(3.0), Transform<double>(Vec3<double>(3.5, 0, 0)), ids, onlyMask1);
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(ids, std::vector<InstanceId>{7});
}

}  // namespace
}  // namespace gq
