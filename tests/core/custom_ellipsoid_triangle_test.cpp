// Ellipsoid and Triangle custom shapes (gq/custom_shapes.h): raycasts, bounds and support points against closed
// forms worked in long double, the factories' rejections, and the queries that run through the support mapping.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "gq/custom_shapes.h"
#include "gq/query.h"

namespace {

using namespace gq;
using LD = long double;

template <class T> struct EllipsoidTriangle : ::testing::Test {
  static constexpr double kTol = std::is_same_v<T, double> ? 1e-12 : 2e-6;
};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(EllipsoidTriangle, Scalars);

// GJK's answers (the support-mapped queries): its relative tolerance, not rounding.
template <class T> constexpr double gjkTol() { return std::is_same_v<T, float> ? 1e-4 : 1e-7; }

template <class T> RaycastHit<T> localRay(const CustomGeometryCallbacks<T>& c, const Vec3<T>& o, const Vec3<T>& d,
                                          bool& hit, T maxDist = T(100)) {
  RaycastHit<T> h;
  hit = c.raycast(o, d, maxDist, kDefaultHitFlags | HitFlag::UV, h);
  return h;
}

// The entry distance of the ray o + t d into x^2/a^2 + y^2/b^2 + z^2/c^2 <= 1, solved in long double.
inline LD ellipsoidEntry(const LD (&r)[3], const LD (&o)[3], const LD (&d)[3]) {
  LD a = 0, b = 0, c = -1;
  for (int i = 0; i < 3; ++i) {
    a += d[i] * d[i] / (r[i] * r[i]);
    b += o[i] * d[i] / (r[i] * r[i]);
    c += o[i] * o[i] / (r[i] * r[i]);
  }
  return (-b - std::sqrt(b * b - a * c)) / a;
}

TYPED_TEST(EllipsoidTriangle, EllipsoidRaycastEntersAtTheRootOfItsQuadratic) {
  using T = TypeParam;
  const EllipsoidCallbacks<T> e(Vec3<T>(T(2), T(0.5), T(1.25)));
  const LD radii[3] = {2, 0.5L, 1.25L};
  std::mt19937_64 gen(7);
  std::normal_distribution<double> n;
  std::uniform_real_distribution<double> u(-0.9, 0.9);
  for (int i = 0; i < 200; ++i) {
    // A target point inside, an origin 6 away from it along a random direction: the ray must enter.
    const Vec3<T> target(T(2 * u(gen)) * T(0.5), T(0.5 * u(gen)) * T(0.5), T(1.25 * u(gen)) * T(0.5));
    Vec3<T> dir(T(n(gen)), T(n(gen)), T(n(gen)));
    dir.normalize();
    const Vec3<T> origin = target - T(6) * dir;
    bool hit = false;
    const RaycastHit<T> h = localRay<T>(e, origin, dir, hit);
    ASSERT_TRUE(hit) << i;
    const LD o[3] = {origin.x(), origin.y(), origin.z()}, d[3] = {dir.x(), dir.y(), dir.z()};
    const LD t = ellipsoidEntry(radii, o, d);
    EXPECT_NEAR(double(h.distance), double(t), this->kTol * 10) << i;
    // The normal is the gradient (x/a^2, y/b^2, z/c^2) at the entry point, normalised.
    LD g[3], len = 0;
    for (int k = 0; k < 3; ++k) {
      g[k] = (o[k] + t * d[k]) / (radii[k] * radii[k]);
      len += g[k] * g[k];
    }
    len = std::sqrt(len);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(double(h.normal[k]), double(g[k] / len), this->kTol * 100) << i;
    EXPECT_TRUE(h.flags.has(HitFlag::Position) && h.flags.has(HitFlag::Normal));
  }
}

TYPED_TEST(EllipsoidTriangle, EllipsoidRaycastMissesPastTheRimAndReportsAnInsideOriginAtZero) {
  using T = TypeParam;
  const EllipsoidCallbacks<T> e(Vec3<T>(T(2), T(1), T(1)));
  bool hit = true;
  // Along -X at height y = 1.001 (just beyond the rim y = 1) misses; at y = 0.999 it hits.
  localRay<T>(e, Vec3<T>(T(5), T(1.001), T(0)), Vec3<T>(T(-1), T(0), T(0)), hit);
  EXPECT_FALSE(hit);
  const RaycastHit<T> grazing = localRay<T>(e, Vec3<T>(T(5), T(0.6), T(0)), Vec3<T>(T(-1), T(0), T(0)), hit);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(double(grazing.distance), 5.0 - 2.0 * 0.8, this->kTol * 10);  // x = 2 sqrt(1 - 0.36) = 1.6
  // Pointing away, and too short.
  localRay<T>(e, Vec3<T>(T(5), T(0), T(0)), Vec3<T>(T(1), T(0), T(0)), hit);
  EXPECT_FALSE(hit);
  localRay<T>(e, Vec3<T>(T(5), T(0), T(0)), Vec3<T>(T(-1), T(0), T(0)), hit, T(2.9));
  EXPECT_FALSE(hit);
  const RaycastHit<T> inside = localRay<T>(e, Vec3<T>(T(0.5), T(0.2), T(0)), Vec3<T>(T(0), T(0), T(1)), hit);
  ASSERT_TRUE(hit);
  EXPECT_EQ(inside.distance, T(0));
  EXPECT_EQ(inside.normal, Vec3<T>(T(0), T(0), T(-1)));
}

TYPED_TEST(EllipsoidTriangle, EllipsoidSupportIsTheTangentPointAndBoundsAreTheRadii) {
  using T = TypeParam;
  const Vec3<T> r(T(3), T(0.25), T(1.5));
  const EllipsoidCallbacks<T> e(r);
  const Bounds3<T> b = e.localBounds();
  EXPECT_EQ(b.min, Vec3<T>(-r));
  EXPECT_EQ(b.max, r);
  std::mt19937_64 gen(3);
  std::normal_distribution<double> n;
  for (int i = 0; i < 100; ++i) {
    const LD d[3] = {n(gen), n(gen), n(gen)};
    // Any positive multiple of d, tiny or huge, has the same support point: D^2 d / |D d|.
    for (const double scale : {1e-30, 1.0, 1e30}) {
      const Vec3<T> dir(T(d[0] * scale), T(d[1] * scale), T(d[2] * scale));
      if (!isFinite(dir) || dir.cwiseAbs().maxCoeff() == T(0)) continue;
      const Vec3<T> s = e.support(dir);
      const LD rr[3] = {3, 0.25L, 1.5L};
      LD norm = 0;
      for (int k = 0; k < 3; ++k) norm += (rr[k] * LD(dir[k])) * (rr[k] * LD(dir[k]));
      norm = std::sqrt(norm);
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(double(s[k]), double(rr[k] * rr[k] * LD(dir[k]) / norm), this->kTol * 10) << i << " " << scale;
    }
  }
  EXPECT_EQ(e.support(Vec3<T>::Zero()), Vec3<T>(r.x(), T(0), T(0)));  // any boundary point will do; this one
}

TYPED_TEST(EllipsoidTriangle, EllipsoidQueriesRunThroughItsSupportMapping) {
  using T = TypeParam;
  CustomGeometry<T> e;
  ASSERT_TRUE(makeEllipsoid(Vec3<T>(T(2), T(1), T(1)), e).ok());
  EXPECT_STREQ(e.callbacks->name(), "ellipsoid");
  // A unit sphere at x = 3.5 is 0.5 beyond the ellipsoid's tip x = 2.
  DistanceResult<T> d;
  ASSERT_TRUE(distance<T>(d, e, Transform<T>(), SphereGeometry<T>(1), Transform<T>(Vec3<T>(T(3.5), 0, 0))).ok());
  EXPECT_NEAR(double(d.distance), 0.5, gjkTol<T>());
  EXPECT_NEAR(double(d.point0.x()), 2.0, 10 * gjkTol<T>());
  bool overlapping = true;
  ASSERT_TRUE(overlap<T>(e, Transform<T>(), SphereGeometry<T>(1), Transform<T>(Vec3<T>(T(3.5), 0, 0)), overlapping).ok());
  EXPECT_FALSE(overlapping);
  ASSERT_TRUE(overlap<T>(e, Transform<T>(), SphereGeometry<T>(1), Transform<T>(Vec3<T>(T(2.9), 0, 0)), overlapping).ok());
  EXPECT_TRUE(overlapping);
  Bounds3<T> world;
  ASSERT_TRUE(computeGeomBounds<T>(world, e, Transform<T>(Vec3<T>(T(1), T(2), T(3))), T(0), T(1)).ok());
  EXPECT_NEAR(double(world.min.x()), -1.0, 1e-6);
  EXPECT_NEAR(double(world.max.z()), 4.0, 1e-6);
}

TYPED_TEST(EllipsoidTriangle, MakeEllipsoidRejectsNonPositiveAndNonFiniteRadii) {
  using T = TypeParam;
  CustomGeometry<T> out;
  const T inf = std::numeric_limits<T>::infinity(), nan = std::numeric_limits<T>::quiet_NaN();
  for (const Vec3<T>& r : {Vec3<T>(0, 1, 1), Vec3<T>(1, -1, 1), Vec3<T>(1, 1, inf), Vec3<T>(nan, 1, 1)}) {
    const Status s = makeEllipsoid(r, out);
    EXPECT_EQ(s.code, StatusCode::InvalidArgument) << r.transpose();
    EXPECT_EQ(out.callbacks, nullptr);  // untouched
  }
}

// Triangle (0,0,0), (2,0,0), (0,2,0) lifted to z = 1.
template <class T> TriangleCallbacks<T> liftedTriangle() {
  return TriangleCallbacks<T>(Vec3<T>(0, 0, 1), Vec3<T>(2, 0, 1), Vec3<T>(0, 2, 1));
}

TYPED_TEST(EllipsoidTriangle, TriangleRaycastHitsEitherFaceWithTheBarycentricWeights) {
  using T = TypeParam;
  const TriangleCallbacks<T> tri = liftedTriangle<T>();
  bool hit = false;
  // From below, up +Z at (0.5, 0.25): distance 3, normal -Z (against the ray), u = x/2, v = y/2.
  RaycastHit<T> h = localRay<T>(tri, Vec3<T>(T(0.5), T(0.25), T(-2)), Vec3<T>(0, 0, 1), hit);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(double(h.distance), 3.0, this->kTol);
  EXPECT_EQ(h.normal, Vec3<T>(0, 0, -1));
  EXPECT_NEAR(double(h.u), 0.25, this->kTol);
  EXPECT_NEAR(double(h.v), 0.125, this->kTol);
  EXPECT_TRUE(h.flags.has(HitFlag::UV));
  // From above, down: normal +Z.
  h = localRay<T>(tri, Vec3<T>(T(0.5), T(0.25), T(4)), Vec3<T>(0, 0, -1), hit);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(double(h.distance), 3.0, this->kTol);
  EXPECT_EQ(h.normal, Vec3<T>(0, 0, 1));
  EXPECT_NEAR((h.position - Vec3<T>(T(0.5), T(0.25), T(1))).norm(), 0.0, this->kTol);
  // An oblique ray through (1, 0.5, 1), the closed form of its parameter: |(1, 0.5, 1) - o|.
  const Vec3<T> o(T(-1), T(-1.5), T(3)), target(T(1), T(0.5), T(1));
  h = localRay<T>(tri, o, Vec3<T>((target - o).normalized()), hit);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(double(h.distance), std::sqrt(12.0), this->kTol * 10);
  // Misses: beyond the hypotenuse x + y = 2, beside the triangle, pointing away, too short.
  localRay<T>(tri, Vec3<T>(T(1.01), T(1), T(0)), Vec3<T>(0, 0, 1), hit);
  EXPECT_FALSE(hit);
  localRay<T>(tri, Vec3<T>(T(-0.01), T(1), T(0)), Vec3<T>(0, 0, 1), hit);
  EXPECT_FALSE(hit);
  localRay<T>(tri, Vec3<T>(T(0.5), T(0.5), T(0)), Vec3<T>(0, 0, -1), hit);
  EXPECT_FALSE(hit);
  localRay<T>(tri, Vec3<T>(T(0.5), T(0.5), T(0)), Vec3<T>(0, 0, 1), hit, T(0.99));
  EXPECT_FALSE(hit);
}

TYPED_TEST(EllipsoidTriangle, TriangleRaycastInItsPlaneEntersThroughAnEdge) {
  using T = TypeParam;
  const TriangleCallbacks<T> tri = liftedTriangle<T>();
  bool hit = false;
  // In the plane z = 1, along +X from x = -3 at y = 0.5: enters through the edge x = 0 (outward normal -X).
  RaycastHit<T> h = localRay<T>(tri, Vec3<T>(T(-3), T(0.5), T(1)), Vec3<T>(1, 0, 0), hit);
  ASSERT_TRUE(hit);
  EXPECT_EQ(h.distance, T(3));
  EXPECT_EQ(h.normal, Vec3<T>(-1, 0, 0));
  // Along -X from x = 5 at y = 0.5: enters through the hypotenuse at x = 1.5, normal (1, 1)/sqrt 2.
  h = localRay<T>(tri, Vec3<T>(T(5), T(0.5), T(1)), Vec3<T>(-1, 0, 0), hit);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(double(h.distance), 3.5, this->kTol);
  EXPECT_NEAR(double(h.normal.x()), std::sqrt(0.5), this->kTol);
  EXPECT_NEAR(double(h.normal.y()), std::sqrt(0.5), this->kTol);
  // In the plane but passing beside it.
  localRay<T>(tri, Vec3<T>(T(-3), T(2.5), T(1)), Vec3<T>(1, 0, 0), hit);
  EXPECT_FALSE(hit);
  // Starting on the triangle: distance 0, normal -dir.
  h = localRay<T>(tri, Vec3<T>(T(0.5), T(0.5), T(1)), Vec3<T>(0, 1, 0), hit);
  ASSERT_TRUE(hit);
  EXPECT_EQ(h.distance, T(0));
  EXPECT_EQ(h.normal, Vec3<T>(0, -1, 0));
}

TYPED_TEST(EllipsoidTriangle, TriangleSupportIsTheFarthestVertexAndBoundsAreTheVertices) {
  using T = TypeParam;
  const TriangleCallbacks<T> tri = liftedTriangle<T>();
  EXPECT_EQ(tri.support(Vec3<T>(1, 0, 0)), Vec3<T>(2, 0, 1));
  EXPECT_EQ(tri.support(Vec3<T>(0, 1, 0)), Vec3<T>(0, 2, 1));
  EXPECT_EQ(tri.support(Vec3<T>(-1, -1, 0)), Vec3<T>(0, 0, 1));
  EXPECT_EQ(tri.support(Vec3<T>(0, 0, 1)), Vec3<T>(0, 0, 1));  // ties: the first vertex
  const Bounds3<T> b = tri.localBounds();
  EXPECT_EQ(b.min, Vec3<T>(0, 0, 1));
  EXPECT_EQ(b.max, Vec3<T>(2, 2, 1));
}

TYPED_TEST(EllipsoidTriangle, TriangleDistanceToASphereIsTheGapToItsFace) {
  using T = TypeParam;
  CustomGeometry<T> tri;
  ASSERT_TRUE(makeTriangle(Vec3<T>(0, 0, 1), Vec3<T>(2, 0, 1), Vec3<T>(0, 2, 1), tri).ok());
  EXPECT_STREQ(tri.callbacks->name(), "triangle");
  DistanceResult<T> d;
  ASSERT_TRUE(distance<T>(d, tri, Transform<T>(), SphereGeometry<T>(T(0.5)), Transform<T>(Vec3<T>(T(0.5), T(0.5), T(3)))).ok());
  EXPECT_NEAR(double(d.distance), 1.5, gjkTol<T>());
  EXPECT_NEAR(double(d.normal.z()), 1.0, 1e-4);
}

TYPED_TEST(EllipsoidTriangle, MakeTriangleRejectsNonFiniteAndAreaLessTriangles) {
  using T = TypeParam;
  CustomGeometry<T> out;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  EXPECT_EQ(makeTriangle(Vec3<T>(nan, 0, 0), Vec3<T>(1, 0, 0), Vec3<T>(0, 1, 0), out).code, StatusCode::InvalidArgument);
  EXPECT_EQ(makeTriangle(Vec3<T>(1, 1, 1), Vec3<T>(1, 1, 1), Vec3<T>(1, 1, 1), out).code, StatusCode::DegenerateMesh);
  EXPECT_EQ(makeTriangle(Vec3<T>(0, 0, 0), Vec3<T>(1, 1, 1), Vec3<T>(3, 3, 3), out).code, StatusCode::DegenerateMesh);
  EXPECT_EQ(makeTriangle(Vec3<T>(0, 0, 0), Vec3<T>(1, 0, 0), Vec3<T>(2, 0, 0), out).code, StatusCode::DegenerateMesh);
  EXPECT_EQ(out.callbacks, nullptr);  // untouched
  // Huge and tiny triangles with area are accepted (the test scales before it multiplies).
  EXPECT_TRUE(makeTriangle(Vec3<T>(0, 0, 0), Vec3<T>(T(1e30), 0, 0), Vec3<T>(0, T(1e30), 0), out).ok());
  EXPECT_TRUE(makeTriangle(Vec3<T>(0, 0, 0), Vec3<T>(T(1e-30), 0, 0), Vec3<T>(0, T(1e-30), 0), out).ok());
}

}  // namespace
