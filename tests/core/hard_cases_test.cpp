// The hard cases (docs/accuracy.md), each with its exact answer computed here in closed form (long double where the
// arithmetic matters): touching at tiny gaps, contained boxes (FCL bugs fcl#628 and fcl#545), coincident centres,
// R vs R*Rz(pi), extreme size ratios, poses far from the origin, parallel and zero-length capsules, paper-thin
// boxes.
#include <gtest/gtest.h>

#include <cmath>

#include "gq/query.h"
#include "overlap_test_support.h"

namespace gq::test {
namespace {

template <class T> class HardCases : public ::testing::Test {};
TYPED_TEST_SUITE(HardCases, Scalars);

template <class T> double eps() { return double(std::numeric_limits<T>::epsilon()); }

// Exact MTD of two axis-aligned boxes (centres c, half extents h), moving box 0: per axis the smaller push-out.
struct AxisPush {
  LD depth;
  int axis;
  int sign;
};
AxisPush alignedBoxPush(const Vec3L& c0, const Vec3L& h0, const Vec3L& c1, const Vec3L& h1) {
  AxisPush best{std::numeric_limits<LD>::infinity(), 0, 1};
  for (int i = 0; i < 3; ++i) {
    const LD up = (c1[i] + h1[i]) - (c0[i] - h0[i]), down = (c0[i] + h0[i]) - (c1[i] - h1[i]);
    if (up < best.depth) best = {up, i, 1};
    if (down < best.depth) best = {down, i, -1};
  }
  return best;
}

template <class T> void expectAxisDirection(const Vec3<T>& dir, int axis, int sign, double tol) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(double(dir[i]), i == axis ? double(sign) : 0.0, tol) << "component " << i;
}

TYPED_TEST(HardCases, TouchingAtRelativeGapsGivesTheRightBoolean) {
  using T = TypeParam;
  const Geometry<T> box = BoxGeometry<T>(1, 1, 1), sphere = SphereGeometry<T>(1), cap = CapsuleGeometry<T>(1, 1);
  const Geometry<T> hull = ConvexMeshGeometry<T>(boxHull<T>(Vec3<T>(1, 1, 1)));
  for (double g : {1e-12, 1e-9, 1e-6, 1e-3}) {
    for (int sign : {-1, 1}) {
      // Contact of unit shapes at x = 2: the position as stored in T decides the true gap.
      const T x = T(2.0 + sign * g);
      const LD gap = LD(x) - 2;
      const bool expected = gap <= 0;
      const Transform<T> at(Vec3<T>(x, 0, 0));
      SCOPED_TRACE(testing::Message() << "gap " << double(gap));
      EXPECT_EQ(overlaps<T>(sphere, Transform<T>(), sphere, at), expected);
      EXPECT_EQ(overlaps<T>(box, Transform<T>(), box, at), expected);
      EXPECT_EQ(overlaps<T>(sphere, Transform<T>(), box, at), expected);
      EXPECT_EQ(overlaps<T>(hull, Transform<T>(), hull, at), expected);
      EXPECT_EQ(overlaps<T>(box, Transform<T>(), hull, at), expected);
      EXPECT_EQ(overlaps<T>(cap, Transform<T>(), cap, Transform<T>(Vec3<T>(0, x, 0))), expected);
      const T c = T(1.0 + sign * g);  // unit sphere above the plane x = 0
      EXPECT_EQ(overlaps<T>(PlaneGeometry<T>(), Transform<T>(), sphere, Transform<T>(Vec3<T>(c, 0, 0))), LD(c) - 1 <= 0);
      for (const Geometry<T>* g0 : {&sphere, &box, &hull}) {
        const PenetrationResult<T> r = penetration<T>(*g0, Transform<T>(), box, at);
        ASSERT_EQ(r.penetrating, expected);
        if (r.penetrating) {
          EXPECT_NEAR(double(r.depth), double(-gap), 4 * eps<T>());
          expectAxisDirection<T>(r.direction, 0, -1, 4 * eps<T>());
        }
      }
    }
  }
}

TYPED_TEST(HardCases, BoxContainedInBoxPushesOutThroughNearestFace) {
  using T = TypeParam;
  // FCL bug fcl#628 reports 1.0 or 0 here; the exact answer is the smallest face-to-face push-out.
  const Vec3<T> h0(0.2, 0.3, 0.1), c0(0.1, -0.2, 0.3), h1(1, 1, 1);
  const AxisPush want = alignedBoxPush(toLD(c0), toLD(h0), Vec3L::Zero(), toLD(h1));
  ASSERT_NEAR(double(want.depth), 0.8, 1e-7);
  const auto r = penetration<T>(BoxGeometry<T>(h0), Transform<T>(c0), BoxGeometry<T>(h1), Transform<T>());
  ASSERT_TRUE(r.penetrating);
  EXPECT_NEAR(double(r.depth), double(want.depth), 8 * eps<T>());
  expectAxisDirection<T>(r.direction, want.axis, want.sign, 8 * eps<T>());
  // The same configuration under a common rotation: same depth, rotated direction.
  Rng rng(628);
  for (int i = 0; i < 20; ++i) {
    const Quat<T> q = rng.rotation<T>();
    const Vec3<T> t = rng.inBox<T>(3);
    const auto s = penetration<T>(BoxGeometry<T>(h0), Transform<T>(Vec3<T>(q * c0 + t), q), BoxGeometry<T>(h1), Transform<T>(t, q));
    ASSERT_TRUE(s.penetrating);
    EXPECT_NEAR(double(s.depth), double(want.depth), 64 * eps<T>());
    const Vec3<T> local = q.conjugate() * s.direction;
    expectAxisDirection<T>(local, want.axis, want.sign, 64 * eps<T>());
  }
}

TYPED_TEST(HardCases, SmallCubeInsideUnitCubeIsNotOverestimated) {
  using T = TypeParam;
  // FCL bug fcl#545 reports sqrt(3) times the true depth. Cube of half 0.1 at (0.4,0.4,0.4) in the cube of half 0.5.
  for (bool asHull : {false, true}) {
    const Geometry<T> small = asHull ? Geometry<T>(ConvexMeshGeometry<T>(boxHull<T>(Vec3<T>::Constant(T(0.1)))))
                                     : Geometry<T>(BoxGeometry<T>(0.1, 0.1, 0.1));
    const auto r = penetration<T>(small, Transform<T>(Vec3<T>(0.4, 0.4, 0.4)), BoxGeometry<T>(0.5, 0.5, 0.5), Transform<T>());
    ASSERT_TRUE(r.penetrating);
    const AxisPush want = alignedBoxPush(Vec3L::Constant(LD(T(0.4))), Vec3L::Constant(LD(T(0.1))), Vec3L::Zero(),
                                         Vec3L::Constant(LD(T(0.5))));
    EXPECT_NEAR(double(r.depth), double(want.depth), 8 * eps<T>());  // 0.2, not 0.2*sqrt(3)
    EXPECT_NEAR(double(r.direction.cwiseAbs().maxCoeff()), 1.0, 8 * eps<T>());
    EXPECT_NEAR(double(r.direction.sum()), 1.0, 8 * eps<T>());  // +X, +Y or +Z
  }
}

TYPED_TEST(HardCases, CoincidentCentresGiveAValidDirection) {
  using T = TypeParam;
  const Transform<T> pose(Vec3<T>(0.3, -0.7, 2), Quat<T>(Eigen::AngleAxis<T>(T(0.4), Vec3<T>(1, 2, 3).normalized())));
  struct Case {
    Geometry<T> g0, g1;
    double depth;
  };
  const std::vector<Case> cases = {
      {SphereGeometry<T>(1), SphereGeometry<T>(T(0.5)), 1.5},
      {SphereGeometry<T>(1), CapsuleGeometry<T>(T(0.5), 2), 1.5},
      {CapsuleGeometry<T>(1, 1), CapsuleGeometry<T>(T(0.5), 2), 1.5},  // colinear axes: push perpendicular
      {SphereGeometry<T>(1), BoxGeometry<T>(T(0.5), 2, 3), 1.5},
      {BoxGeometry<T>(1, 2, 3), BoxGeometry<T>(T(0.5), 2, 3), 1.5},
      {ConvexMeshGeometry<T>(boxHull<T>(Vec3<T>(1, 2, 3))), BoxGeometry<T>(T(0.5), 2, 3), 1.5},
      {ConvexMeshGeometry<T>(octahedronHull<T>(1)), ConvexMeshGeometry<T>(octahedronHull<T>(2)), 3 / std::sqrt(3.0)},
      {SphereGeometry<T>(1), ConvexMeshGeometry<T>(octahedronHull<T>(1)), 1 + 1 / std::sqrt(3.0)},
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    SCOPED_TRACE(testing::Message() << "case " << i);
    const auto r = penetration<T>(cases[i].g0, pose, cases[i].g1, pose);
    ASSERT_TRUE(r.penetrating);
    EXPECT_TRUE(std::isfinite(double(r.depth)));
    EXPECT_NEAR(double(r.direction.norm()), 1.0, 16 * eps<T>());
    EXPECT_NEAR(double(r.depth), cases[i].depth, 64 * eps<T>());
    const Transform<T> out(Vec3<T>(pose.p + r.direction * T(r.depth * T(1.001))), pose.q);
    EXPECT_FALSE(overlaps<T>(cases[i].g0, out, cases[i].g1, pose));
  }
}

TYPED_TEST(HardCases, RotationByPiAboutZGivesTheSameAnswer) {
  using T = TypeParam;
  // Boxes are symmetric under Rz(pi): R and R*Rz(pi) describe the same box and must give the same answer.
  Rng rng(314);
  const Quat<T> rzPi(Eigen::AngleAxis<T>(T(M_PI), Vec3<T>::UnitZ()));
  const Geometry<T> box0 = BoxGeometry<T>(T(0.5), T(0.8), T(0.3)), box1 = BoxGeometry<T>(T(1), T(0.4), T(0.6));
  const Geometry<T> cap = CapsuleGeometry<T>(T(0.3), T(0.7));
  for (int i = 0; i < 200; ++i) {
    const Transform<T> p0 = rng.pose<T>(0.8), p1 = rng.pose<T>(0.8);
    const Transform<T> p1Flipped(p1.p, Quat<T>(p1.q * rzPi));
    for (const Geometry<T>* g0 : {&box0, &cap}) {
      const auto a = penetration<T>(*g0, p0, box1, p1), b = penetration<T>(*g0, p0, box1, p1Flipped);
      ASSERT_EQ(a.penetrating, b.penetrating) << i;
      EXPECT_EQ(overlaps<T>(*g0, p0, box1, p1), overlaps<T>(*g0, p0, box1, p1Flipped)) << i;
      if (!a.penetrating) continue;
      EXPECT_NEAR(double(a.depth), double(b.depth), 64 * eps<T>()) << i;
    }
  }
}

TYPED_TEST(HardCases, SizeRatiosFromMilliToKilo) {
  using T = TypeParam;
  // A box of half s resting on the +X face of the unit box with overlap s/2, and a sphere of radius s likewise.
  for (double s : {1e-3, 1e-2, 1e-1, 1.0, 1e1, 1e2, 1e3}) {
    SCOPED_TRACE(testing::Message() << "s " << s);
    const T x = T(1 + s / 2);
    const LD depth = (LD(1) + LD(T(s))) - LD(x);  // exact for the stored values
    const double tol = 16 * eps<T>() * std::max(1.0, s);
    const auto b = penetration<T>(BoxGeometry<T>(T(s), T(s), T(s)), Transform<T>(Vec3<T>(x, 0, 0)), BoxGeometry<T>(1, 1, 1), Transform<T>());
    ASSERT_TRUE(b.penetrating);
    EXPECT_NEAR(double(b.depth), double(depth), tol);
    const auto sp = penetration<T>(SphereGeometry<T>(T(s)), Transform<T>(Vec3<T>(x, 0, 0)), BoxGeometry<T>(1, 1, 1), Transform<T>());
    ASSERT_TRUE(sp.penetrating);
    EXPECT_NEAR(double(sp.depth), double(depth), tol);
    EXPECT_NEAR(double(sp.direction.x()), 1.0, 16 * eps<T>());
    const auto c = penetration<T>(CapsuleGeometry<T>(T(s), T(s)), Transform<T>(Vec3<T>(T(x + T(s)), 0, 0)), BoxGeometry<T>(1, 1, 1), Transform<T>());
    ASSERT_TRUE(c.penetrating);
    EXPECT_NEAR(double(c.depth), double((LD(1) + 2 * LD(T(s))) - LD(T(x + T(s)))), tol);
  }
}

TYPED_TEST(HardCases, PosesFarFromOriginKeepRelativePrecision) {
  using T = TypeParam;
  const Vec3<T> far(T(1e4), T(-1e4), T(1e4));
  const Vec3<T> c0 = far + Vec3<T>(T(1.7), T(0.2), T(-0.1));
  const Vec3<T> h(1, 1, 1);
  const AxisPush want = alignedBoxPush(toLD(c0), toLD(h), toLD(far), toLD(h));
  const double tol = 4 * eps<T>() * 1e4;  // the stored positions' own resolution
  const auto b = penetration<T>(BoxGeometry<T>(h), Transform<T>(c0), BoxGeometry<T>(h), Transform<T>(far));
  ASSERT_TRUE(b.penetrating);
  EXPECT_NEAR(double(b.depth), double(want.depth), tol);
  expectAxisDirection<T>(b.direction, want.axis, want.sign, 1e-3);
  const auto s = penetration<T>(SphereGeometry<T>(1), Transform<T>(c0), SphereGeometry<T>(1), Transform<T>(far));
  ASSERT_TRUE(s.penetrating);
  EXPECT_NEAR(double(s.depth), double(2 - (toLD(c0) - toLD(far)).norm()), tol);
  const Geometry<T> hull = ConvexMeshGeometry<T>(boxHull<T>(h));
  const auto hh = penetration<T>(hull, Transform<T>(c0), hull, Transform<T>(far));
  ASSERT_TRUE(hh.penetrating);
  EXPECT_NEAR(double(hh.depth), double(want.depth), tol);
}

// A pose passes validation when | |q| - 1 | <= 1e-3 (PxTransform::isValid); every family then uses the normalised
// rotation, so a quaternion scaled by 1.0008 answers as its unit quaternion (found by fuzz_pair_queries: the SAT
// kernels read the relative pose of non-unit quaternions as a scaled rotation, a cube 0.17 % too big).
TYPED_TEST(HardCases, QuaternionsWithinTheUnitToleranceAreNormalisedByEveryFamily) {
  using T = TypeParam;
  const Quat<T> unit = Quat<T>(T(-0.5), T(-0.5), T(-0.5), T(-0.5));
  const Quat<T> scaled(unit.coeffs() * T(1.0008));
  const Transform<T> tilted(Vec3<T>(T(-1.5), T(-1.5), T(-1.5)),
                            Quat<T>(T(-0.2734738), T(0), T(-0.6988775), T(-0.6608951)).normalized());
  const Geometry<T> hull = ConvexMeshGeometry<T>(boxHull<T>(Vec3<T>(1, 1, 1)));
  const Geometry<T> capsule = CapsuleGeometry<T>(T(4.9375), T(4.875)), box = BoxGeometry<T>(T(1.5), T(1), T(2));
  const double tol = 64 * eps<T>() * 10;
  for (const Geometry<T>* other : {&capsule, &box, &hull}) {
    SCOPED_TRACE(toString(other->type()));
    const auto want = penetration<T>(*other, tilted, hull, Transform<T>(Vec3<T>::Zero(), unit));
    const auto got = penetration<T>(*other, tilted, hull, Transform<T>(Vec3<T>::Zero(), scaled));
    ASSERT_TRUE(want.penetrating);
    ASSERT_TRUE(got.penetrating);
    EXPECT_NEAR(double(got.depth), double(want.depth), tol);
    EXPECT_NEAR(double(got.direction.dot(want.direction)), 1.0, tol);
    DistanceResult<T> d;
    ASSERT_TRUE(distance(d, *other, tilted, hull, Transform<T>(Vec3<T>::Zero(), scaled)).ok());
    EXPECT_NEAR(double(d.distance), -double(want.depth), 1e3 * tol);  // GJK/EPA against the exact SAT
  }
}

TYPED_TEST(HardCases, ParallelCapsulesPushApartPerpendicularToTheirAxes) {
  using T = TypeParam;
  const Quat<T> q(Eigen::AngleAxis<T>(T(0.7), Vec3<T>(1, 1, 0).normalized()));
  const Vec3<T> axis = q * Vec3<T>::UnitX(), side = q * Vec3<T>::UnitY();
  for (double offset : {0.0, 0.3, 0.7}) {
    const auto r = penetration<T>(CapsuleGeometry<T>(T(0.25), 1), Transform<T>(Vec3<T>(side * T(offset) + axis * T(0.5)), q),
                                  CapsuleGeometry<T>(T(0.5), 2), Transform<T>(Vec3<T>::Zero(), q));
    ASSERT_TRUE(r.penetrating);
    EXPECT_NEAR(double(r.depth), 0.75 - offset, 16 * eps<T>());
    EXPECT_NEAR(double(r.direction.dot(axis)), 0.0, 16 * eps<T>());
    if (offset > 0) EXPECT_NEAR(double(r.direction.dot(side)), 1.0, 16 * eps<T>());
  }
  // Parallel to a box face, over it: depth from the face, along its normal.
  const auto f = penetration<T>(CapsuleGeometry<T>(T(0.25), T(0.5)), Transform<T>(Vec3<T>(0, 0, 1.1)), BoxGeometry<T>(1, 1, 1), Transform<T>());
  ASSERT_TRUE(f.penetrating);
  EXPECT_NEAR(double(f.depth), 0.15, 16 * eps<T>());
  expectAxisDirection<T>(f.direction, 2, 1, 16 * eps<T>());
}

TYPED_TEST(HardCases, ZeroLengthCapsuleBehavesAsSphere) {
  using T = TypeParam;
  Rng rng(0);
  const Geometry<T> others[] = {BoxGeometry<T>(T(0.5), T(0.8), T(0.3)), CapsuleGeometry<T>(T(0.3), T(0.6)),
                                ConvexMeshGeometry<T>(octahedronHull<T>(1)), SphereGeometry<T>(T(0.4))};
  for (int i = 0; i < 200; ++i) {
    const Transform<T> p0 = rng.pose<T>(1), p1 = rng.pose<T>(1);
    for (const Geometry<T>& other : others) {
      const auto c = penetration<T>(CapsuleGeometry<T>(T(0.6), T(0)), p0, other, p1);
      const auto s = penetration<T>(SphereGeometry<T>(T(0.6)), p0, other, p1);
      ASSERT_EQ(c.penetrating, s.penetrating) << i;
      EXPECT_EQ(overlaps<T>(CapsuleGeometry<T>(T(0.6), T(0)), p0, other, p1), s.penetrating) << i;
      if (!c.penetrating) continue;
      EXPECT_NEAR(double(c.depth), double(s.depth), 64 * eps<T>()) << i;
    }
  }
  // Two zero-length capsules at the same point.
  const auto z = penetration<T>(CapsuleGeometry<T>(T(0.6), T(0)), Transform<T>(), CapsuleGeometry<T>(T(0.4), T(0)), Transform<T>());
  ASSERT_TRUE(z.penetrating);
  EXPECT_NEAR(double(z.depth), 1.0, 16 * eps<T>());
  EXPECT_NEAR(double(z.direction.norm()), 1.0, 16 * eps<T>());
}

TYPED_TEST(HardCases, PaperThinBoxes) {
  using T = TypeParam;
  const T thin = std::is_same_v<T, float> ? T(1e-4) : T(1e-9);
  const Geometry<T> sheet = BoxGeometry<T>(1, 1, thin);
  // A sheet lying inside a unit box, off centre: push out through the nearest face of the sheet or the box.
  const auto r = penetration<T>(sheet, Transform<T>(Vec3<T>(0, 0, 0.9)), BoxGeometry<T>(1, 1, 1), Transform<T>());
  ASSERT_TRUE(r.penetrating);
  EXPECT_NEAR(double(r.depth), double(LD(1) - (LD(T(0.9)) - LD(thin))), 16 * eps<T>());
  expectAxisDirection<T>(r.direction, 2, 1, 16 * eps<T>());
  // Two sheets crossing at right angles (parallel edges along X): depth is the thin dimension.
  const Quat<T> rx(Eigen::AngleAxis<T>(T(M_PI / 2), Vec3<T>::UnitX()));
  const auto x = penetration<T>(sheet, Transform<T>(), sheet, Transform<T>(Vec3<T>::Zero(), rx));
  ASSERT_TRUE(x.penetrating);
  EXPECT_NEAR(double(x.depth), 1.0 + double(thin), 64 * eps<T>());
  // A sheet just above another: separated by a gap smaller than its thickness.
  EXPECT_FALSE(overlaps<T>(sheet, Transform<T>(Vec3<T>(0.3, 0.2, 3 * thin)), sheet, Transform<T>()));
  EXPECT_TRUE(overlaps<T>(sheet, Transform<T>(Vec3<T>(0.3, 0.2, T(1.5) * thin)), sheet, Transform<T>()));
  const auto s = penetration<T>(SphereGeometry<T>(T(0.5)), Transform<T>(Vec3<T>(0.2, 0.1, 0.4)), sheet, Transform<T>());
  ASSERT_TRUE(s.penetrating);
  EXPECT_NEAR(double(s.depth), 0.1 + double(thin), 16 * eps<T>());
  expectAxisDirection<T>(s.direction, 2, 1, 16 * eps<T>());
}

}  // namespace
}  // namespace gq::test
