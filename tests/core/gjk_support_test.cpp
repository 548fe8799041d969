// Support mappings, the boolean GJK and EPA's separating translation (internal API in core/src/gjk/gjk.h).
#include "gjk_test_shapes.h"

#include "gjk/gjk.h"

namespace {

using namespace gjktest;

template <class T> class GjkSupport : public ::testing::Test {};
TYPED_TEST_SUITE(GjkSupport, Scalars);

template <class T> L bruteForceSupportValue(const gq::ConvexMesh<T>& mesh, const Eigen::Matrix<L, 3, 3>& S, const PoseL& t,
                                            const VL& d) {
  L best = -std::numeric_limits<L>::infinity();
  for (const auto& v : mesh.vertices) best = std::max(best, d.dot(t.apply(S * toL(v))));
  return best;
}

TYPED_TEST(GjkSupport, HillClimbingOnLargeHullFindsTheExtremeVertex) {
  using T = TypeParam;
  Rng rng(41);
  const auto hull = makeHull<T>(pointsOnEllipsoid<T>(rng, 80, Eigen::Vector3d(1, 0.6, 0.9)));
  ASSERT_GT(hull->vertices.size(), gq::detail::kHillClimbMinVertices);
  for (int s = 0; s < 2; ++s) {
    const gq::MeshScale<T> scale = s ? randomScale<T>(rng, 0.3, 2) : gq::MeshScale<T>();
    const auto pose = randomPose<T>(rng, 2);
    const auto shape = gq::detail::makeConvexShape<T>(gq::ConvexMeshGeometry<T>(hull, scale), pose);
    const Eigen::Matrix<L, 3, 3> S = scale.toMatrix().template cast<L>();
    for (int i = 0; i < 2000; ++i) {
      const Eigen::Vector3d d = rng.unit();
      const L got = toL(shape.support(d.cast<T>())).dot(d.cast<L>());
      const L want = bruteForceSupportValue(*hull, S, toL(pose), d.cast<L>());
      ASSERT_NEAR(double(got), double(want), kClosedFormTol<T>) << "direction " << i;
    }
  }
}

TYPED_TEST(GjkSupport, SphereAndCapsuleAreRoundedPointAndSegment) {
  using T = TypeParam;
  const gq::Transform<T> pose(gq::Vec3<T>(T(1), T(2), T(3)));
  const auto s = gq::detail::makeConvexShape<T>(sphere<T>(0.5), pose);
  EXPECT_EQ(s.margin, T(0.5));
  EXPECT_EQ(s.support(gq::Vec3<T>(T(1), T(1), T(0))), pose.p);
  const auto c = gq::detail::makeConvexShape<T>(capsule<T>(0.25, 2), pose);
  EXPECT_EQ(c.margin, T(0.25));
  EXPECT_EQ(c.support(gq::Vec3<T>(T(-1), T(5), T(0))), pose.p - gq::Vec3<T>(T(2), T(0), T(0)));
}

TYPED_TEST(GjkSupport, OverlapAgreesWithExactSeparation) {
  using T = TypeParam;
  Rng rng(42);
  int overlapping = 0;
  for (int i = 0; i < 1000; ++i) {
    const Eigen::Vector3d h0 = rng.vec(0.2, 1), h1 = rng.vec(0.2, 1);
    const auto p0 = randomPose<T>(rng, 1.2), p1 = randomPose<T>(rng, 1.2);
    const L sat = polytopePenetration(boxPolytope<T>(h0.cast<T>(), p0), boxPolytope<T>(h1.cast<T>(), p1));
    if (std::abs(double(sat)) < 1e-3) continue;  // too close to touching to be a fair test in float
    const auto a = gq::detail::makeConvexShape<T>(box<T>(h0), p0);
    const auto b = gq::detail::makeConvexShape<T>(box<T>(h1), p1);
    EXPECT_EQ(gq::detail::gjkOverlap(a, b), sat > 0) << "pose " << i;
    overlapping += sat > 0;
  }
  EXPECT_GT(overlapping, 100);
}

TYPED_TEST(GjkSupport, EpaTranslationByDepthAlongNormalSeparates) {
  using T = TypeParam;
  Rng rng(43);
  const T slack = T(std::is_same_v<T, double> ? 1e-6 : 1e-3);
  int tested = 0;
  for (int i = 0; i < 1000 && tested < 300; ++i) {
    const auto hull = makeHull<T>(pointsOnEllipsoid<T>(rng, 14, rng.vec(0.4, 1)));
    const auto p0 = randomPose<T>(rng, 0.5), p1 = randomPose<T>(rng, 0.5);
    const gq::Geometry<T> g0 = gq::ConvexMeshGeometry<T>(hull), g1 = box<T>(rng.vec(0.2, 0.8));
    const auto a = gq::detail::makeConvexShape<T>(g0, p0);
    const auto e = gq::detail::epaPenetration(a, gq::detail::makeConvexShape<T>(g1, p1));
    if (!(e.depth > slack)) continue;
    ++tested;
    ASSERT_TRUE(e.status.ok()) << e.status.toString();
    const auto moved = [&](T t) { return gq::Transform<T>(p1.p + t * e.normal, p1.q); };
    EXPECT_FALSE(gq::detail::gjkOverlap(a, gq::detail::makeConvexShape<T>(g1, moved(e.depth + slack)))) << "pose " << i;
    EXPECT_TRUE(gq::detail::gjkOverlap(a, gq::detail::makeConvexShape<T>(g1, moved(e.depth - slack)))) << "pose " << i;
  }
  EXPECT_GE(tested, 100);
}

}  // namespace
