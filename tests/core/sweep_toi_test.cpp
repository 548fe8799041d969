// Sweep accuracy (the spec's sweep rule "time of impact within 1e-7 * size of the exact one"): seeded cases per
// (swept, target) pair of sphere, capsule, box and convex mesh, checked against the exact distance in long double
// (sweep_reference.h). With d(t) the exact signed distance after moving the swept shape by t * dir (convex in t):
//  - a reported hit at t is touching: |d(t)| <= kTouch;
//  - nothing overlaps before it: d(t - tol) > 0 and d decreases there (by convexity, d > 0 on all of [0, t - tol]);
//  - it is not late: d(t + tol) <= 0, or else the exact first root (bisection) is within tol of t;
//  - a reported miss is a miss: the minimum of d over [0, maxDist] (golden section) is > 0, or the exact first root
//    is within tol of maxDist;
//  - an exact initial overlap (d(0) <= 0) is reported as hadInitialOverlap.
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <random>

#include "gq/cooking.h"
#include "gq/query.h"
#include "sweep_reference.h"

namespace {

using namespace gq;
using sweeptest::L;
using sweeptest::VL;

template <class T> struct SweepToi : ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(SweepToi, Scalars);

// Shapes have sizes in [0.2, 0.8] and sit within 3 units of the origin: tolerances are relative to a unit size.
// float carries 24 bits on coordinates of magnitude ~4 (about 5e-7), and GJK's float tolerance is 16 ulps.
template <class T> constexpr double kToiTol = std::is_same_v<T, double> ? 1e-7 : 2e-4;
template <class T> constexpr double kTouch = std::is_same_v<T, double> ? 1e-9 : 1e-4;
template <class T> constexpr int kCasesPerPair = std::is_same_v<T, double> ? 1000 : 250;

// Three draws of d in order, one per declarator: argument evaluation order is unspecified (GCC and clang differ).
template <class Distribution> Eigen::Vector3d draw3(Distribution& d, std::mt19937_64& gen) {
  const double x = d(gen), y = d(gen), z = d(gen);
  return {x, y, z};
}

template <class T> std::shared_ptr<const ConvexMesh<T>> randomHull(std::mt19937_64& gen) {
  std::normal_distribution<double> n;
  std::uniform_real_distribution<double> u(0.3, 0.8);
  const Eigen::Vector3d radii = draw3(u, gen);
  std::vector<Vec3<T>> pts;
  for (int i = 0; i < 9; ++i) pts.push_back(draw3(n, gen).normalized().cwiseProduct(radii).cast<T>());
  std::shared_ptr<const ConvexMesh<T>> mesh;
  EXPECT_TRUE(cookConvexMesh(pts, mesh).ok());
  return mesh;
}

template <class T> Geometry<T> randomShape(GeometryType type, std::mt19937_64& gen) {
  std::uniform_real_distribution<double> u(0.2, 0.7);
  switch (type) {
    case GeometryType::Sphere: return SphereGeometry<T>(T(u(gen)));
    case GeometryType::Capsule: {
      const double radius = u(gen) * 0.6;
      return CapsuleGeometry<T>(T(radius), T(u(gen)));
    }
    case GeometryType::Box: return BoxGeometry<T>(draw3(u, gen).cast<T>());
    default: return ConvexMeshGeometry<T>(randomHull<T>(gen));
  }
}

template <class T> Transform<T> randomPose(std::mt19937_64& gen, double spread) {
  std::uniform_real_distribution<double> u(-spread, spread);
  std::normal_distribution<double> n;
  const double w = n(gen), x = n(gen), y = n(gen), z = n(gen);
  const Eigen::Quaterniond q(w, x, y, z);
  return Transform<T>(draw3(u, gen).cast<T>(), q.normalized().cast<T>());
}

struct PairStats {
  int hits = 0, misses = 0, overlaps = 0, bisections = 0;
  double maxLate = 0;  // largest t - exact root seen when the root had to be bisected
};

template <class T> struct CaseChecker {
  const sweeptest::Core& A;
  const sweeptest::Core& B;
  VL dir;
  L maxDist;
  int index;
  PairStats& st;

  L d(L t) const { return sweeptest::shapeDistance(A.moved(t * dir), B); }

  void checkHit(const SweepHit<T>& hit, const Vec3<T>& unitDir) {
    const L tol = kToiTol<T>, t = L(hit.distance);
    EXPECT_LE(std::abs(double(d(t))), kTouch<T>) << "case " << index << ": not touching at the reported distance " << double(t);
    if (t > tol) {
      const L before = d(t - tol);
      EXPECT_GT(double(before), 0.0) << "case " << index << ": overlapping before the reported distance " << double(t);
      EXPECT_LT(double(d(t)), double(before)) << "case " << index << ": distance not decreasing at the hit";
    }
    if (!(d(t + tol) <= 0)) {  // grazing contact, or late: compare with the exact root
      ++st.bisections;
      const L exact = sweeptest::exactToi(A, B, dir, maxDist, tol / 16);
      if (exact >= 0) {
        st.maxLate = std::max(st.maxLate, double(t - exact));
        // float stops at a touching distance of up to kTouch, which costs kTouch / closing speed in TOI on grazing
        // hits; double is held to the plain 1e-7.
        const double closing = std::max(1e-3, -double(hit.normal.dot(unitDir)));
        const double allowed = double(tol) + (std::is_same_v<T, float> ? kTouch<T> / closing : 0.0);
        EXPECT_LE(std::abs(double(t - exact)), allowed) << "case " << index << " exact " << double(exact) << " got " << double(t);
      }
    }
    EXPECT_TRUE(hit.flags.has(HitFlag::Normal) && hit.flags.has(HitFlag::Position));
    EXPECT_NEAR(double(hit.normal.norm()), 1.0, 1e-5);
    EXPECT_LT(double(hit.normal.dot(unitDir)), 0.0) << "case " << index;
    // The position is a touching point: on the target's surface.
    sweeptest::Core point;
    point.v = {sweeptest::toL(hit.position)};
    EXPECT_LE(std::abs(double(sweeptest::shapeDistance(point, B))), 10 * double(tol)) << "case " << index;
  }

  void checkMiss() {
    const auto [fmin, tmin] = sweeptest::minimumAlong(A, B, dir, L(0), maxDist, 50);
    if (fmin > 0) return;
    const L exact = sweeptest::exactToi(A, B, dir, maxDist, L(kToiTol<T>) / 16);
    EXPECT_GE(double(exact), double(maxDist) - kToiTol<T>) << "case " << index << ": missed a hit at " << double(exact)
                                                          << " (min distance " << double(fmin) << " at " << double(tmin) << ")";
  }
};

// Runs seeded sweeps of `swept` against `target`, each checked against the exact distance.
template <class T> PairStats checkPair(GeometryType swept, GeometryType target, std::uint64_t seed) {
  std::mt19937_64 gen(seed);
  std::normal_distribution<double> n;
  PairStats st;
  const T maxDist = T(5);
  for (int i = 0; i < kCasesPerPair<T>; ++i) {
    const Geometry<T> g0 = randomShape<T>(swept, gen), g1 = randomShape<T>(target, gen);
    const Transform<T> p0 = randomPose<T>(gen, 2.0), p1 = randomPose<T>(gen, 0.5);
    // Aim near the target: most sweeps hit, some graze past or miss.
    const Eigen::Vector3d aim = (p1.p - p0.p).template cast<double>() + 0.35 * draw3(n, gen);
    const Vec3<T> dir = aim.normalized().cast<T>();
    SweepHit<T> hit;
    bool hasHit = false;
    EXPECT_TRUE(sweep(dir, maxDist, g0, p0, g1, p1, hit, hasHit).ok());
    const sweeptest::Core A = sweeptest::coreOf(g0, p0), B = sweeptest::coreOf(g1, p1);
    CaseChecker<T> check{A, B, sweeptest::toL(dir), L(maxDist), i, st};
    if (check.d(0) <= 0) {
      ++st.overlaps;
      EXPECT_TRUE(hasHit && hit.hadInitialOverlap()) << "case " << i;
    } else if (hasHit && !hit.hadInitialOverlap()) {
      ++st.hits;
      check.checkHit(hit, dir);
    } else if (hasHit) {  // reported initial overlap: must be touching within the tolerance
      ++st.overlaps;
      EXPECT_LE(double(check.d(0)), kTouch<T>) << "case " << i << ": initial overlap reported on separated shapes";
    } else {
      ++st.misses;
      check.checkMiss();
    }
  }
  return st;
}

template <class T> void checkAllSwept(GeometryType target, std::uint64_t seed) {
  int misses = 0;
  for (GeometryType swept : {GeometryType::Sphere, GeometryType::Capsule, GeometryType::Box, GeometryType::ConvexMesh}) {
    const PairStats st = checkPair<T>(swept, target, seed + 17 * std::uint64_t(swept));
    EXPECT_GT(st.hits, kCasesPerPair<T> / 2);
    misses += st.misses;
    std::printf("[sweep toi] %s %s vs %s: %d hits, %d misses, %d initial overlaps, %d bisected (max late %.3g)\n",
                std::is_same_v<T, double> ? "double" : "float", toString(swept), toString(target), st.hits, st.misses,
                st.overlaps, st.bisections, st.maxLate);
  }
  EXPECT_GT(misses, 0);  // the miss branch is exercised
}

TYPED_TEST(SweepToi, TimeOfImpactMatchesExactAgainstSphere) { checkAllSwept<TypeParam>(GeometryType::Sphere, 101); }
TYPED_TEST(SweepToi, TimeOfImpactMatchesExactAgainstCapsule) { checkAllSwept<TypeParam>(GeometryType::Capsule, 202); }
TYPED_TEST(SweepToi, TimeOfImpactMatchesExactAgainstBox) { checkAllSwept<TypeParam>(GeometryType::Box, 303); }
TYPED_TEST(SweepToi, TimeOfImpactMatchesExactAgainstConvex) { checkAllSwept<TypeParam>(GeometryType::ConvexMesh, 404); }

}  // namespace
