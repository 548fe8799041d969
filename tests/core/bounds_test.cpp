// computeGeomBounds for sphere, plane, capsule, box, convex and custom: tight boxes (rotated too), the spec's
// offset/inflation semantics, plane extents, and rejected inputs.
#include <gtest/gtest.h>

#include <limits>

#include "gq/cooking.h"
#include "gq/custom.h"
#include "gq/query.h"
#include "test_util.h"

namespace gq {
namespace {

using test::LD;
using test::Vec3L;

template <class T> class Bounds : public ::testing::Test {};
TYPED_TEST_SUITE(Bounds, test::Scalars);

template <class T> Bounds3<T> bounds(const Geometry<T>& g, const Transform<T>& pose, T offset = T(0), T inflation = T(1)) {
  Bounds3<T> b;
  EXPECT_TRUE(computeGeomBounds(b, g, pose, offset, inflation).ok());
  return b;
}

template <class T> void expectBox(const Bounds3<T>& b, const Vec3L& lo, const Vec3L& hi, double scale) {
  const double tol = test::Tol<T>::kRel * scale;
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(double(b.min[i]), double(lo[i]), tol) << "min axis " << i;
    EXPECT_NEAR(double(b.max[i]), double(hi[i]), tol) << "max axis " << i;
  }
}

// A custom shape whose local bounds are an off-centre box.
template <class T> class OffsetBox : public CustomGeometryCallbacks<T> {
 public:
  const char* name() const override { return "offset-box"; }
  Bounds3<T> localBounds() const override { return Bounds3<T>::fromMinMax(Vec3<T>(0, -1, -2), Vec3<T>(2, 1, 0)); }
  Vec3<T> support(const Vec3<T>& d) const override {
    const Bounds3<T> b = localBounds();
    return Vec3<T>(d.x() > 0 ? b.max.x() : b.min.x(), d.y() > 0 ? b.max.y() : b.min.y(), d.z() > 0 ? b.max.z() : b.min.z());
  }
  bool raycast(const Vec3<T>&, const Vec3<T>&, T, HitFlags, RaycastHit<T>&) const override { return false; }
};

// Brute force: the box of a set of local points under a pose, in long double.
template <class T> std::pair<Vec3L, Vec3L> boxOfPoints(const std::vector<Vec3L>& local, const Transform<T>& pose) {
  Vec3L lo = Vec3L::Constant(std::numeric_limits<LD>::max()), hi = -lo;
  for (const Vec3L& p : local) {
    const Vec3L w = test::rotationLD(pose.q) * p + test::toLD(pose.p);
    lo = lo.cwiseMin(w);
    hi = hi.cwiseMax(w);
  }
  return {lo, hi};
}

std::vector<Vec3L> corners(const Vec3L& lo, const Vec3L& hi) {
  std::vector<Vec3L> out;
  for (int i = 0; i < 8; ++i) out.emplace_back(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z());
  return out;
}

TYPED_TEST(Bounds, SphereBoundsAreCentrePlusMinusRadius) {
  using T = TypeParam;
  test::Rng rng(1);
  const Transform<T> pose = rng.pose<T>(10);
  const Bounds3<T> b = bounds<T>(SphereGeometry<T>(T(2)), pose);
  expectBox(b, test::toLD(pose.p) - Vec3L::Constant(2), test::toLD(pose.p) + Vec3L::Constant(2), 12);
}

TYPED_TEST(Bounds, BoxBoundsAreTightWhenRotated) {
  using T = TypeParam;
  test::Rng rng(2);
  for (int i = 0; i < 100; ++i) {
    const Vec3<T> h = rng.vec<T>(0.1, 3);
    const Transform<T> pose = rng.pose<T>(10);
    const auto [lo, hi] = boxOfPoints(corners(-test::toLD(h), test::toLD(h)), pose);
    expectBox(bounds<T>(BoxGeometry<T>(h), pose), lo, hi, 20);
  }
}

TYPED_TEST(Bounds, CapsuleBoundsAreTightWhenRotated) {
  using T = TypeParam;
  test::Rng rng(3);
  for (int i = 0; i < 100; ++i) {
    const T r = T(rng.uniform(0.1, 2)), hh = T(rng.uniform(0, 3));
    const Transform<T> pose = rng.pose<T>(10);
    // The union of the end spheres' boxes.
    auto [lo, hi] = boxOfPoints<T>({Vec3L(LD(hh), 0, 0), Vec3L(-LD(hh), 0, 0)}, pose);
    expectBox(bounds<T>(CapsuleGeometry<T>(r, hh), pose), Vec3L(lo - Vec3L::Constant(LD(r))),
              Vec3L(hi + Vec3L::Constant(LD(r))), 20);
  }
}

TYPED_TEST(Bounds, ConvexBoundsAreExactUnderScaleAndPose) {
  using T = TypeParam;
  test::Rng rng(4);
  std::vector<Vec3<T>> pts;
  for (int i = 0; i < 60; ++i) {
    const Vec3<T> dir = rng.unitVector<T>();
    pts.push_back(dir * T(rng.uniform(0.5, 2)));
  }
  std::shared_ptr<const ConvexMesh<T>> hull;
  ASSERT_TRUE(cookConvexMesh(pts, hull).ok());
  for (int i = 0; i < 50; ++i) {
    const MeshScale<T> scale = rng.meshScale<T>(0.3, 3);
    const Transform<T> pose = rng.pose<T>(10);
    // Every input point, scaled in long double: interior points cannot extend the box, so this is the hull's box.
    const test::Mat3L R = test::rotationLD(scale.rotation);
    const test::Mat3L S = R * test::toLD(scale.scale).asDiagonal() * R.transpose();
    std::vector<Vec3L> local;
    for (const Vec3<T>& p : pts) local.push_back(S * test::toLD(p));
    const auto [lo, hi] = boxOfPoints(local, pose);
    expectBox(bounds<T>(ConvexMeshGeometry<T>(hull, scale), pose), lo, hi, 20);
  }
}

TYPED_TEST(Bounds, CustomBoundsAreTheLocalBoxTransformed) {
  using T = TypeParam;
  test::Rng rng(5);
  const Geometry<T> g = CustomGeometry<T>(std::make_shared<OffsetBox<T>>());
  for (int i = 0; i < 20; ++i) {
    const Transform<T> pose = rng.pose<T>(10);
    const auto [lo, hi] = boxOfPoints(corners(Vec3L(0, -1, -2), Vec3L(2, 1, 0)), pose);
    expectBox(bounds<T>(g, pose), lo, hi, 20);
  }
}

TYPED_TEST(Bounds, PlaneBoundsAreInfiniteExceptAlongAnExactlyAlignedNormal) {
  using T = TypeParam;
  constexpr T big = std::numeric_limits<T>::max();
  // Normal +X at x = 3: the solid half-space ends at x = 3.
  Bounds3<T> b = bounds<T>(PlaneGeometry<T>(), Transform<T>(Vec3<T>(3, 1, 2)));
  EXPECT_EQ(b.max.x(), T(3));
  EXPECT_EQ(b.min.x(), -big);
  EXPECT_EQ(b.min.y(), -big);
  EXPECT_EQ(b.max.z(), big);
  // Normal -X (rotated half a turn about Y): the box starts at x = 3.
  const Quat<T> flip(T(0), T(0), T(1), T(0));
  b = bounds<T>(PlaneGeometry<T>(), Transform<T>(Vec3<T>(3, 1, 2), flip));
  EXPECT_EQ(b.min.x(), T(3));
  EXPECT_EQ(b.max.x(), big);
  // Normal +Z (X mapped onto Z by a quarter turn about Y written exactly): bounded along Z.
  const Quat<T> toZ(Eigen::Matrix<T, 3, 3>((Eigen::Matrix<T, 3, 3>() << 0, 0, -1, 0, 1, 0, 1, 0, 0).finished()));
  b = bounds<T>(PlaneGeometry<T>(), Transform<T>(Vec3<T>(3, 1, 2), toZ), T(0.5), T(1.01));
  const Vec3<T> n = toZ * Vec3<T>::UnitX();
  if (n.x() == T(0) && n.y() == T(0)) {
    EXPECT_EQ(b.max.z(), T(2.5));  // the finite face moves out by the offset; inflation does not apply
    EXPECT_EQ(b.min.z(), -big);
  } else {  // round-off tilted the normal: no longer exactly aligned, so unbounded
    EXPECT_EQ(b.max.z(), big);
  }
  EXPECT_EQ(b.max.x(), big);
  // Tilted: unbounded everywhere, and never infinite even with offset and inflation.
  b = bounds<T>(PlaneGeometry<T>(), Transform<T>(Vec3<T>(3, 1, 2), Quat<T>(Eigen::AngleAxis<T>(T(0.1), Vec3<T>::UnitZ()))),
                T(1), T(1.01));
  EXPECT_EQ(b.min, Vec3<T>::Constant(-big));
  EXPECT_EQ(b.max, Vec3<T>::Constant(big));
}

TYPED_TEST(Bounds, OffsetGrowsExtentsThenInflationScalesAboutTheCentre) {
  using T = TypeParam;
  const Transform<T> pose(Vec3<T>(1, 2, 3));
  const Geometry<T> box = BoxGeometry<T>(T(1), T(2), T(3));
  const Bounds3<T> b = bounds<T>(box, pose, T(0.5), T(2));
  // extents (1,2,3) + 0.5 = (1.5, 2.5, 3.5), times 2 = (3, 5, 7), about centre (1,2,3).
  expectBox(b, Vec3L(-2, -3, -4), Vec3L(4, 7, 10), 10);
}

TYPED_TEST(Bounds, DefaultInflationIsOnePointZeroOne) {
  using T = TypeParam;
  Bounds3<T> b;
  ASSERT_TRUE(computeGeomBounds<T>(b, SphereGeometry<T>(T(1)), Transform<T>()).ok());
  expectBox(b, Vec3L::Constant(-1.01L), Vec3L::Constant(1.01L), 1);
}

TYPED_TEST(Bounds, ZeroOffsetAndUnitInflationGiveTheTightBox) {
  using T = TypeParam;
  const Bounds3<T> b = bounds<T>(BoxGeometry<T>(T(1), T(2), T(3)), Transform<T>(Vec3<T>(5, 0, 0)));
  EXPECT_EQ(b.min, Vec3<T>(4, -2, -3));
  EXPECT_EQ(b.max, Vec3<T>(6, 2, 3));
}

TYPED_TEST(Bounds, InvalidOffsetInflationOrPoseIsRejectedAndWritesNothing) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  const Geometry<T> g = SphereGeometry<T>(T(1));
  const Bounds3<T> sentinel = Bounds3<T>::fromMinMax(Vec3<T>::Constant(7), Vec3<T>::Constant(8));
  struct Case { T offset, inflation; Transform<T> pose; Geometry<T> geom; };
  const std::vector<Case> cases = {
      {nan, T(1), Transform<T>(), g}, {inf, T(1), Transform<T>(), g}, {T(-1), T(1), Transform<T>(), g},
      {T(0), T(0), Transform<T>(), g}, {T(0), T(-1), Transform<T>(), g}, {T(0), nan, Transform<T>(), g},
      {T(0), T(1), Transform<T>(Vec3<T>(nan, 0, 0)), g}, {T(0), T(1), Transform<T>(), SphereGeometry<T>(T(-1))},
      {T(0), T(1), Transform<T>(Vec3<T>::Zero(), Quat<T>(T(2), T(0), T(0), T(0))), g},
  };
  for (const Case& c : cases) {
    Bounds3<T> b = sentinel;
    const Status s = computeGeomBounds(b, c.geom, c.pose, c.offset, c.inflation);
    EXPECT_EQ(s.code, StatusCode::InvalidArgument) << s.toString();
    EXPECT_STRNE(s.message(), "");
    EXPECT_EQ(b.min, sentinel.min);
    EXPECT_EQ(b.max, sentinel.max);
  }
}

}  // namespace
}  // namespace gq
