// Custom geometry's optional query callbacks (gq/custom.h): a custom ball that answers overlap, penetration and
// sweeps against spheres itself, and the same ball without those callbacks (GJK, EPA and conservative advancement on
// its support mapping). Both paths are checked against closed forms computed here in long double, in float and double.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <limits>
#include <memory>

#include "gq/custom.h"
#include "gq/query.h"
#include "test_util.h"

namespace {

using namespace gq;
using gq::test::LD;
using gq::test::Rng;
using gq::test::Vec3L;

template <class T> Vec3L toL(const Vec3<T>& v) { return v.template cast<LD>(); }

// A ball of radius r about the local origin, described by its support mapping and an exact raycast.
template <class T> class Ball : public CustomGeometryCallbacks<T> {
 public:
  explicit Ball(T r) : r_(r) {}
  const char* name() const override { return "ball"; }
  Bounds3<T> localBounds() const override { return Bounds3<T>::fromCenterExtents(Vec3<T>::Zero(), Vec3<T>::Constant(r_)); }
  Vec3<T> support(const Vec3<T>& d) const override {
    const T n = d.norm();
    return n > T(0) ? Vec3<T>(d * (r_ / n)) : Vec3<T>::Zero();
  }
  bool raycast(const Vec3<T>& o, const Vec3<T>& d, T maxDist, HitFlags, RaycastHit<T>& hit) const override {
    const T b = o.dot(d), c = o.squaredNorm() - r_ * r_;
    if (c <= T(0)) { hit.distance = T(0); hit.position = o; hit.normal = -d; hit.flags = HitFlag::Position | HitFlag::Normal; return true; }
    const T disc = b * b - c;
    if (b > T(0) || disc < T(0)) return false;
    const T t = -b - std::sqrt(disc);
    if (t > maxDist) return false;
    hit.distance = t;
    hit.position = o + t * d;
    hit.normal = hit.position.normalized();
    hit.flags = HitFlag::Position | HitFlag::Normal;
    return true;
  }
  T radius() const { return r_; }

 protected:
  T r_;
};

// The same ball answering overlap, penetration and sweeps against spheres in closed form (other shapes: declined).
template <class T> class AnsweringBall final : public Ball<T> {
 public:
  using Ball<T>::Ball;
  mutable std::atomic<int> calls{0};

  bool overlap(const Geometry<T>& other, const Transform<T>& pose, bool& overlapping) const override {
    const auto* s = other.template getIf<SphereGeometry<T>>();
    if (!s) return false;
    ++calls;
    overlapping = pose.p.norm() <= this->r_ + s->radius;
    return true;
  }
  bool computePenetration(const Geometry<T>& other, const Transform<T>& pose, bool& penetrating, Vec3<T>& direction,
                          T& depth) const override {
    const auto* s = other.template getIf<SphereGeometry<T>>();
    if (!s) return false;
    ++calls;
    const T d = pose.p.norm();
    penetrating = d <= this->r_ + s->radius;
    depth = this->r_ + s->radius - d;
    direction = d > T(0) ? Vec3<T>(-pose.p / d) : Vec3<T>(Vec3<T>::UnitX());  // this ball leaves away from the sphere
    return true;
  }
  bool distance(const Geometry<T>& other, const Transform<T>& pose, DistanceResult<T>& result) const override {
    const auto* s = other.template getIf<SphereGeometry<T>>();
    if (!s) return false;
    ++calls;
    const T d = pose.p.norm();
    result.normal = d > T(0) ? Vec3<T>(pose.p / d) : Vec3<T>(Vec3<T>::UnitX());
    result.distance = d - this->r_ - s->radius;
    result.point0 = this->r_ * result.normal;
    result.point1 = pose.p - s->radius * result.normal;
    return true;
  }
  bool sweep(const Vec3<T>& dir, T maxDist, const Geometry<T>& swept, const Transform<T>& pose, T inflation,
             SweepHit<T>& hit, bool& hasHit) const override {
    const auto* s = swept.template getIf<SphereGeometry<T>>();
    if (!s) return false;
    ++calls;
    const T rr = this->r_ + s->radius + inflation;
    const Vec3<T>& c = pose.p;
    hasHit = false;
    if (c.norm() <= rr) {
      hasHit = true;
      hit.initialOverlap = true;
      hit.distance = T(0);
      hit.normal = -dir;
      hit.position = c;
      return true;
    }
    const T b = c.dot(dir), disc = b * b - (c.squaredNorm() - rr * rr);
    if (b >= T(0) || disc < T(0)) return true;
    const T t = -b - std::sqrt(disc);
    if (t > maxDist) return true;
    hasHit = true;
    hit.distance = t;
    hit.normal = (c + t * dir).normalized();
    hit.position = hit.normal * this->r_;
    return true;
  }
};

// Answers penetration and distance with NaN: the query must report it instead of passing it on.
template <class T> class BrokenBall final : public Ball<T> {
 public:
  using Ball<T>::Ball;
  bool distance(const Geometry<T>&, const Transform<T>&, DistanceResult<T>& result) const override {
    result.distance = std::numeric_limits<T>::quiet_NaN();
    result.normal = Vec3<T>::UnitX();
    return true;
  }
  bool computePenetration(const Geometry<T>&, const Transform<T>&, bool& penetrating, Vec3<T>& direction,
                          T& depth) const override {
    penetrating = true;
    direction = Vec3<T>::UnitX();
    depth = std::numeric_limits<T>::quiet_NaN();
    return true;
  }
};

template <class T> struct CustomCallbacks : ::testing::Test {
  // Callback answers are closed forms in T; the generic path is GJK/EPA to its tolerance on a curved support map.
  // There a distance error e moves the normal by about sqrt(2 e / R) (the ball is flat to second order), so
  // directions and points of the generic path get the square root of its distance tolerance.
  static constexpr double kExact = std::is_same_v<T, double> ? 1e-12 : 2e-5;
  static constexpr double kGeneric = std::is_same_v<T, double> ? 1e-7 : 2e-4;
  static constexpr double kGenericNormal = std::is_same_v<T, double> ? 1e-4 : 1e-2;
  static constexpr double kR = 0.7, kSphere = 0.4;
  std::shared_ptr<AnsweringBall<T>> answering = std::make_shared<AnsweringBall<T>>(T(kR));
  std::shared_ptr<Ball<T>> plain = std::make_shared<Ball<T>>(T(kR));
  const Geometry<T> sphere = SphereGeometry<T>(T(kSphere));

  static Transform<T> pose(Rng& rng, double half) { return rng.pose<T>(half); }
  // The answering ball (its call count reset) or the plain one, with the tolerances of its answers and normals.
  struct BallCase {
    Geometry<T> ball;
    double tol, normalTol;
  };
  BallCase ballOf(bool useAnswering) {
    answering->calls = 0;
    if (useAnswering) return {CustomGeometry<T>(answering), kExact, 10 * kExact};
    return {CustomGeometry<T>(plain), kGeneric, kGenericNormal};
  }
  // Distance between the two centres in long double.
  static LD centreDistance(const Transform<T>& a, const Transform<T>& b) { return (toL(a.p) - toL(b.p)).norm(); }
};
TYPED_TEST_SUITE(CustomCallbacks, gq::test::Scalars);

TYPED_TEST(CustomCallbacks, OverlapAsksTheCallbackOnEitherSideAndFallsBackToGjkWithout) {
  using T = TypeParam;
  Rng rng(501);
  for (const bool useAnswering : {true, false}) {
    const Geometry<T> ball = useAnswering ? CustomGeometry<T>(this->answering) : CustomGeometry<T>(this->plain);
    this->answering->calls = 0;
    int checked = 0;
    for (int i = 0; i < 300; ++i) {
      const Transform<T> p0 = this->pose(rng, 1.5), p1 = this->pose(rng, 1.5);
      const LD gap = this->centreDistance(p0, p1) - LD(this->kR + this->kSphere);
      if (std::abs(double(gap)) < 1e-3) continue;  // the float poses' rounding decides touching cases
      bool a = false, b = false;
      ASSERT_TRUE(overlap(ball, p0, this->sphere, p1, a).ok());
      ASSERT_TRUE(overlap(this->sphere, p1, ball, p0, b).ok());
      EXPECT_EQ(a, gap <= 0) << "gap " << double(gap);
      EXPECT_EQ(b, gap <= 0);
      ++checked;
    }
    EXPECT_GT(checked, 250);
    EXPECT_EQ(this->answering->calls.load(), useAnswering ? 2 * checked : 0);
  }
}

TYPED_TEST(CustomCallbacks, DeclinedOverlapFallsBackToGjk) {
  using T = TypeParam;
  // Against a box the answering ball declines: GJK decides. Exact: the ball overlaps the axis-aligned box iff its
  // centre is within r of the box (distance from a point to a box, per axis).
  const Geometry<T> ball = CustomGeometry<T>(this->answering);
  const Geometry<T> box = BoxGeometry<T>(T(0.5), T(0.3), T(0.2));
  Rng rng(502);
  this->answering->calls = 0;
  for (int i = 0; i < 300; ++i) {
    const Vec3<T> c = rng.inBox<T>(1.5);
    const Vec3L e(0.5L, 0.3L, 0.2L);
    const LD dist = (toL(c).cwiseAbs() - e).cwiseMax(Vec3L::Zero()).norm();
    if (std::abs(double(dist - LD(this->kR))) < 1e-3) continue;
    bool over = false;
    ASSERT_TRUE(overlap(ball, Transform<T>(c), box, Transform<T>(), over).ok());
    EXPECT_EQ(over, dist <= LD(this->kR));
  }
  EXPECT_EQ(this->answering->calls.load(), 0);
}

TYPED_TEST(CustomCallbacks, PenetrationCallbackDirectionMovesGeom0InEitherOrder) {
  using T = TypeParam;
  Rng rng(503);
  for (const bool useAnswering : {true, false}) {
    const auto [ball, tol, normalTol] = this->ballOf(useAnswering);
    int checked = 0;
    for (int i = 0; i < 200; ++i) {
      const Transform<T> p0 = this->pose(rng, 0.3), p1 = this->pose(rng, 0.3);  // centres < 1.04 apart: overlapping
      const Vec3L between = toL(p1.p) - toL(p0.p);  // ball centre -> sphere centre
      const LD d = between.norm();
      if (d < 1e-2) continue;  // concentric: any direction is right
      const LD depth = LD(this->kR + this->kSphere) - d;
      PenetrationResult<T> r0, r1;
      ASSERT_TRUE(computePenetration(r0, ball, p0, this->sphere, p1).ok());
      ASSERT_TRUE(computePenetration(r1, this->sphere, p1, ball, p0).ok());
      ASSERT_TRUE(r0.penetrating && r1.penetrating);
      EXPECT_NEAR(double(r0.depth), double(depth), tol);
      EXPECT_NEAR(double(r1.depth), double(depth), tol);
      // The ball (geom0 of r0) leaves away from the sphere; the sphere (geom0 of r1) the other way.
      EXPECT_NEAR(double((toL(r0.direction) + between / d).norm()), 0.0, normalTol);
      EXPECT_NEAR(double((toL(r1.direction) - between / d).norm()), 0.0, normalTol);
      ++checked;
    }
    EXPECT_EQ(this->answering->calls.load(), useAnswering ? 2 * checked : 0);
  }
}

TYPED_TEST(CustomCallbacks, DistanceCallbackAnswersInEitherOrderWithTheNormalFromGeom0) {
  using T = TypeParam;
  Rng rng(509);
  for (const bool useAnswering : {true, false}) {
    const auto [ball, tol, normalTol] = this->ballOf(useAnswering);
    int checked = 0;
    for (int i = 0; i < 200; ++i) {
      const Transform<T> p0 = this->pose(rng, 1.5), p1 = this->pose(rng, 1.5);
      const Vec3L between = toL(p1.p) - toL(p0.p);  // ball centre -> sphere centre
      const LD d = between.norm();
      if (d < LD(this->kR + this->kSphere + 0.01)) continue;  // separated pairs (penetration: the test above)
      DistanceResult<T> r0, r1;
      ASSERT_TRUE(distance(r0, ball, p0, this->sphere, p1).ok());
      ASSERT_TRUE(distance(r1, this->sphere, p1, ball, p0).ok());
      EXPECT_NEAR(double(r0.distance), double(d - LD(this->kR + this->kSphere)), tol);
      EXPECT_NEAR(double(r1.distance), double(r0.distance), tol);
      EXPECT_NEAR(double((toL(r0.normal) - between / d).norm()), 0.0, normalTol);
      EXPECT_NEAR(double((toL(r1.normal) + between / d).norm()), 0.0, normalTol);
      EXPECT_NEAR(double((toL(r0.point0) - toL(p0.p)).norm()), this->kR, tol) << "point0 on the ball";
      EXPECT_NEAR(double((toL(r1.point1) - toL(p0.p)).norm()), this->kR, tol) << "point1 on the ball";
      ++checked;
    }
    EXPECT_GT(checked, 100);
    EXPECT_EQ(this->answering->calls.load(), useAnswering ? 2 * checked : 0);
  }
}

TYPED_TEST(CustomCallbacks, SweepCallbackAnswersForACustomTargetElseConservativeAdvancement) {
  using T = TypeParam;
  Rng rng(504);
  for (const bool useAnswering : {true, false}) {
    const Geometry<T> ball = useAnswering ? CustomGeometry<T>(this->answering) : CustomGeometry<T>(this->plain);
    const double tol = useAnswering ? this->kExact : this->kGeneric;
    const double normalTol = useAnswering ? 10 * this->kExact : this->kGenericNormal;
    this->answering->calls = 0;
    int hits = 0;
    for (int i = 0; i < 200; ++i) {
      // The sphere starts 3 away and aims within 0.9 of the ball's centre: it hits (0.9 < R + r = 1.1).
      const Vec3<T> target = this->pose(rng, 2).p;
      const Vec3<T> dir = rng.unitVector<T>();
      const Vec3<T> aim = rng.inBox<T>(0.5);
      const Vec3<T> start = Vec3<T>(target + aim - T(3) * dir);
      SweepHit<T> hit;
      bool hasHit = false;
      ASSERT_TRUE(sweep(dir, T(10), this->sphere, Transform<T>(start), ball, Transform<T>(target), hit, hasHit).ok());
      // Closed form: |start + t dir - target| = R + r, first root.
      const Vec3L c = toL(start) - toL(target), dl = toL(dir).normalized();
      const LD rr = LD(this->kR + this->kSphere), b = c.dot(dl), disc = b * b - (c.squaredNorm() - rr * rr);
      ASSERT_GT(disc, 0);
      const LD t = -b - std::sqrt(disc);
      ASSERT_TRUE(hasHit);
      EXPECT_FALSE(hit.hadInitialOverlap());
      EXPECT_NEAR(double(hit.distance), double(t), tol);
      const Vec3L normal = (c + t * dl).normalized();
      EXPECT_NEAR(double((toL(hit.normal) - normal).norm()), 0.0, normalTol);
      EXPECT_LT(double(hit.normal.dot(dir)), 0.0);
      EXPECT_NEAR(double((toL(hit.position) - (toL(target) + LD(this->kR) * normal)).norm()), 0.0, normalTol);
      ++hits;
    }
    EXPECT_EQ(this->answering->calls.load(), useAnswering ? hits : 0);
  }
}

TYPED_TEST(CustomCallbacks, DeclinedSweepFallsBackAndMatchesTheFaceContact) {
  using T = TypeParam;
  // A box swept along +X towards the ball on its axis: its face x = e reaches the ball's pole at L - R.
  const Geometry<T> ball = CustomGeometry<T>(this->answering);
  this->answering->calls = 0;
  SweepHit<T> hit;
  bool hasHit = false;
  const double e = 0.25, L = 3;
  ASSERT_TRUE(sweep(Vec3<T>(Vec3<T>::UnitX()), T(10), Geometry<T>(BoxGeometry<T>(T(e), T(0.3), T(0.3))), Transform<T>(),
                    ball, Transform<T>(Vec3<T>(T(L), T(0), T(0))), hit, hasHit).ok());
  ASSERT_TRUE(hasHit);
  EXPECT_NEAR(double(hit.distance), L - this->kR - e, this->kGeneric);
  EXPECT_NEAR(double(hit.normal.x()), -1.0, this->kGeneric);
  EXPECT_EQ(this->answering->calls.load(), 0);  // asked, declined (only answers count)
}

TYPED_TEST(CustomCallbacks, SweepInitialOverlapWithMtdUsesThePenetrationCallback) {
  using T = TypeParam;
  for (const bool useAnswering : {true, false}) {
    const Geometry<T> ball = useAnswering ? CustomGeometry<T>(this->answering) : CustomGeometry<T>(this->plain);
    const double tol = useAnswering ? this->kExact : this->kGeneric;
    const double normalTol = useAnswering ? 10 * this->kExact : this->kGenericNormal;
    // Sphere centre 0.6 from the ball's: depth R + r - 0.6 = 0.5, escape direction along the centre offset.
    const Vec3<T> offset(T(0.36), T(0.48), T(0));
    SweepHit<T> hit;
    bool hasHit = false;
    ASSERT_TRUE(sweep(Vec3<T>(Vec3<T>::UnitZ()), T(1), this->sphere, Transform<T>(offset), ball, Transform<T>(), hit,
                      hasHit, kDefaultHitFlags | HitFlag::Mtd).ok());
    ASSERT_TRUE(hasHit);
    EXPECT_TRUE(hit.hadInitialOverlap());
    EXPECT_NEAR(double(hit.distance), -0.5, tol);
    EXPECT_NEAR(double((toL(hit.normal) - Vec3L(0.6L, 0.8L, 0)).norm()), 0.0, normalTol);
    // The sphere's deepest point: its support opposite to the escape direction.
    EXPECT_NEAR(double((toL(hit.position) - (toL(offset) - LD(this->kSphere) * Vec3L(0.6L, 0.8L, 0))).norm()), 0.0,
                normalTol);
  }
}

TYPED_TEST(CustomCallbacks, NonFiniteCallbackAnswerIsAnInternalErrorAndWritesNothing) {
  using T = TypeParam;
  const Geometry<T> ball = CustomGeometry<T>(std::make_shared<BrokenBall<T>>(T(this->kR)));
  PenetrationResult<T> r;
  r.depth = T(42);
  const Status s = computePenetration(r, ball, Transform<T>(), this->sphere, Transform<T>(Vec3<T>(T(0.5), T(0), T(0))));
  EXPECT_EQ(s.code, StatusCode::InternalError);
  EXPECT_NE(s.toString().find("ball"), std::string::npos);
  EXPECT_EQ(r.depth, T(42));
  DistanceResult<T> d;
  d.distance = T(42);
  const Status sd = distance(d, ball, Transform<T>(), this->sphere, Transform<T>(Vec3<T>(T(2), T(0), T(0))));
  EXPECT_EQ(sd.code, StatusCode::InternalError);
  EXPECT_NE(sd.toString().find("ball"), std::string::npos);
  EXPECT_EQ(d.distance, T(42));
}

}  // namespace
