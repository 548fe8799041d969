// computePenetration on the curved custom shapes (Cylinder, Cone) through GJK + EPA, against closed forms in long
// double, in float and double. Coaxial cylinders have an exact depth: their Minkowski difference is the coaxial
// cylinder of radius r0 + r1 and half height h0 + h1 centred at the offset s, so the depth is
// min(h0 + h1 - |s|, r0 + r1) (the nearer cap, or the side: a whole ring of closest points, the case that used to
// stop EPA with NotConverged). libccd's cylinder hard case is one of them: exact depth 0.45 (libccd's golden file:
// 0.75).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "gq/custom_shapes.h"
#include "gq/query.h"
#include "test_util.h"

namespace {

using namespace gq;
using gq::test::LD;
using gq::test::Rng;

template <class T> struct CustomPenetration : ::testing::Test {
  // The acceptance: 1e-7 for GJK/EPA pairs in double, 1e-4 in float (relative to the shapes' size ~1).
  static constexpr double kTol = std::is_same_v<T, double> ? 1e-7 : 1e-4;

  static CustomGeometry<T> cylinder(double r, double h) {
    CustomGeometry<T> c;
    EXPECT_TRUE(makeCylinder(T(r), T(h), c).ok());
    return c;
  }
  // Penetration of geom0 at the origin vs geom1 at `offset` along the shared (local X) axis, both turned by `q`.
  // Checks the depth and that the direction is along the axis (cap contact, away from geom1) or across it (side).
  static void expectCoaxial(const Geometry<T>& g0, const Geometry<T>& g1, double offset, const Quat<T>& q,
                            double capDepth, double sideDepth) {
    const Vec3<T> axis = q * Vec3<T>::UnitX();
    const Transform<T> p0(Vec3<T>::Zero(), q), p1(Vec3<T>(T(offset) * axis), q);
    PenetrationResult<T> r;
    const Status s = computePenetration(r, g0, p0, g1, p1);
    ASSERT_TRUE(s.ok()) << s.toString();
    ASSERT_TRUE(r.penetrating);
    EXPECT_NEAR(double(r.depth), std::min(capDepth, sideDepth), kTol) << "offset " << offset;
    const double along = double(r.direction.dot(axis));
    // Away from geom1 along the axis (either way at coincident centres).
    if (capDepth < sideDepth - 10 * kTol) EXPECT_NEAR(offset == 0 ? std::abs(along) : offset > 0 ? -along : along, 1.0, 10 * kTol);
    else if (sideDepth < capDepth - 10 * kTol) EXPECT_NEAR(along, 0.0, std::sqrt(kTol));
  }
};
TYPED_TEST_SUITE(CustomPenetration, gq::test::Scalars);

TYPED_TEST(CustomPenetration, LibccdCylinderPairHasTheExactDepth) {
  using T = TypeParam;
  // Radius 0.35 half-height 0.25 at the origin vs radius 0.5 half-height 0.5 at 0.3 along the shared axis.
  this->expectCoaxial(this->cylinder(0.35, 0.25), this->cylinder(0.5, 0.5), 0.3, Quat<T>::Identity(), 0.45, 0.85);
  Rng rng(601);
  for (int i = 0; i < 20; ++i)
    this->expectCoaxial(this->cylinder(0.35, 0.25), this->cylinder(0.5, 0.5), 0.3, rng.rotation<T>(), 0.45, 0.85);
}

TYPED_TEST(CustomPenetration, CoaxialCylindersMatchTheClosedFormIncludingCoincidentCentres) {
  using T = TypeParam;
  Rng rng(602);
  for (int i = 0; i < 200; ++i) {
    const double r0 = rng.uniform(0.2, 1), h0 = rng.uniform(0.2, 1), r1 = rng.uniform(0.2, 1), h1 = rng.uniform(0.2, 1);
    const double offset = i % 4 == 0 ? 0.0 : rng.uniform(-0.9, 0.9) * (h0 + h1);
    // The offset as T would see it, so that the reference answers the same question.
    const double s = double(T(offset));
    this->expectCoaxial(this->cylinder(r0, h0), this->cylinder(r1, h1), s, rng.rotation<T>(), h0 + h1 - std::abs(s),
                        r0 + r1);
  }
}

TYPED_TEST(CustomPenetration, CylinderVsSphereAndCapsuleAtCoincidentCentresConverge) {
  using T = TypeParam;
  Rng rng(603);
  for (int i = 0; i < 100; ++i) {
    const double r = rng.uniform(0.2, 1), h = rng.uniform(0.2, 1), rs = rng.uniform(0.1, 1), hc = rng.uniform(0.1, 1);
    const Quat<T> q = rng.rotation<T>();
    // Sphere: D's core is the cylinder itself, depth min(r, h) + rs. Coaxial capsule: its segment lengthens the
    // cylinder to half height h + hc, depth min(r, h + hc) + rs.
    this->expectCoaxial(Geometry<T>(SphereGeometry<T>(T(rs))), this->cylinder(r, h), 0.0, q, h + rs, r + rs);
    this->expectCoaxial(Geometry<T>(CapsuleGeometry<T>(T(rs), T(hc))), this->cylinder(r, h), 0.0, q, h + hc + rs,
                        r + rs);
    this->expectCoaxial(this->cylinder(r, h), Geometry<T>(SphereGeometry<T>(T(rs))), 0.0, q, h + rs, r + rs);
  }
}

TYPED_TEST(CustomPenetration, ConeOnItsAxisInsideASphereHasTheApexOrRimDepth) {
  using T = TypeParam;
  // A sphere of radius R centred at the cone's centre: D's core is the cone; the depth is R plus the distance from
  // the centre to the cone's boundary: min(base plane h, the slanted side h r / sqrt(r^2 + 4 h^2)) (the side's
  // distance from the axis point at the middle height: apex at +h, slope r / (2h)).
  Rng rng(604);
  for (int i = 0; i < 100; ++i) {
    const double r = rng.uniform(0.2, 1), h = rng.uniform(0.2, 1), R = rng.uniform(0.1, 1);
    CustomGeometry<T> cone;
    ASSERT_TRUE(makeCone(T(r), T(h), cone).ok());
    const LD side = LD(h) * LD(r) / std::sqrt(LD(r) * r + 4 * LD(h) * h);
    const LD depth = std::min<LD>(h, side) + R;
    PenetrationResult<T> res;
    const Status s = computePenetration(res, Geometry<T>(SphereGeometry<T>(T(R))), Transform<T>(), Geometry<T>(cone),
                                       Transform<T>(Vec3<T>::Zero(), rng.rotation<T>()));
    ASSERT_TRUE(s.ok()) << s.toString();
    EXPECT_NEAR(double(res.depth), double(depth), this->kTol) << "r " << r << " h " << h;
  }
}

}  // namespace
