// GJK and EPA at every length scale T can hold (gjk/pair_scale.h): their face tests square cross products of edges,
// |e|^4, which overflowed float for pairs ~1e9+ across and underflowed below ~1e-9.5 (1e77 and 1e-77 in double).
// The façade bounds sizes and offsets (1e9 in float, 1e75 in double), but not a custom shape's own extent: a point
// inside a float custom cone 3e10 wide was "1.7e8 apart" (a fuzz finding). Two checks:
//  - exact: a small sphere inside a custom cone, near its base, has the closed-form depth (base distance + radius),
//    for cones from 2^-40 to 2^36 wide in float and 2^-400 to 2^300 in double (the large ones flat, so that the
//    sphere's offset from the cone stays within the façade's bound, as in the finding);
//  - scaling: a pair whose every length is multiplied by a power of two (exact in T) answers overlap, penetration and
//    distance as the unit pair does, times that power (sphere-cone, box-cylinder, hull-hull), from 2^-40 to 2^24 in
//    float and 2^-400 to 2^240 in double.
#include "gjk_test_shapes.h"

#include "gjk/gjk.h"
#include "gq/custom_shapes.h"

namespace {

using namespace gjktest;
using gq::Transform;
using gq::Vec3;

// Scales for whole pairs, within the façade's bounds on sizes and offsets.
template <class T> std::vector<int> exponents() {
  if constexpr (std::is_same_v<T, float>) return {-40, -24, 0, 16, 24};
  else return {-400, -200, 0, 200, 240};
}

// Cones (radius, half-height) as powers of two: proportional ones at small scales, flat wide ones at large.
template <class T> std::vector<std::pair<int, int>> coneExponents() {
  if constexpr (std::is_same_v<T, float>) return {{-40, -41}, {-24, -25}, {1, 0}, {30, 28}, {34, 28}, {36, 29}};
  else return {{-400, -401}, {-200, -201}, {1, 0}, {250, 240}, {260, 240}, {300, 248}};
}

// Penetration of a point at local (x, rho) inside a cone along X (base disk of radius R at x = -H, apex at x = H):
// the base plane at x + H, the lateral line through (H, 0) and (-H, R) at (R (H - x) - 2 H rho) / sqrt(4 H^2 + R^2).
struct ConeDepth {
  L base, lateral;
};
ConeDepth coneDepth(L x, L rho, L radius, L halfHeight) {
  return {x + halfHeight, (radius * (halfHeight - x) - 2 * halfHeight * rho) / std::sqrt(4 * halfHeight * halfHeight +
                                                                                           radius * radius)};
}

template <class T> class GjkPairScale : public ::testing::Test {};
TYPED_TEST_SUITE(GjkPairScale, Scalars);

TYPED_TEST(GjkPairScale, SphereInsideAConeNearItsBaseHasTheExactDepthAtEveryScale) {
  using T = TypeParam;
  Rng rng(20261124);
  for (const auto [re, he] : coneExponents<T>()) {
    const T radius = std::ldexp(T(1), re), halfHeight = std::ldexp(T(1), he), sphere = halfHeight / T(16);
    const gq::Geometry<T> cone = gq::CustomGeometry<T>(std::make_shared<gq::ConeCallbacks<T>>(radius, halfHeight));
    const gq::Geometry<T> ball = gq::SphereGeometry<T>(sphere);
    for (int trial = 0; trial < 20; ++trial) {
      // Near the base, well inside the lateral surface: the base is the closest face (a flat one, exact for EPA).
      // Within 1.5 half-heights of the cone's centre (the façade's offset bound).
      const T x = T(rng.uniform(-0.8, -0.6)) * halfHeight;
      const T rho = T(rng.uniform(0, 0.3)) * std::min(radius, T(4) * halfHeight);
      const double phi = rng.uniform(0, 2 * M_PI);
      const Transform<T> pc(Vec3<T>(rng.vec(-1, 1).cast<T>() * halfHeight), rng.rotation().cast<T>());
      const Vec3<T> local(x, T(double(rho) * std::cos(phi)), T(double(rho) * std::sin(phi)));
      const Transform<T> ps(pc.transform(local), Eigen::Quaternion<T>::Identity());
      // The exact depth of the stored centre (its local coordinates recomputed in long double).
      const VL q = (pc.q.template cast<L>().toRotationMatrix().transpose() * (toL(ps.p) - toL(pc.p)));
      const ConeDepth d = coneDepth(q.x(), std::hypot(q.y(), q.z()), L(radius), L(halfHeight));
      ASSERT_GT(d.lateral, L(1.5) * d.base);
      const double exact = double(d.base + L(sphere));
      SCOPED_TRACE(testing::Message() << "cone 2^" << re << " by 2^" << he << " trial " << trial << " exact " << exact);
      // GJK/EPA's tolerance is relative to the pair's size (the radius); the cone's rotation alone rounds its
      // points by ~eps of it.
      const double tol = (std::is_same_v<T, float> ? 1e-4 : 1e-9) * double(radius);
      bool overlapping = false;
      ASSERT_TRUE(gq::overlap(ball, ps, cone, pc, overlapping).ok());
      EXPECT_TRUE(overlapping);
      gq::PenetrationResult<T> pen;
      ASSERT_TRUE(gq::computePenetration(pen, ball, ps, cone, pc).ok());
      EXPECT_TRUE(pen.penetrating);
      EXPECT_NEAR(double(pen.depth), exact, tol);
      EXPECT_NEAR(double(pen.direction.dot(pc.q * Vec3<T>::UnitX())), -1.0, 1e-4);  // push the cone along its axis
      gq::DistanceResult<T> dist;
      ASSERT_TRUE(gq::distance(dist, ball, ps, cone, pc).ok());
      EXPECT_NEAR(double(dist.distance), -exact, tol);
    }
  }
}

// One pair at unit scale times s (every length: sizes, positions, hull scale).
template <class T> struct ScaledPair {
  gq::Geometry<T> a, b;
  Transform<T> pa, pb;
};

template <class T> ScaledPair<T> scaledPair(int kind, const Transform<T>& pa, const Transform<T>& pb, T s,
                                            const std::shared_ptr<const gq::ConvexMesh<T>>& hull) {
  const Transform<T> qa(Vec3<T>(pa.p * s), pa.q), qb(Vec3<T>(pb.p * s), pb.q);
  switch (kind) {
    case 0:
      return {gq::SphereGeometry<T>(T(0.75) * s),
              gq::CustomGeometry<T>(std::make_shared<gq::ConeCallbacks<T>>(T(2) * s, T(1.5) * s)), qa, qb};
    case 1:
      return {gq::BoxGeometry<T>(Vec3<T>(T(0.5), T(0.375), T(0.25)) * s),
              gq::CustomGeometry<T>(std::make_shared<gq::CylinderCallbacks<T>>(T(0.75) * s, T(1.25) * s)), qa, qb};
    default:
      return {gq::ConvexMeshGeometry<T>(hull, gq::MeshScale<T>(Vec3<T>::Constant(s))),
              gq::ConvexMeshGeometry<T>(hull, gq::MeshScale<T>(Vec3<T>(s, T(0.5) * s, T(2) * s))), qa, qb};
  }
}

struct Answers {
  bool overlapping = false, penetrating = false;
  double depth = 0, distance = 0;
  Eigen::Vector3d direction, normal;
};

template <class T> Answers answers(const ScaledPair<T>& p) {
  Answers r;
  EXPECT_TRUE(gq::overlap(p.a, p.pa, p.b, p.pb, r.overlapping).ok());
  gq::PenetrationResult<T> pen;
  EXPECT_TRUE(gq::computePenetration(pen, p.a, p.pa, p.b, p.pb).ok());
  r.penetrating = pen.penetrating;
  r.depth = double(pen.depth);
  r.direction = pen.direction.template cast<double>();
  gq::DistanceResult<T> d;
  EXPECT_TRUE(gq::distance(d, p.a, p.pa, p.b, p.pb).ok());
  r.distance = double(d.distance);
  r.normal = d.normal.template cast<double>();
  return r;
}

TYPED_TEST(GjkPairScale, APairScaledByAPowerOfTwoAnswersTheScaledAnswer) {
  using T = TypeParam;
  Rng rng(1124);
  std::vector<Vec3<T>> points;
  for (int k = 0; k < 14; ++k) points.push_back(rng.unit().cast<T>());
  const auto hull = makeHull<T>(points);
  ASSERT_TRUE(hull);
  const double rel = std::is_same_v<T, float> ? 2e-4 : 1e-9;
  for (int kind = 0; kind < 3; ++kind) {
    for (int trial = 0; trial < 25; ++trial) {
      const Transform<T> pa(rng.vec(-1.5, 1.5).cast<T>(), rng.rotation().cast<T>());
      const Transform<T> pb(rng.vec(-1.5, 1.5).cast<T>(), rng.rotation().cast<T>());
      const Answers unit = answers(scaledPair<T>(kind, pa, pb, T(1), hull));
      // Poses whose answer sits on the boundary of touching could flip by rounding: not this test's subject.
      if (std::abs(unit.distance) < 1e-2) continue;
      for (const int e : exponents<T>()) {
        const double s = std::ldexp(1.0, e);
        SCOPED_TRACE(testing::Message() << "kind " << kind << " trial " << trial << " scale 2^" << e
                                        << " unit distance " << unit.distance);
        const Answers scaled = answers(scaledPair<T>(kind, pa, pb, T(s), hull));
        EXPECT_EQ(scaled.overlapping, unit.overlapping);
        EXPECT_EQ(scaled.penetrating, unit.penetrating);
        EXPECT_NEAR(scaled.depth / s, unit.depth, rel * (1 + unit.depth));
        EXPECT_NEAR(scaled.distance / s, unit.distance, rel * (1 + std::abs(unit.distance)));
        if (unit.penetrating) EXPECT_GT(scaled.direction.dot(unit.direction), 1 - 1e-3);
        EXPECT_GT(scaled.normal.dot(unit.normal), 1 - 1e-3);
      }
    }
  }
}

}  // namespace

namespace {

// A float custom shape wider than 2e19 has a squared bounding radius past FLT_MAX: its GJK size was inf, so a pair's
// tolerance was inf and a sphere inside "overlapped" at once, 0 deep (the fuzz finding, replayed in
// FuzzPairFindings: a sphere inside a cylinder 1e30 wide answered its own radius, 5.3, for a depth of 1e30). The
// size is the bounding radius, sqrt(h^2 + 2 r^2) for a cylinder (long double here).
TEST(GjkPairScale, FloatCustomShapesBeyond1e19HaveAFiniteSize) {
  using T = float;
  for (const T radius : {1e10f, 1e18f, 1e20f, 1e25f, 1e30f, 1e38f}) {
    const T halfHeight = radius / 4;
    const gq::Geometry<T> cylinder =
        gq::CustomGeometry<T>(std::make_shared<gq::CylinderCallbacks<T>>(radius, halfHeight));
    const gq::Geometry<T> cone = gq::CustomGeometry<T>(std::make_shared<gq::ConeCallbacks<T>>(radius, halfHeight));
    const L exact = std::sqrt(L(halfHeight) * L(halfHeight) + 2 * L(radius) * L(radius));
    for (const auto* g : {&cylinder, &cone}) {
      const T size = gq::detail::makeConvexShape(*g, Transform<T>()).size;
      EXPECT_NEAR(double(size / exact), 1.0, 1e-6) << "radius " << radius;
    }
  }
}

}  // namespace
