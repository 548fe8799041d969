// computePenetration, pair by pair, against closed-form answers (spec "Penetration Depth"): returns false when
// not penetrating; depth >= 0; translating geom0 by direction * depth separates; direction is unit.
#include <gtest/gtest.h>

#include <cmath>

#include "gq/query.h"
#include "overlap_test_support.h"

namespace gq::test {
namespace {

template <class T> class Penetration : public ::testing::Test {};
TYPED_TEST_SUITE(Penetration, Scalars);

template <class T> double tolOf() { return std::is_same_v<T, float> ? 2e-5 : 1e-12; }

template <class T> void expectDirection(const Vec3<T>& got, const Vec3<T>& want) {
  EXPECT_NEAR(double(got.x()), double(want.x()), 10 * tolOf<T>());
  EXPECT_NEAR(double(got.y()), double(want.y()), 10 * tolOf<T>());
  EXPECT_NEAR(double(got.z()), double(want.z()), 10 * tolOf<T>());
}

template <class T> Quat<T> rotZ(double a) { return Quat<T>(Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()).cast<T>()); }

TYPED_TEST(Penetration, SphereSphereDepthIsRadiusSumMinusCentreDistance) {
  using T = TypeParam;
  const auto r = penetration<T>(SphereGeometry<T>(1), Transform<T>(Vec3<T>(0.5, 0.5, 0)), SphereGeometry<T>(2),
                                Transform<T>(Vec3<T>(0.5, 3.5, 0)));
  ASSERT_TRUE(r.penetrating);
  EXPECT_NEAR(double(r.depth), 0.0, tolOf<T>());  // touching: penetrating with depth 0
  const auto r2 = penetration<T>(SphereGeometry<T>(1), Transform<T>(Vec3<T>(0, 0, 0)), SphereGeometry<T>(2),
                                 Transform<T>(Vec3<T>(0, 2, 0)));
  ASSERT_TRUE(r2.penetrating);
  EXPECT_NEAR(double(r2.depth), 1.0, tolOf<T>());
  expectDirection<T>(r2.direction, Vec3<T>(0, -1, 0));
}

TYPED_TEST(Penetration, SeparatedPairsReturnFalse) {
  using T = TypeParam;
  EXPECT_FALSE(penetration<T>(SphereGeometry<T>(1), Transform<T>(), SphereGeometry<T>(1), Transform<T>(Vec3<T>(2.001, 0, 0))).penetrating);
  EXPECT_FALSE(penetration<T>(BoxGeometry<T>(1, 1, 1), Transform<T>(), BoxGeometry<T>(1, 1, 1), Transform<T>(Vec3<T>(0, 0, 2.01))).penetrating);
  EXPECT_FALSE(penetration<T>(CapsuleGeometry<T>(1, 1), Transform<T>(), BoxGeometry<T>(1, 1, 1), Transform<T>(Vec3<T>(0, 2.01, 0))).penetrating);
  EXPECT_FALSE(penetration<T>(SphereGeometry<T>(1), Transform<T>(Vec3<T>(1.01, 0, 0)), PlaneGeometry<T>(), Transform<T>()).penetrating);
}

TYPED_TEST(Penetration, SpherePlanePushesAlongPlaneNormal) {
  using T = TypeParam;
  const Transform<T> plane(Vec3<T>(1, 2, 3), rotZ<T>(M_PI / 2));  // normal +Y
  const auto r = penetration<T>(SphereGeometry<T>(1), Transform<T>(Vec3<T>(5, 2.25, -4)), PlaneGeometry<T>(), plane);
  ASSERT_TRUE(r.penetrating);
  EXPECT_NEAR(double(r.depth), 0.75, tolOf<T>());
  expectDirection<T>(r.direction, Vec3<T>(0, 1, 0));
  // Swapped pair: the plane moves the other way.
  const auto s = penetration<T>(PlaneGeometry<T>(), plane, SphereGeometry<T>(1), Transform<T>(Vec3<T>(5, 2.25, -4)));
  ASSERT_TRUE(s.penetrating);
  EXPECT_NEAR(double(s.depth), 0.75, tolOf<T>());
  expectDirection<T>(s.direction, Vec3<T>(0, -1, 0));
  // A sphere deep behind the plane is still penetrating (the half-space is solid).
  const auto deep = penetration<T>(SphereGeometry<T>(1), Transform<T>(Vec3<T>(0, -10, 0)), PlaneGeometry<T>(), plane);
  ASSERT_TRUE(deep.penetrating);
  EXPECT_NEAR(double(deep.depth), 13.0, 10 * tolOf<T>());
}

TYPED_TEST(Penetration, SphereCapsuleCentreOnAxisPushesPerpendicular) {
  using T = TypeParam;
  const auto r = penetration<T>(SphereGeometry<T>(0.5), Transform<T>(Vec3<T>(0.3, 0, 0)), CapsuleGeometry<T>(1, 2), Transform<T>());
  ASSERT_TRUE(r.penetrating);
  EXPECT_NEAR(double(r.depth), 1.5, tolOf<T>());
  EXPECT_NEAR(double(r.direction.norm()), 1.0, tolOf<T>());
  EXPECT_NEAR(double(r.direction.x()), 0.0, tolOf<T>());
  const auto cap = penetration<T>(SphereGeometry<T>(0.5), Transform<T>(Vec3<T>(2.5, 0, 0)), CapsuleGeometry<T>(1, 2), Transform<T>());
  ASSERT_TRUE(cap.penetrating);
  EXPECT_NEAR(double(cap.depth), 1.0, tolOf<T>());
  expectDirection<T>(cap.direction, Vec3<T>(1, 0, 0));
}

TYPED_TEST(Penetration, SphereBoxCentreInsidePushesOutThroughNearestFace) {
  using T = TypeParam;
  const Transform<T> box(Vec3<T>(1, 1, 1), rotZ<T>(M_PI / 2));  // local x -> world y
  const auto r = penetration<T>(SphereGeometry<T>(0.25), Transform<T>(Vec3<T>(1, 1.8, 1.1)), BoxGeometry<T>(1, 2, 3), box);
  ASSERT_TRUE(r.penetrating);
  EXPECT_NEAR(double(r.depth), 0.25 + 0.2, tolOf<T>());
  expectDirection<T>(r.direction, Vec3<T>(0, 1, 0));
  // Outside a corner: r - distance to the corner, along the corner diagonal.
  const auto c = penetration<T>(SphereGeometry<T>(1), Transform<T>(Vec3<T>(1.5, 1.5, 1.5)), BoxGeometry<T>(1, 1, 1), Transform<T>());
  ASSERT_TRUE(c.penetrating);
  EXPECT_NEAR(double(c.depth), 1.0 - std::sqrt(0.75), tolOf<T>());
  const T k = T(1 / std::sqrt(3.0));
  expectDirection<T>(c.direction, Vec3<T>(k, k, k));
}

TYPED_TEST(Penetration, CapsuleCapsuleCrossingAxesPushAlongTheirCrossProduct) {
  using T = TypeParam;
  const auto r = penetration<T>(CapsuleGeometry<T>(0.5, 2), Transform<T>(), CapsuleGeometry<T>(0.25, 2),
                                Transform<T>(Vec3<T>(0, 0, 0), rotZ<T>(M_PI / 2)));
  ASSERT_TRUE(r.penetrating);
  EXPECT_NEAR(double(r.depth), 0.75, tolOf<T>());
  EXPECT_NEAR(std::abs(double(r.direction.z())), 1.0, 10 * tolOf<T>());
  const auto p = penetration<T>(CapsuleGeometry<T>(0.5, 2), Transform<T>(Vec3<T>(0, 0.6, 0)), CapsuleGeometry<T>(0.5, 1), Transform<T>(Vec3<T>(1, 0, 0)));
  ASSERT_TRUE(p.penetrating);  // parallel axes 0.6 apart
  EXPECT_NEAR(double(p.depth), 0.4, tolOf<T>());
  expectDirection<T>(p.direction, Vec3<T>(0, 1, 0));
}

TYPED_TEST(Penetration, PlanePairsPushAlongNormalByDeepestPoint) {
  using T = TypeParam;
  const Transform<T> plane;  // normal +X, solid x <= 0
  const auto cap = penetration<T>(CapsuleGeometry<T>(0.5, 1), Transform<T>(Vec3<T>(1.2, 0, 0)), PlaneGeometry<T>(), plane);
  ASSERT_TRUE(cap.penetrating);
  EXPECT_NEAR(double(cap.depth), 0.3, tolOf<T>());
  expectDirection<T>(cap.direction, Vec3<T>(1, 0, 0));
  const Quat<T> q45 = rotZ<T>(M_PI / 4);
  const auto box = penetration<T>(BoxGeometry<T>(1, 1, 1), Transform<T>(Vec3<T>(1, 0, 0), q45), PlaneGeometry<T>(), plane);
  ASSERT_TRUE(box.penetrating);
  EXPECT_NEAR(double(box.depth), std::sqrt(2.0) - 1.0, tolOf<T>());
  expectDirection<T>(box.direction, Vec3<T>(1, 0, 0));
  const Geometry<T> oct = ConvexMeshGeometry<T>(octahedronHull<T>(1), MeshScale<T>(T(2)));
  const auto hull = penetration<T>(oct, Transform<T>(Vec3<T>(1.5, 0, 0)), PlaneGeometry<T>(), plane);
  ASSERT_TRUE(hull.penetrating);
  EXPECT_NEAR(double(hull.depth), 0.5, tolOf<T>());
  expectDirection<T>(hull.direction, Vec3<T>(1, 0, 0));
}

TYPED_TEST(Penetration, BoxBoxTakesTheSmallestFacePushOut) {
  using T = TypeParam;
  const auto r = penetration<T>(BoxGeometry<T>(1, 1, 1), Transform<T>(Vec3<T>(1.5, 0.2, 1.9)), BoxGeometry<T>(1, 1, 1), Transform<T>());
  ASSERT_TRUE(r.penetrating);
  EXPECT_NEAR(double(r.depth), 0.1, tolOf<T>());
  expectDirection<T>(r.direction, Vec3<T>(0, 0, 1));
}

TYPED_TEST(Penetration, BoxBoxEdgeEdgeAxisGivesTheDepth) {
  using T = TypeParam;
  // Box0 turned 45 degrees about Y has its top edge along Y at z = sqrt2; box1 turned 45 degrees about X has its
  // bottom edge along X at z = c - sqrt2. The edges cross with overlap 2 sqrt2 - c along Z = Y x X.
  const Quat<T> aboutY(Eigen::AngleAxis<T>(T(M_PI / 4), Vec3<T>::UnitY()));
  const Quat<T> aboutX(Eigen::AngleAxis<T>(T(M_PI / 4), Vec3<T>::UnitX()));
  const double c = 2 * std::sqrt(2.0) - 0.05;
  const auto r = penetration<T>(BoxGeometry<T>(1, 1, 1), Transform<T>(Vec3<T>(0, 0, 0), aboutY), BoxGeometry<T>(1, 1, 1),
                                Transform<T>(Vec3<T>(0, 0, T(c)), aboutX));
  ASSERT_TRUE(r.penetrating);
  EXPECT_NEAR(double(r.depth), 0.05, 20 * tolOf<T>());
  expectDirection<T>(r.direction, Vec3<T>(0, 0, -1));
}

TYPED_TEST(Penetration, ConvexHullMatchesBoxWithSameShape) {
  using T = TypeParam;
  const Geometry<T> hull = ConvexMeshGeometry<T>(boxHull<T>(Vec3<T>(1, 2, 0.5)));
  const Geometry<T> box = BoxGeometry<T>(1, 2, 0.5);
  Rng rng(7);
  for (int i = 0; i < 200; ++i) {
    const Transform<T> p0 = rng.pose<T>(1.5), p1 = rng.pose<T>(1.5);
    const auto a = penetration<T>(box, p0, box, p1);
    const auto b = penetration<T>(hull, p0, box, p1);
    const auto c = penetration<T>(hull, p0, hull, p1);
    ASSERT_EQ(a.penetrating, b.penetrating);
    ASSERT_EQ(a.penetrating, c.penetrating);
    if (!a.penetrating) continue;
    EXPECT_NEAR(double(a.depth), double(b.depth), 20 * tolOf<T>());
    EXPECT_NEAR(double(a.depth), double(c.depth), 20 * tolOf<T>());
  }
}

TYPED_TEST(Penetration, ScaledConvexUsesScaledGeometry) {
  using T = TypeParam;
  // Octahedron scaled by (2, 1, 1): the face normal through (2,0,0),(0,1,0),(0,0,1) is (1,2,2)/3, plane offset 2/3.
  const Geometry<T> oct = ConvexMeshGeometry<T>(octahedronHull<T>(1), MeshScale<T>(Vec3<T>(2, 1, 1)));
  const Vec3<T> n(T(1.0 / 3), T(2.0 / 3), T(2.0 / 3));
  const auto r = penetration<T>(SphereGeometry<T>(0.5), Transform<T>(Vec3<T>(n * T(2.0 / 3 + 0.25))), oct, Transform<T>());
  ASSERT_TRUE(r.penetrating);
  EXPECT_NEAR(double(r.depth), 0.25, 10 * tolOf<T>());
  expectDirection<T>(r.direction, n);
}

TYPED_TEST(Penetration, CapsuleBoxSegmentInsideAddsRadiusToSegmentDepth) {
  using T = TypeParam;
  // Segment from (-0.5,0,0.7) to (0.5,0,0.7) inside the unit box: segment depth 0.3 through +Z, plus r = 0.2.
  const auto r = penetration<T>(CapsuleGeometry<T>(0.2, 0.5), Transform<T>(Vec3<T>(0, 0, 0.7)), BoxGeometry<T>(1, 1, 1), Transform<T>());
  ASSERT_TRUE(r.penetrating);
  EXPECT_NEAR(double(r.depth), 0.5, tolOf<T>());
  expectDirection<T>(r.direction, Vec3<T>(0, 0, 1));
  // Segment outside, over an edge: r - distance to the edge.
  const auto e = penetration<T>(CapsuleGeometry<T>(0.5, 3), Transform<T>(Vec3<T>(0, 1.2, 1.2)), BoxGeometry<T>(1, 1, 1), Transform<T>());
  ASSERT_TRUE(e.penetrating);
  EXPECT_NEAR(double(e.depth), 0.5 - 0.2 * std::sqrt(2.0), tolOf<T>());
  const T k = T(1 / std::sqrt(2.0));
  expectDirection<T>(e.direction, Vec3<T>(0, k, k));
}

TYPED_TEST(Penetration, UnsupportedCellsSayWhetherTheSpecExcludesThem) {
  using T = TypeParam;
  PenetrationResult<T> r;
  r.depth = T(42);
  const Status s = computePenetration<T>(r, PlaneGeometry<T>(), Transform<T>(), PlaneGeometry<T>(), Transform<T>());
  EXPECT_EQ(s.code, StatusCode::Unsupported);
  EXPECT_NE(s.toString().find("not defined by the spec"), std::string::npos) << s.toString();
  EXPECT_EQ(r.depth, T(42));  // output untouched
}

TYPED_TEST(Penetration, InvalidInputWritesNoOutput) {
  using T = TypeParam;
  PenetrationResult<T> r;
  r.depth = T(42);
  const T nan = std::numeric_limits<T>::quiet_NaN();
  Status s = computePenetration<T>(r, SphereGeometry<T>(1), Transform<T>(Vec3<T>(nan, 0, 0)), SphereGeometry<T>(1), Transform<T>());
  EXPECT_EQ(s.code, StatusCode::InvalidArgument);
  s = computePenetration<T>(r, SphereGeometry<T>(-1), Transform<T>(), SphereGeometry<T>(1), Transform<T>());
  EXPECT_EQ(s.code, StatusCode::InvalidArgument);
  EXPECT_EQ(r.depth, T(42));
}

}  // namespace
}  // namespace gq::test
