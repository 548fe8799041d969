// pointDistance for sphere, capsule, box and scaled convex hulls against independent long-double closed forms
// (convex: brute force over every triangle of every polygon), inside points, and unsupported/invalid inputs.
#include <gtest/gtest.h>

#include <limits>

#include "gq/cooking.h"
#include "gq/custom.h"
#include "gq/query.h"
#include "test_util.h"

namespace gq {
namespace {

using test::LD;
using test::Mat3L;
using test::Vec3L;

template <class T> class PointDistance : public ::testing::Test {};
TYPED_TEST_SUITE(PointDistance, test::Scalars);

struct Reference {
  LD distance;
  Vec3L closest;  // world
};

template <class T> PointDistanceResult<T> query(const Vec3<T>& p, const Geometry<T>& g, const Transform<T>& pose) {
  PointDistanceResult<T> r;
  const Status s = pointDistance(p, g, pose, r);
  EXPECT_TRUE(s.ok()) << s.toString();
  return r;
}

template <class T> void expectMatches(const PointDistanceResult<T>& got, const Reference& ref, double scale) {
  const double tol = test::Tol<T>::kRel * scale;
  EXPECT_NEAR(double(got.distance), double(ref.distance), tol);
  EXPECT_LT(double((test::toLD(got.closestPoint) - ref.closest).norm()), 2 * tol);
  EXPECT_EQ(got.closestIndex, kInvalidFaceIndex);
}

// Closest point on triangle abc to p (Ericson, Real-Time Collision Detection, 5.1.5), in long double.
Vec3L closestOnTriangle(const Vec3L& p, const Vec3L& a, const Vec3L& b, const Vec3L& c) {
  const Vec3L ab = b - a, ac = c - a, ap = p - a;
  const LD d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3L bp = p - b;
  const LD d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const LD vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const Vec3L cp = p - c;
  const LD d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const LD vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const LD va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const LD denom = 1 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

template <class T> Vec3L toWorld(const Transform<T>& pose, const Vec3L& local) {
  return test::rotationLD(pose.q) * local + test::toLD(pose.p);
}
template <class T> Vec3L toLocal(const Transform<T>& pose, const Vec3<T>& world) {
  return test::rotationLD(pose.q).transpose() * (test::toLD(world) - test::toLD(pose.p));
}

TYPED_TEST(PointDistance, SphereMatchesClosedForm) {
  using T = TypeParam;
  test::Rng rng(1);
  for (int i = 0; i < 2000; ++i) {
    const T r = T(rng.uniform(0.1, 3));
    const Transform<T> pose = rng.pose<T>(10);
    const Vec3<T> p = pose.p + rng.inBox<T>(6);
    const Vec3L m = test::toLD(p) - test::toLD(pose.p);
    const LD len = m.norm();
    const Reference ref = len <= r ? Reference{0, test::toLD(p)} : Reference{len - r, test::toLD(pose.p) + m * (r / len)};
    expectMatches(query<T>(p, SphereGeometry<T>(r), pose), ref, 20);
  }
}

TYPED_TEST(PointDistance, CapsuleMatchesClosedForm) {
  using T = TypeParam;
  test::Rng rng(2);
  for (int i = 0; i < 2000; ++i) {
    const T r = T(rng.uniform(0.1, 2)), hh = T(rng.uniform(0, 3));
    const Transform<T> pose = rng.pose<T>(10);
    const Vec3<T> p = pose.p + rng.inBox<T>(6);
    const Vec3L local = toLocal(pose, p);
    const Vec3L axis(std::clamp(local.x(), -LD(hh), LD(hh)), 0, 0);
    const LD len = (local - axis).norm();
    const Reference ref = len <= r ? Reference{0, test::toLD(p)}
                                   : Reference{len - r, toWorld(pose, Vec3L(axis + (local - axis) * (r / len)))};
    expectMatches(query<T>(p, CapsuleGeometry<T>(r, hh), pose), ref, 20);
  }
}

TYPED_TEST(PointDistance, BoxMatchesClosedForm) {
  using T = TypeParam;
  test::Rng rng(3);
  for (int i = 0; i < 2000; ++i) {
    const Vec3<T> h = rng.vec<T>(0.1, 2);
    const Transform<T> pose = rng.pose<T>(10);
    const Vec3<T> p = pose.p + rng.inBox<T>(5);
    const Vec3L local = toLocal(pose, p);
    const Vec3L hl = test::toLD(h);
    const Vec3L clamped = local.cwiseMax(-hl).cwiseMin(hl);
    const LD dist = (local - clamped).norm();
    const Reference ref = dist == 0 ? Reference{0, test::toLD(p)} : Reference{dist, toWorld(pose, clamped)};
    expectMatches(query<T>(p, BoxGeometry<T>(h), pose), ref, 20);
  }
}

// Brute force over every triangle (fan) of every polygon of the scaled hull, in long double; inside when behind
// every polygon plane.
template <class T>
Reference convexReference(const ConvexMesh<T>& hull, const MeshScale<T>& scale, const Transform<T>& pose,
                          const Vec3<T>& point) {
  const Mat3L R = test::rotationLD(scale.rotation);
  const Mat3L S = R * test::toLD(scale.scale).asDiagonal() * R.transpose();
  const Vec3L p = toLocal(pose, point);
  Vec3L centroid = Vec3L::Zero();
  for (const Vec3<T>& v : hull.vertices) centroid += S * test::toLD(v);
  centroid /= LD(hull.vertices.size());
  bool inside = true;
  LD best = std::numeric_limits<LD>::infinity();
  Vec3L bestPoint;
  for (const HullPolygon<T>& poly : hull.polygons) {
    std::vector<Vec3L> pts;
    for (std::uint32_t k = 0; k < poly.indexCount; ++k)
      pts.push_back(S * test::toLD(hull.vertices[hull.polygonVertices[poly.indexBase + k]]));
    Vec3L n = (pts[1] - pts[0]).cross(pts[2] - pts[0]);
    if (n.dot(pts[0] - centroid) < 0) n = -n;
    if (n.dot(p - pts[0]) > 0) inside = false;
    for (std::size_t k = 1; k + 1 < pts.size(); ++k) {
      const Vec3L c = closestOnTriangle(p, pts[0], pts[k], pts[k + 1]);
      if ((c - p).norm() < best) {
        best = (c - p).norm();
        bestPoint = c;
      }
    }
  }
  if (inside) return {0, test::toLD(point)};
  return {best, toWorld(pose, bestPoint)};
}

TYPED_TEST(PointDistance, ScaledConvexMatchesBruteForceOverTriangles) {
  using T = TypeParam;
  test::Rng rng(4);
  for (int shape = 0; shape < 10; ++shape) {
    std::vector<Vec3<T>> pts;
    for (int i = 0; i < 40; ++i) pts.push_back(rng.inBox<T>(1.5));
    std::shared_ptr<const ConvexMesh<T>> hull;
    ASSERT_TRUE(cookConvexMesh(pts, hull).ok());
    const MeshScale<T> scale = shape == 0 ? MeshScale<T>() : rng.meshScale<T>(0.3, 3);
    const Transform<T> pose = rng.pose<T>(10);
    int insideCount = 0;
    for (int i = 0; i < 300; ++i) {
      const Vec3<T> p = pose.p + rng.inBox<T>(i % 3 == 0 ? 1.5 : 8);
      const Reference ref = convexReference(*hull, scale, pose, p);
      insideCount += ref.distance == 0;
      expectMatches(query<T>(p, ConvexMeshGeometry<T>(hull, scale), pose), ref, 20);
    }
    EXPECT_GT(insideCount, 5);
  }
}

TYPED_TEST(PointDistance, InsidePointsGiveZeroAndThePointItself) {
  using T = TypeParam;
  const Transform<T> pose(Vec3<T>(1, 2, 3), Quat<T>(Eigen::AngleAxis<T>(T(1), Vec3<T>(1, 1, 0).normalized())));
  std::vector<Vec3<T>> cube;
  for (int i = 0; i < 8; ++i) cube.emplace_back(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
  std::shared_ptr<const ConvexMesh<T>> hull;
  ASSERT_TRUE(cookConvexMesh(cube, hull).ok());
  const std::vector<Geometry<T>> shapes = {SphereGeometry<T>(T(1)), CapsuleGeometry<T>(T(0.5), T(1)),
                                           BoxGeometry<T>(T(1), T(1), T(1)), ConvexMeshGeometry<T>(hull)};
  for (const Geometry<T>& g : shapes) {
    for (const Vec3<T>& local : {Vec3<T>(0, 0, 0), Vec3<T>(T(0.2), T(-0.1), T(0.3)), Vec3<T>(T(0.5), 0, 0)}) {
      const Vec3<T> p = pose.transform(local);
      const PointDistanceResult<T> r = query<T>(p, g, pose);
      EXPECT_EQ(r.distance, T(0)) << toString(g.type());
      EXPECT_EQ(r.closestPoint, p) << toString(g.type());
    }
  }
}

TYPED_TEST(PointDistance, PlaneHeightFieldAndCustomAreUnsupported) {
  using T = TypeParam;
  class Dummy : public CustomGeometryCallbacks<T> {
   public:
    const char* name() const override { return "dummy"; }
    Bounds3<T> localBounds() const override { return Bounds3<T>::fromCenterExtents(Vec3<T>::Zero(), Vec3<T>::Ones()); }
    Vec3<T> support(const Vec3<T>& d) const override { return d; }
    bool raycast(const Vec3<T>&, const Vec3<T>&, T, HitFlags, RaycastHit<T>&) const override { return false; }
  };
  for (const Geometry<T>& g : {Geometry<T>(PlaneGeometry<T>()), Geometry<T>(CustomGeometry<T>(std::make_shared<Dummy>()))}) {
    PointDistanceResult<T> r;
    r.distance = T(-5);
    const Status s = pointDistance(Vec3<T>(1, 2, 3), g, Transform<T>(), r);
    EXPECT_EQ(s.code, StatusCode::Unsupported) << toString(g.type());
    EXPECT_EQ(r.distance, T(-5));
  }
}

TYPED_TEST(PointDistance, NonFinitePointOrBadPoseIsRejectedAndWritesNothing) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  PointDistanceResult<T> r;
  r.distance = T(-5);
  EXPECT_EQ(pointDistance(Vec3<T>(nan, 0, 0), Geometry<T>(SphereGeometry<T>(T(1))), Transform<T>(), r).code,
            StatusCode::InvalidArgument);
  EXPECT_EQ(pointDistance(Vec3<T>(0, 0, 0), Geometry<T>(SphereGeometry<T>(T(1))), Transform<T>(Vec3<T>(nan, 0, 0)), r).code,
            StatusCode::InvalidArgument);
  EXPECT_EQ(pointDistance(Vec3<T>(0, 0, 0), Geometry<T>(BoxGeometry<T>(T(1), T(0), T(1))), Transform<T>(), r).code,
            StatusCode::InvalidArgument);
  EXPECT_EQ(r.distance, T(-5));
}

}  // namespace
}  // namespace gq
