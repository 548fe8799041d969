// gq::distance on the closed-form pairs against long-double references written here, over seeded random poses.
#include "gjk_test_shapes.h"

namespace {

using namespace gjktest;

template <class T> class DistanceClosedForm : public ::testing::Test {};
TYPED_TEST_SUITE(DistanceClosedForm, Scalars);

constexpr int kPoses = 1000;

template <class T> gq::DistanceResult<T> run(const gq::Geometry<T>& g0, const gq::Transform<T>& p0, const gq::Geometry<T>& g1,
                                             const gq::Transform<T>& p1) {
  gq::DistanceResult<T> r;
  const gq::Status s = gq::distance(r, g0, p0, g1, p1);
  EXPECT_EQ(s.code, gq::StatusCode::Ok) << s.toString();
  return r;
}

TYPED_TEST(DistanceClosedForm, SphereSphereIsCentreDistanceMinusRadii) {
  using T = TypeParam;
  Rng rng(11);
  for (int i = 0; i < kPoses; ++i) {
    const double r0 = rng.uniform(0.1, 1), r1 = rng.uniform(0.1, 1);
    const auto p0 = randomPose<T>(rng, 1.5), p1 = randomPose<T>(rng, 1.5);
    const auto r = run<T>(sphere<T>(r0), p0, sphere<T>(r1), p1);
    const L exact = (toL(p1.p) - toL(p0.p)).norm() - L(T(r0)) - L(T(r1));
    ASSERT_NEAR(double(r.distance), double(exact), kClosedFormTol<T>) << "pose " << i;
    EXPECT_NEAR(double((toL(r.point0) - toL(p0.p)).norm()), double(T(r0)), kClosedFormTol<T>);
    EXPECT_NEAR(double((toL(r.point1) - toL(p1.p)).norm()), double(T(r1)), kClosedFormTol<T>);
    expectConsistent(r, kClosedFormTol<T>);
  }
}

TYPED_TEST(DistanceClosedForm, SphereCapsuleIsDistanceToSegmentMinusRadii) {
  using T = TypeParam;
  Rng rng(12);
  for (int i = 0; i < kPoses; ++i) {
    const double r0 = rng.uniform(0.1, 1), r1 = rng.uniform(0.1, 0.6), hh = rng.uniform(0, 1.5);
    const auto p0 = randomPose<T>(rng, 1.5), p1 = randomPose<T>(rng, 1.5);
    const gq::CapsuleGeometry<T> cap{T(r1), T(hh)};
    const auto [a, b] = capsuleSegment(cap, p1);
    const L exact = pointSegment(toL(p0.p), a, b) - L(T(r0)) - L(T(r1));
    // Both orders: the mirrored cell flips the answer.
    const auto r = run<T>(sphere<T>(r0), p0, cap, p1);
    const auto m = run<T>(cap, p1, sphere<T>(r0), p0);
    ASSERT_NEAR(double(r.distance), double(exact), kClosedFormTol<T>) << "pose " << i;
    ASSERT_NEAR(double(m.distance), double(exact), kClosedFormTol<T>) << "pose " << i;
    EXPECT_NEAR(double((toL(r.point0) - toL(p0.p)).norm()), double(T(r0)), kClosedFormTol<T>);
    EXPECT_NEAR(double(pointSegment(toL(r.point1), a, b)), double(T(r1)), kClosedFormTol<T>);
    EXPECT_LE(double((toL(m.normal) + toL(r.normal)).norm()), kClosedFormTol<T>);
    expectConsistent(r, kClosedFormTol<T>);
    expectConsistent(m, kClosedFormTol<T>);
  }
}

template <class T> void checkCapsulePair(const gq::CapsuleGeometry<T>& c0, const gq::Transform<T>& p0,
                                         const gq::CapsuleGeometry<T>& c1, const gq::Transform<T>& p1, int i) {
  const auto [a0, b0] = capsuleSegment(c0, p0);
  const auto [a1, b1] = capsuleSegment(c1, p1);
  const L exact = segmentSegment(a0, b0, a1, b1) - L(c0.radius) - L(c1.radius);
  const auto r = run<T>(c0, p0, c1, p1);
  ASSERT_NEAR(double(r.distance), double(exact), kClosedFormTol<T>) << "pose " << i;
  EXPECT_NEAR(double(pointSegment(toL(r.point0), a0, b0)), double(c0.radius), kClosedFormTol<T>);
  EXPECT_NEAR(double(pointSegment(toL(r.point1), a1, b1)), double(c1.radius), kClosedFormTol<T>);
  expectConsistent(r, kClosedFormTol<T>);
}

// Capsule 0 at (base, q); capsule 1 turned by `turn` about capsule 0's Z and moved by `offset` in its frame.
template <class T>
void checkTurnedCapsulePair(const gq::CapsuleGeometry<T>& c0, const gq::CapsuleGeometry<T>& c1, const Eigen::Quaterniond& q,
                            double turn, const Eigen::Vector3d& offset, const Eigen::Vector3d& base, int i) {
  const Eigen::Quaterniond q1 = q * Eigen::Quaterniond(Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitZ()));
  checkCapsulePair(c0, gq::Transform<T>(base.cast<T>(), q.cast<T>()), c1,
                   gq::Transform<T>((base + q * offset).cast<T>(), q1.cast<T>()), i);
}

TYPED_TEST(DistanceClosedForm, CapsuleCapsuleIsSegmentDistanceMinusRadii) {
  using T = TypeParam;
  Rng rng(13);
  for (int i = 0; i < kPoses; ++i) {
    const double r0 = rng.uniform(0.1, 0.5), hh0 = rng.uniform(0, 1.5);
    const double r1 = rng.uniform(0.1, 0.5), hh1 = rng.uniform(0, 1.5);
    const gq::CapsuleGeometry<T> c0{T(r0), T(hh0)}, c1{T(r1), T(hh1)};
    const auto p0 = randomPose<T>(rng, 1.5), p1 = randomPose<T>(rng, 1.5);
    checkCapsulePair(c0, p0, c1, p1, i);
  }
}

TYPED_TEST(DistanceClosedForm, CapsuleCapsuleParallelAxesAreExact) {
  using T = TypeParam;
  Rng rng(14);
  for (int i = 0; i < kPoses; ++i) {
    const double r0 = rng.uniform(0.1, 0.5), hh0 = rng.uniform(0.1, 1.5);
    const double r1 = rng.uniform(0.1, 0.5), hh1 = rng.uniform(0.1, 1.5);
    const gq::CapsuleGeometry<T> c0{T(r0), T(hh0)}, c1{T(r1), T(hh1)};
    const Eigen::Quaterniond q = rng.rotation();
    // Same axis (or reversed), offset both along and across it: overlapping or disjoint spans.
    const double turn = (i % 2) ? 0 : M_PI;
    const Eigen::Vector3d offset{rng.uniform(-3, 3), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    checkTurnedCapsulePair(c0, c1, q, turn, offset, rng.vec(-1, 1), i);
  }
}

// Axes a small angle apart (1e-6 to 1e-2 rad), side by side with the spans shifted: the closest points sit at
// one end, which the Gram-determinant form of the segment solve (ae - b^2 below eps * ae read as parallel) missed
// by up to |d| sin(angle), 5e-4 in float.
TYPED_TEST(DistanceClosedForm, CapsuleCapsuleNearlyParallelAxesAreExact) {
  using T = TypeParam;
  Rng rng(16);
  for (int i = 0; i < kPoses; ++i) {
    const double r0 = rng.uniform(0.05, 0.2), hh0 = rng.uniform(0.5, 1.5);
    const double r1 = rng.uniform(0.05, 0.2), hh1 = rng.uniform(0.5, 1.5);
    const gq::CapsuleGeometry<T> c0{T(r0), T(hh0)}, c1{T(r1), T(hh1)};
    const Eigen::Quaterniond q = rng.rotation();
    const double angle = std::pow(10.0, rng.uniform(-6, -2)) * (i % 2 ? 1 : -1);
    const Eigen::Vector3d offset{rng.uniform(-1, 1), rng.uniform(0.5, 1), 0};
    checkTurnedCapsulePair(c0, c1, q, angle, offset, rng.vec(-1, 1), i);
  }
}

// A half axis whose square is below the smallest normal number counts as a point, and axes whose |a0 x a1|^2 is
// below it as parallel (closestCentredSegments takes reciprocals of both): each moves the closest points by less
// than that number's square root, so the answers stay exact.
TYPED_TEST(DistanceClosedForm, CapsuleCapsuleSquaresBelowTheSmallestNormalNumberStayExact) {
  using T = TypeParam;
  const double tiny = 0.5 * std::sqrt(double(std::numeric_limits<T>::min()));  // tiny^2 is subnormal in T
  Rng rng(17);
  for (int i = 0; i < kPoses; ++i) {
    const double r0 = rng.uniform(0.1, 0.5), r1 = rng.uniform(0.1, 0.5);
    const double hh0 = i % 3 == 0 ? tiny : rng.uniform(0.5, 1.5), hh1 = i % 3 == 1 ? tiny : rng.uniform(0.5, 1.5);
    const gq::CapsuleGeometry<T> c0{T(r0), T(hh0)}, c1{T(r1), T(hh1)};
    const double angle = i % 3 == 2 ? tiny : rng.uniform(0, M_PI);  // two long axes `tiny` radians apart
    // Even poses: capsule 0 on X at the origin, capsule 1's centre off X (and off the axes' plane when they are
    // nearly parallel), where the solve's numerators are exactly 0 (0 times an overflowed reciprocal is NaN).
    const bool square = i % 2 == 0;
    Eigen::Vector3d offset{square ? 0.0 : rng.uniform(-2, 2), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    if (square && i % 3 == 2) offset.y() = 0;
    checkTurnedCapsulePair(c0, c1, square ? Eigen::Quaterniond::Identity() : rng.rotation(), angle, offset,
                           square ? Eigen::Vector3d::Zero() : rng.vec(-1, 1), i);
  }
}

TYPED_TEST(DistanceClosedForm, CapsuleCapsuleZeroLengthSegmentsAreSpheres) {
  using T = TypeParam;
  Rng rng(15);
  for (int i = 0; i < kPoses; ++i) {
    const double r0 = rng.uniform(0.1, 0.5);
    const double r1 = rng.uniform(0.1, 0.5), hh1 = i % 2 ? 0 : rng.uniform(0, 1);
    const gq::CapsuleGeometry<T> c0{T(r0), T(0)}, c1{T(r1), T(hh1)};
    const auto p0 = randomPose<T>(rng, 1.5), p1 = randomPose<T>(rng, 1.5);
    checkCapsulePair(c0, p0, c1, p1, i);
  }
}

TYPED_TEST(DistanceClosedForm, CapsuleCapsuleCrossingAxesSeparateAlongCommonPerpendicular) {
  using T = TypeParam;
  // Axes X and Y crossing at the origin: depth r0 + r1 along +-Z.
  const gq::CapsuleGeometry<T> c(T(0.25), T(1));
  const gq::Transform<T> p1(gq::Vec3<T>::Zero(), gq::Quat<T>(Eigen::AngleAxis<T>(T(M_PI / 2), gq::Vec3<T>::UnitZ())));
  const auto r = run<T>(c, gq::Transform<T>(), c, p1);
  EXPECT_NEAR(double(r.distance), -0.5, kClosedFormTol<T>);
  EXPECT_NEAR(std::abs(double(r.normal.z())), 1.0, kClosedFormTol<T>);
  expectConsistent(r, kClosedFormTol<T>);
}

TYPED_TEST(DistanceClosedForm, SphereBoxMatchesSignedDistanceToBox) {
  using T = TypeParam;
  Rng rng(16);
  for (int i = 0; i < kPoses; ++i) {
    const double rad = rng.uniform(0.05, 0.8);
    const Eigen::Vector3d h = rng.vec(0.2, 1.2);
    const auto p0 = randomPose<T>(rng, 1.8), p1 = randomPose<T>(rng, 0.5);
    const Polytope P = boxPolytope<T>(h.cast<T>(), p1);
    const L exact = signedDistanceToPolytope(toL(p0.p), P) - L(T(rad));
    const auto r = run<T>(sphere<T>(rad), p0, box<T>(h), p1);
    const auto m = run<T>(box<T>(h), p1, sphere<T>(rad), p0);
    ASSERT_NEAR(double(r.distance), double(exact), kClosedFormTol<T>) << "pose " << i;
    ASSERT_NEAR(double(m.distance), double(exact), kClosedFormTol<T>) << "pose " << i;
    EXPECT_NEAR(double(signedDistanceToPolytope(toL(r.point1), P)), 0.0, kClosedFormTol<T>);  // on the box surface
    EXPECT_NEAR(double((toL(r.point0) - toL(p0.p)).norm()), double(T(rad)), kClosedFormTol<T>);
    expectConsistent(r, kClosedFormTol<T>);
    expectConsistent(m, kClosedFormTol<T>);
  }
}

// Capsule-box is a closed form in both orders (exact against brute force: DistanceGjk.CapsuleBoxMatchesBruteForce...).
TYPED_TEST(DistanceClosedForm, CapsuleBoxInEitherOrderIsTheMirroredAnswerAndAZeroLengthCapsuleIsASphere) {
  using T = TypeParam;
  Rng rng(17);
  for (int i = 0; i < kPoses; ++i) {
    const double rad = rng.uniform(0.05, 0.6);
    const gq::CapsuleGeometry<T> cap(T(rad), T(i % 4 == 0 ? 0 : rng.uniform(0.1, 1.2)));
    const Eigen::Vector3d h = rng.vec(0.2, 1.2);
    const auto p0 = randomPose<T>(rng, 1.8), p1 = randomPose<T>(rng, 0.5);
    const auto r = run<T>(cap, p0, box<T>(h), p1);
    const auto m = run<T>(box<T>(h), p1, cap, p0);
    ASSERT_NEAR(double(r.distance), double(m.distance), kClosedFormTol<T>) << "pose " << i;
    EXPECT_NEAR(double((r.point0 - m.point1).norm()), 0.0, kClosedFormTol<T>);
    EXPECT_NEAR(double((r.normal + m.normal).norm()), 0.0, kClosedFormTol<T>);
    expectConsistent(r, kClosedFormTol<T>);
    if (cap.halfHeight == T(0)) {
      const Polytope P = boxPolytope<T>(h.cast<T>(), p1);
      EXPECT_NEAR(double(r.distance), double(signedDistanceToPolytope(toL(p0.p), P) - L(T(rad))), kClosedFormTol<T>);
    }
  }
}

TYPED_TEST(DistanceClosedForm, SpherePlaneIsHeightMinusRadius) {
  using T = TypeParam;
  Rng rng(17);
  for (int i = 0; i < kPoses; ++i) {
    const double rad = rng.uniform(0.1, 1);
    const auto p0 = randomPose<T>(rng, 2), p1 = randomPose<T>(rng, 1);
    const PoseL pl = toL(p1);
    const L exact = pl.rotate(VL(1, 0, 0)).dot(toL(p0.p) - pl.p) - L(T(rad));
    const auto r = run<T>(sphere<T>(rad), p0, gq::PlaneGeometry<T>(), p1);
    const auto m = run<T>(gq::PlaneGeometry<T>(), p1, sphere<T>(rad), p0);
    ASSERT_NEAR(double(r.distance), double(exact), kClosedFormTol<T>);
    ASSERT_NEAR(double(m.distance), double(exact), kClosedFormTol<T>);
    EXPECT_NEAR(double(pl.rotate(VL(1, 0, 0)).dot(toL(r.point1) - pl.p)), 0.0, kClosedFormTol<T>);  // on the plane
    expectConsistent(r, kClosedFormTol<T>);
    expectConsistent(m, kClosedFormTol<T>);
  }
}

TYPED_TEST(DistanceClosedForm, PlaneBoxIsLowestCornerHeight) {
  using T = TypeParam;
  Rng rng(18);
  for (int i = 0; i < kPoses; ++i) {
    const Eigen::Vector3d h = rng.vec(0.2, 1.2);
    const auto p0 = randomPose<T>(rng, 1), p1 = randomPose<T>(rng, 2);
    const PoseL pl = toL(p0);
    const VL n = pl.rotate(VL(1, 0, 0));
    L exact = std::numeric_limits<L>::infinity();
    for (const VL& v : boxPolytope<T>(h.cast<T>(), p1).v) exact = std::min(exact, n.dot(v - pl.p));
    const auto r = run<T>(gq::PlaneGeometry<T>(), p0, box<T>(h), p1);
    const auto m = run<T>(box<T>(h), p1, gq::PlaneGeometry<T>(), p0);
    ASSERT_NEAR(double(r.distance), double(exact), kClosedFormTol<T>);
    ASSERT_NEAR(double(m.distance), double(exact), kClosedFormTol<T>);
    EXPECT_NEAR(double(n.dot(toL(r.point0) - pl.p)), 0.0, kClosedFormTol<T>);
    expectConsistent(r, kClosedFormTol<T>);
    expectConsistent(m, kClosedFormTol<T>);
  }
}

TYPED_TEST(DistanceClosedForm, PlaneCapsuleIsLowestEndHeightMinusRadius) {
  using T = TypeParam;
  Rng rng(19);
  for (int i = 0; i < kPoses; ++i) {
    const double rad = rng.uniform(0.1, 0.6), hh = rng.uniform(0, 1.5);
    const gq::CapsuleGeometry<T> cap{T(rad), T(hh)};
    const auto p0 = randomPose<T>(rng, 1), p1 = randomPose<T>(rng, 2);
    const PoseL pl = toL(p0);
    const VL n = pl.rotate(VL(1, 0, 0));
    const auto [a, b] = capsuleSegment(cap, p1);
    const L exact = std::min(n.dot(a - pl.p), n.dot(b - pl.p)) - L(cap.radius);
    const auto r = run<T>(gq::PlaneGeometry<T>(), p0, cap, p1);
    ASSERT_NEAR(double(r.distance), double(exact), kClosedFormTol<T>);
    EXPECT_NEAR(double(pointSegment(toL(r.point1), a, b)), double(cap.radius), kClosedFormTol<T>);
    expectConsistent(r, kClosedFormTol<T>);
  }
}

}  // namespace
