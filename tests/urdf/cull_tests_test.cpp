// The checker's culling tests (plugins/urdf/src/cull_tests.h) and enclosing capsules: a cull may only answer
// "disjoint" when the volumes are. Exact answers in long double (stationary point and edges of the segment-parameter square).
#include <gtest/gtest.h>

#include <random>

#include "../../plugins/urdf/src/cull_tests.h"
#include "../../plugins/urdf/src/internal.h"

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

TEST(CullTests, SegmentDistanceMatchesExactMinimumIncludingParallelAndDegenerateSegments) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 300; ++k) {
    Vec3<double> p0(u(rng), u(rng), u(rng)), d0(u(rng), u(rng), u(rng)), p1(u(rng), u(rng), u(rng)),
        d1(u(rng), u(rng), u(rng));
    if (k % 5 == 1) d1 = d0 * u(rng);                // parallel (or antiparallel)
    if (k % 5 == 2) d1 = d0 + 1e-9 * Vec3<double>(u(rng), u(rng), u(rng));  // nearly parallel
    if (k % 5 == 3) d0.setZero();                     // a point
    const LD exact = exactSegmentDistance(p0.cast<LD>(), d0.cast<LD>(), p1.cast<LD>(), d1.cast<LD>());
    const double got = std::sqrt(detail::segmentSquaredDistance(p0, d0, p1, d1));
    // Never farther than the closest pair by more than the bound the checker adds to capsule radii.
    const double bound = 4 * std::sqrt(std::numeric_limits<double>::epsilon()) * (d0.norm() + d1.norm()) + 1e-12;
    EXPECT_LE(got, double(exact) + bound) << k;
    EXPECT_GE(got, double(exact) - 1e-12) << k;  // attained by a pair of points on the segments
  }
}

TEST(CullTests, CapsulesTouchingAlongTheirLengthAreNotCulled) {
  // Two parallel capsules of radius 0.1 whose axes are 0.2 apart touch along a whole segment.
  const Vec3<double> a(0, 0, 0), span(1, 0, 0), b(0.3, 0.2, 0);
  EXPECT_FALSE(detail::capsulesDisjoint(a, span, 0.1, b, span, 0.1 + 1e-15));
  EXPECT_TRUE(detail::capsulesDisjoint(a, span, 0.1, b, span, 0.0999));
}

TEST(CullTests, EnclosingCapsuleContainsEveryPoint) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec3<double>> points;
  for (int k = 0; k < 500; ++k) points.emplace_back(0.8 * u(rng), 0.2 * u(rng) + 0.3, 0.1 * u(rng));
  Vec3<double> mean;
  const detail::EnclosingCapsule c = detail::enclosingCapsule(points, detail::principalAxes(points, mean), 0.0);
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
