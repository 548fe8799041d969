// Sphere/cylinder closed forms. Overlap (overlap/sphere_cylinder.cpp, which the Cylinder's overlap callback answers
// with): the boolean is the sign of GJK's certified distance outside a thin band, and a sphere tangent to the cap,
// the side or the rim touches (overlaps) while 1e-3 farther out it does not. Distance (distance.h; the inside case
// in distance/sphere_cylinder.cpp; the FCL adapter's): GJK's certified answer when apart, EPA's when the centre is
// outside the cylinder but the sphere overlaps it, and radius + the least room to the cap or side when the centre is
// inside.
#include "gjk_test_shapes.h"

#include "gq/custom_shapes.h"
#include "distance/distance.h"
#include "overlap/overlap.h"

namespace {

using namespace gjktest;

template <class T> class SphereCylinderOverlap : public ::testing::Test {};
TYPED_TEST_SUITE(SphereCylinderOverlap, Scalars);

TYPED_TEST(SphereCylinderOverlap, ClosedFormIsTheSignOfGjksDistance) {
  using T = TypeParam;
  Rng rng(1702);
  const double band = std::is_same_v<T, float> ? 1e-4 : 1e-9;
  int overlapping = 0, apart = 0;
  for (int i = 0; i < 3000; ++i) {
    const T radius = T(rng.uniform(0.1, 1.0));
    const T halfHeight = T(rng.uniform(0.05, 1.5));
    const T sphereRadius = T(rng.uniform(0.05, 1.0));
    const gq::Transform<T> cyl = randomPose<T>(rng, 1.0);
    const gq::Transform<T> sph = randomPose<T>(rng, 1.0);
    gq::CustomGeometry<T> c;
    ASSERT_TRUE(gq::makeCylinder(radius, halfHeight, c).ok());
    const gq::Geometry<T> gc{c}, gs{gq::SphereGeometry<T>(sphereRadius)};
    gq::DistanceResult<T> d;
    ASSERT_TRUE(gq::distance(d, gc, cyl, gs, sph).ok());  // GJK (EPA when overlapping)
    if (std::abs(double(d.distance)) < band) continue;
    bool facade = false;
    ASSERT_TRUE(gq::overlap(gs, sph, gc, cyl, facade).ok());
    const bool closedForm =
        gq::detail::overlapSphereCylinder<T>(cyl.transformInv(sph.p), sphereRadius, radius, halfHeight);
    ASSERT_EQ(closedForm, d.distance < T(0)) << "pose " << i << ", GJK distance " << d.distance;
    ASSERT_EQ(facade, closedForm) << "pose " << i;
    (closedForm ? overlapping : apart)++;
  }
  EXPECT_GT(overlapping, 500);
  EXPECT_GT(apart, 500);
}

TYPED_TEST(SphereCylinderOverlap, TangentSpheresTouchAndFartherOnesDoNot) {
  using T = TypeParam;
  const T radius = T(0.5), halfHeight = T(0.75), sphereRadius = T(0.25);
  const T s = T(std::sqrt(0.5));
  const gq::Vec3<T> outward[] = {gq::Vec3<T>::UnitX(), gq::Vec3<T>::UnitY(), gq::Vec3<T>(s, s, T(0))};
  const gq::Vec3<T> feature[] = {gq::Vec3<T>(halfHeight, T(0.1), T(0)), gq::Vec3<T>(T(0.2), radius, T(0)),
                                 gq::Vec3<T>(halfHeight, radius, T(0))};  // on the cap, the side, the rim
  for (int k = 0; k < 3; ++k) {
    const auto overlapsAt = [&](T gap) {
      return gq::detail::overlapSphereCylinder<T>(feature[k] + (sphereRadius + gap) * outward[k], sphereRadius, radius,
                                                  halfHeight);
    };
    EXPECT_TRUE(overlapsAt(T(0)) || k == 2) << "feature " << k;  // the rim's diagonal is not exact in binary
    EXPECT_TRUE(overlapsAt(T(-1e-3))) << "feature " << k;
    EXPECT_FALSE(overlapsAt(T(1e-3))) << "feature " << k;
  }
}

TYPED_TEST(SphereCylinderOverlap, DistanceClosedFormIsGjksAnswerAndTheExitThroughTheNearestFeature) {
  using T = TypeParam;
  Rng rng(1703);
  const double tol = std::is_same_v<T, float> ? 2e-4 : 1e-8;
  const T radius = T(0.6), halfHeight = T(0.9), sphereRadius = T(0.3);
  gq::CustomGeometry<T> c;
  ASSERT_TRUE(gq::makeCylinder(radius, halfHeight, c).ok());
  const gq::Geometry<T> gc{c}, gs{gq::SphereGeometry<T>(sphereRadius)};
  int apart = 0, inside = 0;
  for (int i = 0; i < 2000; ++i) {
    const gq::Vec3<T> centre = rng.vec(-1.6, 1.6).cast<T>();  // in the cylinder's frame (pose: identity)
    gq::DistanceResult<T> got;
    gq::detail::distanceSphereCylinder<T>(centre, sphereRadius, radius, halfHeight, got);
    const double rho = std::hypot(double(centre.y()), double(centre.z()));
    const double axialRoom = double(halfHeight) - std::abs(double(centre.x())), radialRoom = double(radius) - rho;
    if (axialRoom >= 0 && radialRoom >= 0) {  // centre inside: out through the nearer of cap and side
      ++inside;
      ASSERT_NEAR(double(got.distance), -(std::min(axialRoom, radialRoom) + double(sphereRadius)), tol) << i;
      ASSERT_NEAR(double((got.point1 - got.point0).dot(got.normal)), double(got.distance), tol) << i;
      continue;
    }
    gq::DistanceResult<T> ref;
    ASSERT_TRUE(gq::distance(ref, gs, gq::Transform<T>(centre), gc, gq::Transform<T>()).ok());
    const bool separated = ref.distance > T(0);
    const double t = separated ? tol : (std::is_same_v<T, float> ? 1e-3 : 1e-6);  // EPA when overlapping
    ASSERT_NEAR(double(got.distance), double(ref.distance), t) << "centre " << centre.transpose();
    ASSERT_NEAR(double((got.normal - ref.normal).norm()), 0.0, 10 * t) << "centre " << centre.transpose();
    ASSERT_NEAR(double((got.point0 - ref.point0).norm()), 0.0, 10 * t) << "centre " << centre.transpose();
    ASSERT_NEAR(double((got.point1 - ref.point1).norm()), 0.0, 10 * t) << "centre " << centre.transpose();
    apart += separated;
  }
  EXPECT_GT(apart, 500);
  EXPECT_GT(inside, 100);
}

}  // namespace
