// The checker's culling tests (plugins/urdf/src/cull_tests.h) and enclosing capsules: a cull may only answer
// "disjoint" when the volumes are. Exact answers in long double (stationary point and edges of the segment-parameter square).
#include <gtest/gtest.h>

#include <random>

#include "../../plugins/urdf/src/cull_tests.h"
#include "../../plugins/urdf/src/internal.h"
#include "gq/query.h"

namespace gq::urdf::test {
namespace {

using LD = long double;
using V = Eigen::Matrix<LD, 3, 1>;

// Distance from point q to segment p + t d, t in [0, 1].
LD pointSegmentDistance(const V& q, const V& p, const V& d) {
  const LD dd = d.squaredNorm();
  const LD t = dd > 0 ? std::clamp((q - p).dot(d) / dd, LD(0), LD(1)) : LD(0);
  return (p + t * d - q).norm();
}

// |p0 + s d0 - p1 - t d1| is convex in (s, t): its minimum over the unit square is at the interior stationary
// point (when the lines are not parallel and it lies inside) or on one of the four edges (point-segment distances).
LD exactSegmentDistance(const V& p0, const V& d0, const V& p1, const V& d1) {
  LD best = std::min({pointSegmentDistance(p0, p1, d1), pointSegmentDistance(V(p0 + d0), p1, d1),
                      pointSegmentDistance(p1, p0, d0), pointSegmentDistance(V(p1 + d1), p0, d0)});
  const V r = p0 - p1;
  const LD a = d0.squaredNorm(), b = d0.dot(d1), e = d1.squaredNorm(), c = d0.dot(r), f = d1.dot(r);
  const LD det = a * e - b * b;
  if (det > 0) {
    const LD s = (b * f - c * e) / det, t = (a * f - b * c) / det;
    if (s >= 0 && s <= 1 && t >= 0 && t <= 1) best = std::min(best, (p0 + s * d0 - p1 - t * d1).norm());
  }
  return best;
}

// The capsule tests add no widening for the segment distance: it must be within rounding (a few ulps of the
// coordinates' size) of the exact minimum, also for nearly parallel segments, where the two-clamp form with
// a e - b^2 was off by up to sqrt(eps) |d|.
template <class T> void expectSegmentDistanceWithinRounding(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  const double tilts[] = {1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12};
  // One draw per declarator: argument evaluation order is unspecified (GCC and clang differ).
  const auto vec = [&] {
    const double x = u(rng), y = u(rng), z = u(rng);
    return Vec3<T>(T(x), T(y), T(z));
  };
  for (int k = 0; k < 600; ++k) {
    Vec3<T> p0 = vec(), d0 = vec(), p1 = vec(), d1 = vec();
    if (k % 5 == 1) d1 = d0 * T(u(rng));  // parallel (or antiparallel)
    if (k % 5 == 2) d1 = d0 + T(tilts[(k / 5) % 6]) * vec();  // nearly parallel
    if (k % 5 == 3) d0.setZero();  // a point
    if (k % 5 == 4) {              // nearly parallel and overlapping along their length, a small gap apart
      d1 = -d0 + T(tilts[(k / 5) % 6]) * vec();
      p1 = p0 + d0 + T(0.01) * d0.cross(vec());
    }
    const LD exact = exactSegmentDistance(p0.template cast<LD>(), d0.template cast<LD>(), p1.template cast<LD>(),
                                          d1.template cast<LD>());
    const LD got = std::sqrt(LD(internal::segmentSquaredDistance(p0, d0, p1, d1)));
    const LD size = LD(p0.norm() + d0.norm() + p1.norm() + d1.norm());
    const LD rounding = 64 * LD(std::numeric_limits<T>::epsilon()) * size;  // well inside the checker's slack
    EXPECT_LE(got, exact + rounding) << k;
    EXPECT_GE(got, exact - rounding) << k;  // attained by a pair of points on the segments
  }
}

TEST(CullTests, SegmentDistanceIsWithinRoundingOfTheExactMinimumEvenForNearlyParallelSegmentsDouble) {
  expectSegmentDistanceWithinRounding<double>(3);
}

TEST(CullTests, SegmentDistanceIsWithinRoundingOfTheExactMinimumEvenForNearlyParallelSegmentsFloat) {
  expectSegmentDistanceWithinRounding<float>(4);
}

TEST(CullTests, CapsulesTouchingAlongTheirLengthAreNotCulled) {
  // Two parallel capsules of radius 0.1 whose axes are 0.2 apart touch along a whole segment.
  const Vec3<double> a(0, 0, 0), span(1, 0, 0), b(0.3, 0.2, 0);
  EXPECT_FALSE(internal::capsulesDisjoint(a, span, 0.1, b, span, 0.1 + 1e-15));
  EXPECT_TRUE(internal::capsulesDisjoint(a, span, 0.1, b, span, 0.0999));
}

// The box cull is core's box-box SAT with box b brought into box a's frame: on seeded oriented boxes it must answer
// "disjoint" exactly when gq::overlap (the façade, which frames the pair itself) answers no overlap.
template <class T> void expectBoxCullAgreesWithOverlap(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1), size(0.05, 0.6);
  int disjoint = 0, overlapping = 0;
  for (int k = 0; k < 2000; ++k) {
    OrientedBox<T> box[2];
    Transform<T> pose[2];
    for (int i = 0; i < 2; ++i) {
      const double qw = u(rng), qx = u(rng), qy = u(rng), qz = u(rng);
      const double cx = u(rng), cy = u(rng), cz = u(rng);
      const double hx = size(rng), hy = size(rng), hz = size(rng);
      pose[i] = Transform<T>(Vec3<T>(T(cx), T(cy), T(cz)), Quat<T>(T(qw), T(qx), T(qy), T(qz)).normalized());
      box[i].centre = pose[i].p;
      box[i].axes = pose[i].q.toRotationMatrix();
      box[i].halfExtents = Vec3<T>(T(hx), T(hy), T(hz));
    }
    bool hit = false;
    ASSERT_TRUE(gq::overlap<T>(BoxGeometry<T>(box[0].halfExtents), pose[0], BoxGeometry<T>(box[1].halfExtents),
                               pose[1], hit).ok());
    const bool culled = internal::orientedBoxesDisjoint(box[0], box[1]);
    EXPECT_EQ(culled, !hit) << k;
    (culled ? disjoint : overlapping) += 1;
  }
  EXPECT_GT(disjoint, 200);  // both answers are exercised
  EXPECT_GT(overlapping, 200);
}

TEST(CullTests, BoxCullAgreesWithTheBoxBoxOverlapQueryDouble) { expectBoxCullAgreesWithOverlap<double>(11); }

TEST(CullTests, BoxCullAgreesWithTheBoxBoxOverlapQueryFloat) { expectBoxCullAgreesWithOverlap<float>(12); }

TEST(CullTests, EnclosingCapsuleContainsEveryPoint) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec3<double>> points;
  for (int k = 0; k < 500; ++k) {
    const double x = u(rng), y = u(rng), z = u(rng);
    points.emplace_back(0.8 * x, 0.2 * y + 0.3, 0.1 * z);
  }
  Vec3<double> mean;
  const internal::EnclosingCapsule c = internal::enclosingCapsule(points, internal::principalAxes(points, mean), 0.0);
  double worst = -1;
  for (const auto& p : points) {
    const Vec3<double> start = c.centre - c.halfHeight * c.axis;
    const double s = std::clamp((p - start).dot(c.axis), 0.0, 2 * c.halfHeight);
    worst = std::max(worst, (p - start - s * c.axis).norm() - c.radius);
  }
  EXPECT_LE(worst, 1e-12);
  EXPECT_GT(c.halfHeight, 0.5);  // along the long (x) extent
}

}  // namespace
}  // namespace gq::urdf::test
