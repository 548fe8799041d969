// GJK on curved support maps from a cold start: a capsule against the exact custom Cylinder, against an
// independent long-double reference (the distance from the capsule's segment to the solid cylinder is convex
// along the segment, so a ternary search over it in long double is exact to round-off).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "gq/custom_shapes.h"
#include "gq/query.h"

namespace {

using L = long double;
using VL = Eigen::Matrix<L, 3, 1>;

// Distance from a point (cylinder frame: axis X, radius r, half height h) to the solid cylinder.
L pointCylinderDistance(const VL& p, L r, L h) {
  const L dx = std::max(std::abs(p.x()) - h, L(0));
  const L dr = std::max(std::sqrt(p.y() * p.y() + p.z() * p.z()) - r, L(0));
  return std::sqrt(dx * dx + dr * dr);
}

L segmentCylinderDistance(const VL& a, const VL& b, L r, L h) {
  L lo = 0, hi = 1;
  const auto f = [&](L s) { return pointCylinderDistance(a + s * (b - a), r, h); };
  for (int i = 0; i < 200; ++i) {
    const L m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    (f(m1) <= f(m2) ? hi : lo) = f(m1) <= f(m2) ? m2 : m1;
  }
  return f((lo + hi) / 2);
}

template <class T> class GjkCurved : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(GjkCurved, Scalars);

TYPED_TEST(GjkCurved, CapsuleAgainstCylinderConvergesFromAColdStartToTheExactDistance) {
  using T = TypeParam;
  const T r = T(0.4), h = T(0.6), capR = T(0.2), capH = T(0.5);
  gq::CustomGeometry<T> cylinder;
  ASSERT_TRUE(gq::makeCylinder<T>(r, h, cylinder).ok());
  const gq::Geometry<T> cyl = cylinder, cap = gq::CapsuleGeometry<T>(capR, capH);
  const T tolerance = std::is_same_v<T, float> ? T(1e-4) : T(1e-7);
  std::mt19937_64 gen(17);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  std::normal_distribution<double> n;
  // One draw per declarator: argument evaluation order is unspecified (GCC and clang differ).
  const auto randomPose = [&] {
    const T x = T(u(gen)), y = T(u(gen)), z = T(u(gen));
    const T w = T(n(gen)), qx = T(n(gen)), qy = T(n(gen)), qz = T(n(gen));
    return gq::Transform<T>(gq::Vec3<T>(x, y, z), gq::Quat<T>(w, qx, qy, qz).normalized());
  };
  int separated = 0;
  for (int i = 0; i < 2000; ++i) {
    const gq::Transform<T> p0 = randomPose(), p1 = randomPose();
    // The capsule's segment in the cylinder's frame, in long double.
    const auto toCylinder = [&](T x) {
      const gq::Vec3<T> world = p1.transform(gq::Vec3<T>(x, 0, 0));
      const Eigen::Quaternion<L> q = p0.q.template cast<L>();
      return VL(q.conjugate() * (world.template cast<L>() - p0.p.template cast<L>()));
    };
    const L exact = segmentCylinderDistance(toCylinder(-capH), toCylinder(capH), L(r), L(h)) - L(capR);
    if (exact <= L(1e-3)) continue;  // separated pairs: the distance is GJK's answer, not EPA's
    ++separated;
    gq::DistanceResult<T> d;
    const gq::Status s = gq::distance(d, cap, p1, cyl, p0);
    // Ok, or a Warning when rounding stalls GJK with a certified error bound just above its tolerance.
    ASSERT_TRUE(s.ok()) << "pose " << i << ": " << s.toString();
    EXPECT_NEAR(double(d.distance), double(exact), double(tolerance)) << "pose " << i;
    bool hit = true;
    ASSERT_TRUE(gq::overlap(cap, p1, cyl, p0, hit).ok());
    EXPECT_FALSE(hit) << "pose " << i << " is apart by " << double(exact);
  }
  EXPECT_GT(separated, 500);
}

}  // namespace
