// gq::distance with triangle meshes and heightfields (thin surfaces: distance >= 0, 0 in contact), against
// long-double brute force over every triangle (pair).
#include <gtest/gtest.h>

#include <iostream>
#include <vector>

#include "gq/cooking.h"
#include "gq/query.h"
#include "mesh_pairs_reference.h"
#include "mesh_test_helpers.h"

namespace gq::meshpairs {
namespace {

template <class T> class MeshDistance : public ::testing::Test {};
TYPED_TEST_SUITE(MeshDistance, test::Scalars);

// Sphere/capsule use closed forms (1e-9 relative in double); the box goes through GJK (1e-7).
template <class T> LD tolerance(bool gjk) {
  if (std::is_same_v<T, float>) return 1e-4L;
  return gjk ? 1e-7L : 1e-9L;
}

struct ShapeRef {
  int kind;  // 0 sphere, 1 capsule, 2 box
  Vec3L a, b;
  LD r = 0;
  BoxL box;
  LD distanceTo(const TriL& t) const {
    if (kind == 2) return std::sqrt(boxTriangleDistSq(box, t));
    return std::max<LD>(0, std::sqrt(segmentTriangleDistSq(a, b, t)) - r);
  }
};

template <class T> Geometry<T> randomShape(test::Rng& rng, int kind, const Transform<T>& pose, ShapeRef& ref) {
  const Mat3L rot = test::rotationLD(pose.q);
  ref.kind = kind;
  if (kind == 0) {
    const T r = T(rng.uniform(0.05, 0.4));
    ref.a = ref.b = test::toLD(pose.p);
    ref.r = r;
    return SphereGeometry<T>(r);
  }
  if (kind == 1) {
    const T r = T(rng.uniform(0.05, 0.3)), hh = T(rng.uniform(0.0, 0.5));
    ref.a = test::toLD(pose.p) - rot.col(0) * LD(hh);
    ref.b = test::toLD(pose.p) + rot.col(0) * LD(hh);
    ref.r = r;
    return CapsuleGeometry<T>(r, hh);
  }
  const Vec3<T> he = rng.vec<T>(0.05, 0.4);
  ref.box = BoxL{test::toLD(pose.p), rot, test::toLD(he)};
  return BoxGeometry<T>(he);
}

template <class T> void expectWitnessesConsistent(const DistanceResult<T>& r, LD tol) {
  EXPECT_NEAR(double(r.normal.norm()), 1.0, double(tol) * 10);
  if (r.distance > T(0)) {
    const Vec3<T> diff = r.point1 - r.point0;
    EXPECT_NEAR(double((diff - r.distance * r.normal).norm()), 0.0, double(tol) * 10);
  } else {
    EXPECT_NEAR(double((r.point1 - r.point0).norm()), 0.0, double(tol) * 10);
  }
}

// A level-2 icosphere under a non-uniform, rotated scale (one factor negative) at a rotated pose, and its world
// triangles in long double.
template <class T> struct ScaledIcosphere {
  MeshData<T> data = meshtest::icosphere<T>(2);
  MeshScale<T> scale{Vec3<T>(T(1.1), T(0.8), T(-1.2)), Quat<T>(Eigen::AngleAxis<T>(T(0.5), Vec3<T>::UnitZ()))};
  Geometry<T> mesh = TriangleMeshGeometry<T>(meshtest::cook(data.vertices, data.triangles), scale);
  Transform<T> pose{Vec3<T>(T(0.3), T(0.2), T(-0.1)), Quat<T>(Eigen::AngleAxis<T>(T(0.7), Vec3<T>(1, 1, 0).normalized()))};
  std::vector<TriL> triangles = worldTriangles(data, scale, pose);
};

TYPED_TEST(MeshDistance, ConvexVsScaledIcosphereEqualsBruteForceMinimumOverTriangles) {
  using T = TypeParam;
  const ScaledIcosphere<T> scene;
  const Geometry<T>& mesh = scene.mesh;
  const Transform<T>& meshPose = scene.pose;
  const std::vector<TriL>& tris = scene.triangles;
  test::Rng rng(61);
  int contacts = 0;
  for (int i = 0; i < 1200; ++i) {
    const int kind = i % 3;
    const Transform<T> pose = rng.pose<T>(2.0);
    ShapeRef ref;
    const Geometry<T> shape = randomShape<T>(rng, kind, pose, ref);
    LD expected = std::numeric_limits<LD>::infinity();
    for (const auto& t : tris) expected = std::min(expected, ref.distanceTo(t));
    DistanceResult<T> r;
    ASSERT_TRUE(distance(r, shape, pose, mesh, meshPose).ok());
    const LD tol = tolerance<T>(kind == 2);
    ASSERT_NEAR(double(r.distance), double(expected), double(tol * std::max<LD>(1, expected))) << "kind " << kind << " pose " << i;
    ASSERT_GE(r.distance, T(0));
    expectWitnessesConsistent(r, tol);
    DistanceResult<T> s;
    ASSERT_TRUE(distance(s, mesh, meshPose, shape, pose).ok());
    EXPECT_EQ(s.distance, r.distance);
    EXPECT_EQ(s.normal, Vec3<T>(-r.normal));
    contacts += expected == 0;
  }
  EXPECT_GT(contacts, 100);
  EXPECT_LT(contacts, 1150);
}

// Hulls, whose triangle distances run GJK after a ball bound prunes them (distance/convex_surface.cpp), against the
// icosphere: the least distance between a hull face and a mesh triangle, in long double, wherever the answer is
// positive (a hull apart from every triangle: then its faces' distance is the solid's).
TYPED_TEST(MeshDistance, ConvexHullVsScaledIcosphereEqualsBruteForceMinimumOverFaceTrianglePairs) {
  using T = TypeParam;
  const ScaledIcosphere<T> scene;
  const Geometry<T>& mesh = scene.mesh;
  const Transform<T>& meshPose = scene.pose;
  const std::vector<TriL>& tris = scene.triangles;
  test::Rng rng(62);
  std::vector<Vec3<T>> points;
  for (int i = 0; i < 12; ++i)
    points.push_back(Vec3<T>(rng.unitVector<double>().cwiseProduct(Eigen::Vector3d(0.35, 0.25, 0.15)).cast<T>()));
  std::shared_ptr<const ConvexMesh<T>> hull;
  ASSERT_TRUE(cookConvexMesh(points, hull).ok());
  const Geometry<T> shape = ConvexMeshGeometry<T>(hull);
  int apart = 0;
  for (int i = 0; i < 120; ++i) {
    const Transform<T> pose = rng.pose<T>(2.0);
    const Mat3L rot = test::rotationLD(pose.q);
    const auto world = [&](std::uint32_t v) { return Vec3L(rot * hull->vertices[v].template cast<LD>() + test::toLD(pose.p)); };
    LD expectedSq = std::numeric_limits<LD>::infinity();
    for (const auto& poly : hull->polygons)
      for (std::uint32_t k = 1; k + 1 < poly.indexCount; ++k) {  // the polygon as a fan of triangles
        const TriL face{world(hull->polygonVertices[poly.indexBase]), world(hull->polygonVertices[poly.indexBase + k]),
                        world(hull->polygonVertices[poly.indexBase + k + 1])};
        for (const auto& t : tris) expectedSq = std::min(expectedSq, triangleTriangleDistSq(face, t));
      }
    DistanceResult<T> r;
    ASSERT_TRUE(distance(r, shape, pose, mesh, meshPose).ok());
    if (!(r.distance > T(0))) continue;
    ++apart;
    const LD expected = std::sqrt(expectedSq), tol = tolerance<T>(true);
    ASSERT_NEAR(double(r.distance), double(expected), double(tol * std::max<LD>(1, expected))) << "pose " << i;
    expectWitnessesConsistent(r, tol);
  }
  EXPECT_GT(apart, 60);
}

TYPED_TEST(MeshDistance, MeshVsMeshEqualsBruteForceMinimumOverTrianglePairs) {
  using T = TypeParam;
  const MeshData<T> data = meshtest::icosphere<T>(0);
  const auto cooked = meshtest::cook(data.vertices, data.triangles);
  const MeshScale<T> scale1(Vec3<T>(T(0.5), T(0.7), T(0.4)));
  const Geometry<T> mesh0 = TriangleMeshGeometry<T>(cooked), mesh1 = TriangleMeshGeometry<T>(cooked, scale1);
  test::Rng rng(71);
  int contacts = 0;
  for (int i = 0; i < 1000; ++i) {
    const Transform<T> pose0 = rng.pose<T>(0.5), pose1 = rng.pose<T>(2.0);
    const std::vector<TriL> a = worldTriangles(data, MeshScale<T>(), pose0), b = worldTriangles(data, scale1, pose1);
    LD expected = std::numeric_limits<LD>::infinity();
    for (const auto& x : a)
      for (const auto& y : b) expected = std::min(expected, triangleTriangleDistSq(x, y));
    expected = std::sqrt(expected);
    DistanceResult<T> r;
    ASSERT_TRUE(distance(r, mesh0, pose0, mesh1, pose1).ok());
    ASSERT_NEAR(double(r.distance), double(expected), double(tolerance<T>(false) * std::max<LD>(1, expected))) << "pose " << i;
    expectWitnessesConsistent(r, tolerance<T>(false));
    contacts += expected == 0;
  }
  EXPECT_GT(contacts, 50);
  EXPECT_LT(contacts, 950);
}

TYPED_TEST(MeshDistance, ConvexVsHeightFieldEqualsBruteForceMinimumOverCells) {
  using T = TypeParam;
  HeightFieldDesc<T> desc;
  desc.rows = 9;
  desc.columns = 11;
  test::Rng rng(81);
  for (std::uint32_t i = 0; i < desc.rows * desc.columns; ++i) desc.heights.push_back(T(rng.uniform(-0.4, 0.4)));
  desc.holes = {0, 5, 33};
  std::shared_ptr<const HeightField<T>> field;
  ASSERT_TRUE(cookHeightField(desc, field).ok());
  const Geometry<T> hf = HeightFieldGeometry<T>(field, T(1), T(0.5), T(0.4));
  const Transform<T> fieldPose(Vec3<T>(T(-2), T(0), T(-2)), Quat<T>(Eigen::AngleAxis<T>(T(0.25), Vec3<T>::UnitZ())));
  std::vector<bool> valid;
  const std::vector<TriL> tris = heightFieldTriangles(desc, T(1), T(0.5), T(0.4), fieldPose, valid);
  int contacts = 0, stopped = 0;
  for (int i = 0; i < 1200; ++i) {
    const int kind = i % 3;
    const Transform<T> pose = rng.pose<T>(2.5);
    ShapeRef ref;
    const Geometry<T> shape = randomShape<T>(rng, kind, pose, ref);
    LD expected = std::numeric_limits<LD>::infinity();
    for (std::size_t k = 0; k < tris.size(); ++k)
      if (valid[k]) expected = std::min(expected, ref.distanceTo(tris[k]));
    DistanceResult<T> r;
    ASSERT_TRUE(distance(r, shape, pose, hf, fieldPose).ok());
    const LD tol = tolerance<T>(kind == 2) * std::max<LD>(1, expected);
    ASSERT_NEAR(double(r.distance), double(expected), double(tol)) << "pose " << i;
    contacts += expected == 0;
    // distanceWithin: the rings stop growing past the bound; a stop is a lower bound above it.
    for (const double fraction : {-0.1, 0.5, 1.01, 2.0}) {
      const T bound = T(fraction * double(expected)) - (fraction < 0 ? T(0.1) : T(0));
      DistanceResult<T> w;
      bool beyond = false;
      ASSERT_TRUE(distanceWithin(w, beyond, bound, shape, pose, hf, fieldPose).ok());
      if (beyond) {
        EXPECT_GT(w.distance, bound) << "pose " << i;
        EXPECT_LE(double(w.distance), double(expected + tol)) << "pose " << i;
        ++stopped;
      } else {
        EXPECT_NEAR(double(w.distance), double(expected), double(tol)) << "pose " << i << ", bound " << double(bound);
      }
      if (double(bound) > double(expected + tol)) EXPECT_FALSE(beyond) << "pose " << i;
    }
  }
  EXPECT_GT(contacts, 50);
  EXPECT_GT(stopped, 600);
}

// (Plane against a mesh or heightfield answers: tests/core/plane_surface_test.cpp.)
TYPED_TEST(MeshDistance, SurfaceSurfacePairsOtherThanMeshMeshAreUnsupported) {
  using T = TypeParam;
  const MeshData<T> quad = meshtest::quadStack<T>(1);
  const Geometry<T> mesh = TriangleMeshGeometry<T>(meshtest::cook(quad.vertices, quad.triangles));
  HeightFieldDesc<T> flat;
  flat.rows = flat.columns = 2;
  flat.heights.assign(4, T(0));
  std::shared_ptr<const HeightField<T>> field;
  ASSERT_TRUE(cookHeightField(flat, field).ok());
  const Geometry<T> hf = HeightFieldGeometry<T>(field, T(1), T(1), T(1));
  DistanceResult<T> r;
  r.distance = T(42);
  EXPECT_EQ(distance(r, mesh, Transform<T>(), hf, Transform<T>()).code, StatusCode::Unsupported);
  EXPECT_EQ(distance(r, hf, Transform<T>(), hf, Transform<T>()).code, StatusCode::Unsupported);
  EXPECT_EQ(r.distance, T(42));
}

// distanceWithin: a pair closer than the bound gets distance()'s answer; a farther one may stop (beyond) with only a
// lower bound of its distance above the bound. Boxes (GJK per triangle, after the ball bound) and capsules (closed
// forms) against the scaled icosphere, and mesh against mesh, with brute-force distances; the bound at fractions of
// the exact distance, and negative (nothing of a surface is closer than 0). NaN is rejected, changing nothing.
TYPED_TEST(MeshDistance, DistanceWithinAnswersBelowTheBoundAndBoundsFromBelowBeyondIt) {
  using T = TypeParam;
  const ScaledIcosphere<T> scene;
  const MeshData<T> small = meshtest::icosphere<T>(0);
  const MeshScale<T> smallScale(Vec3<T>(T(0.5), T(0.7), T(0.4)));
  const Geometry<T> smallMesh = TriangleMeshGeometry<T>(meshtest::cook(small.vertices, small.triangles), smallScale);
  test::Rng rng(63);
  int stopped = 0, answered = 0;
  for (int i = 0; i < 240; ++i) {
    const Transform<T> pose = rng.pose<T>(2.5);
    const bool meshPair = i % 3 == 2;
    ShapeRef ref;
    const Geometry<T> shape = meshPair ? smallMesh : randomShape<T>(rng, 1 + i % 3, pose, ref);
    LD exact = std::numeric_limits<LD>::infinity();
    if (meshPair) {
      for (const auto& x : worldTriangles(small, smallScale, pose))
        for (const auto& y : scene.triangles) exact = std::min(exact, std::sqrt(triangleTriangleDistSq(x, y)));
    } else {
      for (const auto& t : scene.triangles) exact = std::min(exact, ref.distanceTo(t));
    }
    const LD tol = tolerance<T>(true) * std::max<LD>(1, exact);
    for (const double fraction : {-0.1, 0.5, 0.99, 1.01, 2.0}) {
      const T bound = T(fraction * double(exact));
      SCOPED_TRACE(testing::Message() << "pose " << i << ", exact " << double(exact) << ", bound " << double(bound));
      DistanceResult<T> r;
      bool beyond = false;
      ASSERT_TRUE(distanceWithin(r, beyond, bound, shape, pose, scene.mesh, scene.pose).ok());
      if (beyond) {
        EXPECT_GT(r.distance, bound);
        EXPECT_LE(double(r.distance), double(exact + tol));
        EXPECT_GE(double(exact), double(bound) - double(tol));
        ++stopped;
      } else {
        EXPECT_NEAR(double(r.distance), double(exact), double(tol));
        expectWitnessesConsistent(r, tolerance<T>(true));
        ++answered;
      }
      if (fraction > 1 && exact > tol) EXPECT_FALSE(beyond);
    }
  }
  EXPECT_GT(stopped, 240);  // both outcomes are exercised
  EXPECT_GT(answered, 240);
  std::cout << stopped << " stopped beyond the bound, " << answered << " answered\n";
  DistanceResult<T> r;
  r.distance = T(42);
  bool beyond = true;
  EXPECT_EQ(distanceWithin(r, beyond, std::numeric_limits<T>::quiet_NaN(), smallMesh, Transform<T>(), scene.mesh,
                           scene.pose).code,
            StatusCode::InvalidArgument);
  EXPECT_EQ(r.distance, T(42));
  EXPECT_TRUE(beyond);
}

}  // namespace
}  // namespace gq::meshpairs
