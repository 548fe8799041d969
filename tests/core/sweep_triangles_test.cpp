// sweepTriangles rules (the spec's sweep against a triangle buffer), float and double. Expected values are closed
// forms: a sphere of radius r moving along +X towards the triangle in the plane x = c touches it after c - r - x0.
#include <gtest/gtest.h>

#include <vector>

#include "gq/mesh_query.h"

namespace {

using namespace gq;

template <class T> struct SweepTriangles : ::testing::Test {
  static constexpr double kTol = std::is_same_v<T, double> ? 1e-9 : 2e-4;
  // A big triangle in the plane x = c; front face (counter-clockwise) towards -X, so +X sweeps hit its front.
  static Triangle<T> wallAt(double c) {
    Triangle<T> t;
    t.verts[0] = Vec3<T>(T(c), T(-5), T(-5));
    t.verts[1] = Vec3<T>(T(c), T(-5), T(10));
    t.verts[2] = Vec3<T>(T(c), T(10), T(-5));
    return t;
  }
  static Triangle<T> flipped(const Triangle<T>& t) {
    Triangle<T> f = t;
    std::swap(f.verts[1], f.verts[2]);
    return f;
  }
  static Vec3<T> x() { return Vec3<T>::UnitX(); }
};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(SweepTriangles, Scalars);

TYPED_TEST(SweepTriangles, ClosestHitIsReportedWithItsIndexInFaceIndex) {
  using T = TypeParam;
  const std::vector<Triangle<T>> tris = {this->wallAt(6), this->wallAt(3), this->wallAt(4.5)};
  SweepHit<T> hit;
  bool has = false;
  ASSERT_TRUE(sweepTriangles(this->x(), T(10), Geometry<T>(SphereGeometry<T>(T(0.5))), Transform<T>(), tris.data(),
                             std::uint32_t(tris.size()), hit, has).ok());
  ASSERT_TRUE(has);
  EXPECT_NEAR(double(hit.distance), 2.5, this->kTol);
  EXPECT_EQ(hit.faceIndex, 1u);
  EXPECT_NEAR(double(hit.normal.x()), -1.0, this->kTol);
  EXPECT_NEAR(double(hit.position.x()), 3.0, this->kTol);
  EXPECT_FALSE(hit.hadInitialOverlap());
}

TYPED_TEST(SweepTriangles, BoxAndCapsuleHitAtTheirSupportDistance) {
  using T = TypeParam;
  const std::vector<Triangle<T>> tris = {this->wallAt(4)};
  SweepHit<T> hit;
  bool has = false;
  // Box half extent 0.75 along X: touches after 4 - 0.75 - 1 (start at x = 1).
  const Transform<T> start(Vec3<T>(T(1), T(0.3), T(-0.2)));
  ASSERT_TRUE(sweepTriangles(this->x(), T(10), Geometry<T>(BoxGeometry<T>(T(0.75), T(0.5), T(0.25))), start,
                             tris.data(), 1u, hit, has).ok());
  ASSERT_TRUE(has);
  EXPECT_NEAR(double(hit.distance), 2.25, this->kTol);
  // Capsule along X: half height 0.5 + radius 0.25 reach 0.75 along X as well.
  ASSERT_TRUE(sweepTriangles(this->x(), T(10), Geometry<T>(CapsuleGeometry<T>(T(0.25), T(0.5))), start, tris.data(),
                             1u, hit, has).ok());
  ASSERT_TRUE(has);
  EXPECT_NEAR(double(hit.distance), 2.25, this->kTol);
  EXPECT_LT(double(hit.normal.dot(this->x())), 0.0);
}

TYPED_TEST(SweepTriangles, BackFacesAreCulledUnlessDoubleSidedOrMeshBothSides) {
  using T = TypeParam;
  const std::vector<Triangle<T>> tris = {this->flipped(this->wallAt(3))};
  const Geometry<T> sphere(SphereGeometry<T>(T(0.5)));
  SweepHit<T> hit;
  bool has = true;
  ASSERT_TRUE(sweepTriangles(this->x(), T(10), sphere, Transform<T>(), tris.data(), 1u, hit, has).ok());
  EXPECT_FALSE(has);
  ASSERT_TRUE(sweepTriangles(this->x(), T(10), sphere, Transform<T>(), tris.data(), 1u, hit, has,
                             TriangleSweepSettings<T>{kDefaultHitFlags, nullptr, T(0), true})
                  .ok());
  ASSERT_TRUE(has);
  EXPECT_NEAR(double(hit.distance), 2.5, this->kTol);
  EXPECT_NEAR(double(hit.normal.x()), -1.0, this->kTol);  // faces against the sweep
  ASSERT_TRUE(sweepTriangles(this->x(), T(10), sphere, Transform<T>(), tris.data(), 1u, hit, has,
                             TriangleSweepSettings<T>{kDefaultHitFlags | HitFlag::MeshBothSides})
                  .ok());
  EXPECT_TRUE(has);
}

TYPED_TEST(SweepTriangles, AnyHitReturnsTheFirstHitFoundStartingWithTheCachedIndex) {
  using T = TypeParam;
  const std::vector<Triangle<T>> tris = {this->wallAt(6), this->wallAt(3), this->wallAt(4.5)};
  const Geometry<T> sphere(SphereGeometry<T>(T(0.5)));
  SweepHit<T> hit;
  bool has = false;
  const std::uint32_t cached = 2;
  ASSERT_TRUE(sweepTriangles(this->x(), T(10), sphere, Transform<T>(), tris.data(), 3u, hit, has,
                             TriangleSweepSettings<T>{kDefaultHitFlags | HitFlag::AnyHit, &cached})
                  .ok());
  ASSERT_TRUE(has);
  EXPECT_EQ(hit.faceIndex, 2u);
  EXPECT_NEAR(double(hit.distance), 4.0, this->kTol);
  // Without anyHit the cached index is only an order: the closest still wins.
  ASSERT_TRUE(sweepTriangles(this->x(), T(10), sphere, Transform<T>(), tris.data(), 3u, hit, has,
                             TriangleSweepSettings<T>{kDefaultHitFlags, &cached})
                  .ok());
  EXPECT_EQ(hit.faceIndex, 1u);
  // anyHit without a cached index: the first triangle in order that is hit.
  ASSERT_TRUE(sweepTriangles(this->x(), T(10), sphere, Transform<T>(), tris.data(), 3u, hit, has,
                             TriangleSweepSettings<T>{kDefaultHitFlags | HitFlag::AnyHit})
                  .ok());
  EXPECT_EQ(hit.faceIndex, 0u);
}

TYPED_TEST(SweepTriangles, InitialOverlapReportsZeroDistanceAndMinusDir) {
  using T = TypeParam;
  const std::vector<Triangle<T>> tris = {this->wallAt(6), this->wallAt(0.25)};
  SweepHit<T> hit;
  bool has = false;
  ASSERT_TRUE(sweepTriangles(this->x(), T(10), Geometry<T>(SphereGeometry<T>(T(0.5))), Transform<T>(), tris.data(),
                             2u, hit, has).ok());
  ASSERT_TRUE(has);
  EXPECT_TRUE(hit.hadInitialOverlap());
  EXPECT_EQ(hit.distance, T(0));
  EXPECT_EQ(hit.normal, Vec3<T>(-this->x()));
  EXPECT_EQ(hit.faceIndex, 1u);
}

TYPED_TEST(SweepTriangles, MaxDistShortOfTheTriangleMisses) {
  using T = TypeParam;
  const std::vector<Triangle<T>> tris = {this->wallAt(3)};
  SweepHit<T> hit;
  bool has = true;
  ASSERT_TRUE(sweepTriangles(this->x(), T(2.4), Geometry<T>(SphereGeometry<T>(T(0.5))), Transform<T>(), tris.data(),
                             1u, hit, has).ok());
  EXPECT_FALSE(has);
}

TYPED_TEST(SweepTriangles, InvalidInputReturnsAStatusAndWritesNothing) {
  using T = TypeParam;
  const std::vector<Triangle<T>> tris = {this->wallAt(3)};
  const Geometry<T> sphere(SphereGeometry<T>(T(0.5)));
  SweepHit<T> hit;
  hit.distance = T(42);
  bool has = true;
  const std::uint32_t badCache = 7;
  EXPECT_EQ(sweepTriangles(this->x(), T(10), sphere, Transform<T>(), tris.data(), 1u, hit, has,
                           TriangleSweepSettings<T>{kDefaultHitFlags, &badCache})
                .code,
            StatusCode::InvalidArgument);
  EXPECT_EQ(sweepTriangles(Vec3<T>(T(2), T(0), T(0)), T(10), sphere, Transform<T>(), tris.data(), 1u, hit, has).code,
            StatusCode::InvalidArgument);
  EXPECT_EQ(sweepTriangles(this->x(), T(10), sphere, Transform<T>(), tris.data(), 1u, hit, has,
                           TriangleSweepSettings<T>{kDefaultHitFlags | HitFlag::MeshMultiple})
                .code,
            StatusCode::InvalidArgument);
  EXPECT_EQ(sweepTriangles(this->x(), T(10), sphere, Transform<T>(), static_cast<const Triangle<T>*>(nullptr), 1u, hit,
                           has).code, StatusCode::InvalidArgument);
  EXPECT_EQ(sweepTriangles(this->x(), T(10), Geometry<T>(PlaneGeometry<T>()), Transform<T>(), tris.data(), 1u, hit,
                           has).code, StatusCode::Unsupported);
  EXPECT_EQ(hit.distance, T(42));
  EXPECT_TRUE(has);
}

}  // namespace
