// The pieces of a contact set (core/src/contacts): clipping an incident feature to a reference face, float and
// double. A box face clipped in its own 2D frame gives the general polygon clip's points; a rectangle over a
// triangle keeps the triangle's part of it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "contacts/contact_features.h"

namespace {

using namespace gq;
using detail::Feature;

template <class T> struct ContactSetClipping : ::testing::Test {
  static constexpr double kTol = std::is_same_v<T, double> ? 1e-12 : 2e-5;
};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(ContactSetClipping, Scalars);

TYPED_TEST(ContactSetClipping, BoxFaceClippedInItsFrameMatchesThePolygonClip) {
  using T = TypeParam;
  using V3 = Vec3<T>;
  const Geometry<T> box = BoxGeometry<T>(V3(T(0.5), T(0.3), T(0.7)));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 200; ++trial) {
    const Quat<T> q = Quat<T>(T(u(rng)), T(u(rng)), T(u(rng)), T(u(rng))).normalized();
    const Transform<T> pose(V3(T(u(rng)), T(u(rng)), T(u(rng))), q);
    const V3 dir = q * V3(0, 1, 0);
    Feature<T> face;
    ASSERT_TRUE(detail::referenceFace(box, pose, dir, face));
    ASSERT_TRUE(face.rectangle);
    Feature<T> polygon = face;
    polygon.rectangle = false;
    // An incident quad (or segment) around the face, on a plane tilted a little off it (a real incident face is
    // planar; the clipped corners of a warped quad depend on the order the edges are clipped in).
    const T tiltU = T(0.05 * u(rng)), tiltW = T(0.05 * u(rng));
    Feature<T> a;
    a.count = trial % 3 == 0 ? 2 : 4;
    const V3 c = face.centre + face.u * T(0.4 * u(rng)) + face.w * T(0.4 * u(rng));
    const T angle = T(3 * u(rng));
    for (int k = 0; k < a.count; ++k) {
      const T t = angle + T(k) * T(EIGEN_PI / 2);
      const T x = std::cos(t) * T(0.6), y = std::sin(t) * T(0.6);
      a.points[k] = c + face.u * x + face.w * y + face.normal * (tiltU * x + tiltW * y);
    }
    Feature<T> b = a;
    detail::clipToFace(face, a);
    detail::clipToFace(polygon, b);
    ASSERT_EQ(a.count, b.count) << "trial " << trial;
    // The same points (the two clips visit the edges in different orders, so the polygons start elsewhere).
    for (int k = 0; k < a.count; ++k) {
      double nearest = std::numeric_limits<double>::max();
      for (int m = 0; m < b.count; ++m) nearest = std::min(nearest, double((a.points[k] - b.points[m]).norm()));
      EXPECT_LT(nearest, this->kTol * 10) << "trial " << trial << " point " << k;
    }
  }
}

// One side plane per edge (Sutherland-Hodgman). Three edges, so the clip's last pass leaves its polygon in the
// scratch buffer and copies it back; a square face (four passes) does not.
TYPED_TEST(ContactSetClipping, ClippingKeepsTheIncidentPolygonOverTheReferenceFace) {
  using T = TypeParam;
  using V3 = Vec3<T>;
  Feature<T> triangle;
  triangle.count = 3;
  triangle.points[0] = V3(0, 0, 0);
  triangle.points[1] = V3(2, 0, 0);
  triangle.points[2] = V3(0, 2, 0);
  triangle.normal = V3(0, 0, 1);
  triangle.origin = triangle.points[0];
  const auto rectangle = [](T xlo, T ylo, T hi) {
    Feature<T> f;
    f.count = 4;
    f.points[0] = V3(xlo, ylo, T(0.1));
    f.points[1] = V3(hi, ylo, T(0.1));
    f.points[2] = V3(hi, hi, T(0.1));
    f.points[3] = V3(xlo, hi, T(0.1));
    return f;
  };
  const auto square = [&](T lo, T hi) { return rectangle(lo, lo, hi); };
  // x >= 0 (the last edge clips too), y >= 0.5 and x + y <= 2: the triangle (0, 0.5), (1.5, 0.5), (0, 2).
  Feature<T> incident = rectangle(T(-1), T(0.5), T(3));
  ASSERT_EQ(detail::clipToFace(triangle, incident), 3);
  ASSERT_EQ(incident.count, 3);
  for (const V3& expected : {V3(T(0), T(0.5), T(0.1)), V3(T(1.5), T(0.5), T(0.1)), V3(T(0), T(2), T(0.1))}) {
    bool found = false;
    for (int i = 0; i < incident.count; ++i) found = found || (incident.points[i] - expected).norm() < T(1e-4);
    EXPECT_TRUE(found) << expected.transpose();
  }
  // A square reference face over a larger square keeps its own outline.
  Feature<T> reference = square(T(0), T(1));
  reference.normal = V3(0, 0, 1);
  reference.origin = reference.points[0];
  Feature<T> big = square(T(-1), T(2));
  ASSERT_EQ(detail::clipToFace(reference, big), 4);
  for (int i = 0; i < big.count; ++i) {
    EXPECT_NEAR(std::min(std::abs(double(big.points[i].x())), std::abs(double(big.points[i].x()) - 1)), 0, 1e-5);
    EXPECT_NEAR(std::min(std::abs(double(big.points[i].y())), std::abs(double(big.points[i].y()) - 1)), 0, 1e-5);
  }
  // Entirely outside: nothing left.
  Feature<T> away = square(T(5), T(6));
  EXPECT_EQ(detail::clipToFace(triangle, away), 0);
  EXPECT_EQ(away.count, 0);
}

// Reduction: the deepest point first, then the largest spread; everything when it fits.
TYPED_TEST(ContactSetClipping, ReductionKeepsTheDeepestAndTheLargestArea) {
  using T = TypeParam;
  using V3 = Vec3<T>;
  // A regular octagon of radius 1; point 3 is the deepest.
  std::array<V3, 8> p;
  std::array<T, 8> s;
  for (int k = 0; k < 8; ++k) {
    p[k] = V3(T(std::cos(k * EIGEN_PI / 4)), T(std::sin(k * EIGEN_PI / 4)), T(0));
    s[k] = k == 3 ? T(-0.2) : T(-0.1);
  }
  std::array<int, 8> keep;
  ASSERT_EQ(detail::reduceContactPoints(p.data(), s.data(), 8, V3(0, 0, 1), 4, keep.data()), 4);
  EXPECT_EQ(keep[0], 3);
  EXPECT_EQ(keep[1], 7);  // opposite the deepest
  // The other two are the farthest from that diameter on each side (1 and 5).
  EXPECT_TRUE((keep[2] == 1 || keep[2] == 5) && (keep[3] == 1 || keep[3] == 5) && keep[2] != keep[3]);
  ASSERT_EQ(detail::reduceContactPoints(p.data(), s.data(), 8, V3(0, 0, 1), 1, keep.data()), 1);
  EXPECT_EQ(keep[0], 3);
  ASSERT_EQ(detail::reduceContactPoints(p.data(), s.data(), 3, V3(0, 0, 1), 4, keep.data()), 3);
}

}  // namespace
