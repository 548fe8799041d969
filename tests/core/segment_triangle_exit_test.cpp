// segmentTriangleExit (the push of spheres and capsules off mesh triangles): the least translation that takes a
// segment off a triangle it touches. The exit along a unit u is max(tri . u) - min(seg . u); the true minimum over
// all u is approached here by brute force over 50,000 directions, which can only overestimate it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "mesh/triangle.h"
#include "mesh_pairs/triangle_tests.h"

namespace {

using V = gq::Vec3<double>;
using Tri = gq::Triangle<double>;

double exitAlong(const V& p, const V& q, const Tri& t, const V& u) {
  const double hi = std::max({t.verts[0].dot(u), t.verts[1].dot(u), t.verts[2].dot(u)});
  return hi - std::min(p.dot(u), q.dot(u));
}

std::vector<V> fibonacciDirections(int n) {
  std::vector<V> dirs;
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / n, r = std::sqrt(1.0 - z * z), phi = 2.399963229728653 * i;
    dirs.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
  }
  return dirs;
}

TEST(SegmentTriangleExit, IsTheLeastExitOverAllDirectionsForSegmentsCrossingOrLyingOnTheTriangle) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  // One draw per declarator: argument evaluation order is unspecified (GCC and clang differ).
  const auto randomVec = [&] {
    const double x = u(rng), y = u(rng), z = u(rng);
    return V(x, y, z);
  };
  const std::vector<V> dirs = fibonacciDirections(50000);
  double worstGap = 0.0;
  for (int k = 0; k < 100; ++k) {
    Tri t;
    for (auto& v : t.verts) v = randomVec();
    double a = std::abs(u(rng)), b = std::abs(u(rng));
    if (a + b > 1.0) a = 1.0 - a, b = 1.0 - b;
    const V x = t.verts[0] + a * (t.verts[1] - t.verts[0]) + b * (t.verts[2] - t.verts[0]);  // on the triangle
    V d = randomVec();
    if (k % 2) {  // every other segment lies in the triangle's plane (a capsule resting on a face)
      const V n = (t.verts[1] - t.verts[0]).cross(t.verts[2] - t.verts[0]).normalized();
      d -= n * n.dot(d);
    }
    const V p = x + (u(rng) * 0.5 - 0.5) * d, q = x + (u(rng) * 0.5 + 0.5) * d;
    const gq::detail::SegmentTriangleExit<double> e = gq::detail::segmentTriangleExit<double>(p, q, t, nullptr);
    double brute = std::numeric_limits<double>::infinity();
    for (const V& dir : dirs) brute = std::min(brute, exitAlong(p, q, t, dir));
    EXPECT_NEAR(e.direction.norm(), 1.0, 1e-12);
    EXPECT_NEAR(exitAlong(p, q, t, e.direction), e.exit, 1e-12) << "case " << k;  // the exit it reports is real
    EXPECT_LE(e.exit, brute + 1e-12) << "case " << k;                              // and no direction beats it
    worstGap = std::max(worstGap, brute - e.exit);
  }
  EXPECT_LT(worstGap, 0.02);  // the brute force's direction grid
}

TEST(SegmentTriangleExit, ADisjointSegmentWithItsClosestPointDirectionExitsByMinusTheDistance) {
  Tri t;
  t.verts[0] = V(0, 0, 0);
  t.verts[1] = V(2, 0, 0);
  t.verts[2] = V(0, 2, 0);
  const V p(0.5, 0.5, 0.3), q(-1.0, 0.5, 0.3);  // above the face at height 0.3
  const V up(0, 0, 1);
  const gq::detail::SegmentTriangleExit<double> e = gq::detail::segmentTriangleExit(p, q, t, &up);
  EXPECT_NEAR(e.exit, -0.3, 1e-15);
  EXPECT_NEAR(e.direction.z(), 1.0, 1e-15);
}

}  // namespace
