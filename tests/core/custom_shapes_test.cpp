// Cylinder and Cone custom shapes: exact raycasts and bounds against closed forms, in float and double. Rays are
// built in the shape's frame along a coordinate axis, where the entry point has a closed form, then moved by a
// seeded random pose (distances and normals are invariant).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "gq/custom_shapes.h"
#include "gq/query.h"

namespace {

using namespace gq;

template <class T> struct CustomShapes : ::testing::Test {
  static constexpr double kTol = std::is_same_v<T, double> ? 1e-9 : 5e-5;
  static Transform<T> randomPose(std::mt19937_64& gen) {
    std::normal_distribution<double> n;
    std::uniform_real_distribution<double> u(-3, 3);
    // One draw per declarator: argument evaluation order is unspecified (GCC and clang differ).
    const double w = n(gen), qx = n(gen), qy = n(gen), qz = n(gen);
    const double x = u(gen), y = u(gen), z = u(gen);
    return Transform<T>(Vec3<T>(T(x), T(y), T(z)), Eigen::Quaterniond(w, qx, qy, qz).normalized().cast<T>());
  }
  // Fires the local ray (origin, dir) at `geom` posed by `pose`; expects the hit at `distance` with local `normal`.
  static void expectHit(const Geometry<T>& geom, const Transform<T>& pose, const Eigen::Vector3d& origin,
                        const Eigen::Vector3d& dir, double distance, const Eigen::Vector3d& normal) {
    RaycastHit<T> hit;
    std::uint32_t count = 0;
    const Vec3<T> o = pose.transform(origin.cast<T>()), d = pose.rotate(dir.cast<T>());
    ASSERT_TRUE(raycast(o, d, geom, pose, T(100), kDefaultHitFlags, 1u, &hit, count).ok());
    ASSERT_EQ(count, 1u) << "origin " << origin.transpose();
    EXPECT_NEAR(double(hit.distance), distance, kTol * 10);
    const Eigen::Vector3d worldNormal = pose.rotate(normal.cast<T>()).template cast<double>();
    EXPECT_NEAR((hit.normal.template cast<double>() - worldNormal).norm(), 0.0, kTol * 10);
    EXPECT_NEAR((hit.position.template cast<double>() - (o + hit.distance * d).template cast<double>()).norm(), 0.0,
                kTol * 10);
  }
};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(CustomShapes, Scalars);

TYPED_TEST(CustomShapes, CylinderRaycastHitsCapAndSideAtTheClosedForm) {
  using T = TypeParam;
  const double r = 0.8, h = 1.3;
  CustomGeometry<T> cyl;
  ASSERT_TRUE(makeCylinder(T(r), T(h), cyl).ok());
  std::mt19937_64 gen(11);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 50; ++i) {
    const Transform<T> pose = this->randomPose(gen);
    // Along -X onto the cap x = h, from (5, y, z) with y^2 + z^2 < r^2.
    const double y = 0.5 * r * u(gen), z = 0.5 * r * u(gen);
    this->expectHit(cyl, pose, {5, y, z}, {-1, 0, 0}, 5 - h, {1, 0, 0});
    // Along -Y onto the side, from (x, 5, z) with |x| < h, |z| < r: enters at y = sqrt(r^2 - z^2).
    const double x = 0.9 * h * u(gen), zs = 0.9 * r * u(gen), ys = std::sqrt(r * r - zs * zs);
    this->expectHit(cyl, pose, {x, 5, zs}, {0, -1, 0}, 5 - ys, Eigen::Vector3d(0, ys, zs) / r);
  }
}

TYPED_TEST(CustomShapes, ConeRaycastHitsBaseSideAndApexAtTheClosedForm) {
  using T = TypeParam;
  const double r = 0.9, h = 1.1, k = r / (2 * h);
  CustomGeometry<T> cone;
  ASSERT_TRUE(makeCone(T(r), T(h), cone).ok());
  std::mt19937_64 gen(12);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 50; ++i) {
    const Transform<T> pose = this->randomPose(gen);
    // Along +X onto the base x = -h.
    const double y = 0.5 * r * u(gen), z = 0.5 * r * u(gen);
    this->expectHit(cone, pose, {-5, y, z}, {1, 0, 0}, 5 - h, {-1, 0, 0});
    // Along -Y onto the side at height x: the section is a disk of radius rx = k (h - x); enters at
    // y = sqrt(rx^2 - z^2), where the outward normal is (k rx, y, z) normalised (gradient of y^2+z^2 - k^2 (h-x)^2).
    const double x = 0.9 * h * u(gen), rx = k * (h - x), zs = 0.9 * rx * u(gen), ys = std::sqrt(rx * rx - zs * zs);
    this->expectHit(cone, pose, {x, 5, zs}, {0, -1, 0}, 5 - ys, Eigen::Vector3d(k * rx, ys, zs).normalized());
  }
  // Along -X on the axis: the apex at x = h, a double root of the side's quadratic. The discriminant is evaluated
  // without cancellation (exactly 0 here), so the apex is as accurate as any other hit: a few ulps of the distance.
  RaycastHit<T> hit;
  std::uint32_t count = 0;
  ASSERT_TRUE(raycast(Vec3<T>(T(5), T(0), T(0)), Vec3<T>(T(-1), T(0), T(0)), Geometry<T>(cone), Transform<T>(), T(100),
                      HitFlags(), 1u, &hit, count).ok());
  ASSERT_EQ(count, 1u);
  const double apexTol = std::is_same_v<T, double> ? 1e-12 : 2e-6;
  EXPECT_NEAR(double(hit.distance), 5 - h, apexTol);
  // Parallel to the axis just off it: enters the side where the section radius k (h - x) equals the offset.
  for (const double offset : {1e-2, 1e-3, 1e-4}) {
    ASSERT_TRUE(raycast(Vec3<T>(T(5), T(offset), T(0)), Vec3<T>(T(-1), T(0), T(0)), Geometry<T>(cone), Transform<T>(),
                        T(100), HitFlags(), 1u, &hit, count).ok());
    ASSERT_EQ(count, 1u);
    EXPECT_NEAR(double(hit.distance), 5 - (h - offset / k), apexTol * 10) << "offset " << offset;
  }
}

TYPED_TEST(CustomShapes, RaysPastTheShapesMiss) {
  using T = TypeParam;
  CustomGeometry<T> cyl, cone;
  ASSERT_TRUE(makeCylinder(T(1), T(1), cyl).ok());
  ASSERT_TRUE(makeCone(T(1), T(1), cone).ok());
  RaycastHit<T> hit;
  std::uint32_t count = 1;
  // Parallel to the axis just outside the cylinder's radius.
  ASSERT_TRUE(raycast(Vec3<T>(T(5), T(1.01), T(0)), Vec3<T>(T(-1), T(0), T(0)), Geometry<T>(cyl), Transform<T>(), T(100),
                      kDefaultHitFlags, 1u, &hit, count).ok());
  EXPECT_EQ(count, 0u);
  // Across the cone above its slanted side: at x = 0.5 the section radius is 0.25.
  ASSERT_TRUE(raycast(Vec3<T>(T(0.5), T(5), T(0.3)), Vec3<T>(T(0), T(-1), T(0)), Geometry<T>(cone), Transform<T>(),
                      T(100), kDefaultHitFlags, 1u, &hit, count).ok());
  EXPECT_EQ(count, 0u);
}

TYPED_TEST(CustomShapes, BoundsMatchTheClosedForm) {
  using T = TypeParam;
  CustomGeometry<T> cyl, cone;
  ASSERT_TRUE(makeCylinder(T(0.5), T(2), cyl).ok());
  ASSERT_TRUE(makeCone(T(0.5), T(2), cone).ok());
  Bounds3<T> b;
  // Axis along world Y after a quarter turn about Z: extents (r, h, r) around the position.
  const Transform<T> pose(Vec3<T>(T(1), T(2), T(3)), Quat<T>(Eigen::AngleAxis<T>(T(M_PI / 2), Vec3<T>::UnitZ())));
  for (const Geometry<T>& g : {Geometry<T>(cyl), Geometry<T>(cone)}) {
    ASSERT_TRUE(computeGeomBounds(b, g, pose, T(0), T(1)).ok());
    EXPECT_NEAR(double(b.min.x()), 0.5, this->kTol);
    EXPECT_NEAR(double(b.max.x()), 1.5, this->kTol);
    EXPECT_NEAR(double(b.min.y()), 0.0, this->kTol);
    EXPECT_NEAR(double(b.max.y()), 4.0, this->kTol);
    EXPECT_NEAR(double(b.min.z()), 2.5, this->kTol);
    EXPECT_NEAR(double(b.max.z()), 3.5, this->kTol);
  }
  EXPECT_EQ(makeCylinder(T(-1), T(1), cyl).code, StatusCode::InvalidArgument);
  EXPECT_EQ(makeCone(T(1), std::numeric_limits<T>::quiet_NaN(), cone).code, StatusCode::InvalidArgument);
}

}  // namespace
