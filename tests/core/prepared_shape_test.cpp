// Prepared shapes (gq/shape.h): the factory validates as validateGeometry does; every query on prepared shapes gives
// the Geometry<T> overload's answer bit for bit and its Status; bad poses, directions and empty shapes are rejected;
// the lazily derived data is built once under concurrent first use.
#include <gtest/gtest.h>

#include <cstring>

#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "core/test_util.h"
#include "gq/cooking.h"
#include "gq/custom_shapes.h"
#include "gq/query.h"
#include "gq/shape.h"
#include "prepared/shape_ref.h"

namespace gq {
namespace {

using test::Rng;

template <class T> class PreparedShape : public ::testing::Test {};
TYPED_TEST_SUITE(PreparedShape, test::Scalars);

template <class T> std::shared_ptr<const ConvexMesh<T>> octahedronHull() {
  std::vector<Vec3<T>> points;
  for (int axis = 0; axis < 3; ++axis)
    for (T sign : {T(-1), T(1)}) {
      Vec3<T> v = Vec3<T>::Zero();
      v[axis] = sign * T(0.6 + 0.1 * axis);
      points.push_back(v);
    }
  points.push_back(Vec3<T>(T(0.3), T(0.3), T(0.3)));
  std::shared_ptr<const ConvexMesh<T>> hull;
  EXPECT_TRUE(cookConvexMesh(points, hull).ok());
  return hull;
}

// A hull with enough vertices to get a support start table (a sampled sphere).
template <class T> std::shared_ptr<const ConvexMesh<T>> roundHull() {
  std::vector<Vec3<T>> points;
  Rng rng(7);
  for (int i = 0; i < 200; ++i) points.push_back(rng.unitVector<T>() * T(0.8));
  std::shared_ptr<const ConvexMesh<T>> hull;
  EXPECT_TRUE(cookConvexMesh(points, hull).ok());
  return hull;
}

template <class T> std::shared_ptr<const TriangleMesh<T>> wavyMesh() {
  std::vector<Vec3<T>> v;
  std::vector<TriangleIndices> tris;
  const int n = 6;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      v.push_back(Vec3<T>(T(i - n / 2) * T(0.5), T(0.2) * T((i + j) % 3) - T(0.2), T(j - n / 2) * T(0.5)));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const std::uint32_t a = std::uint32_t(i * (n + 1) + j), b = a + 1, c = a + std::uint32_t(n + 1), d = c + 1;
      tris.push_back({a, b, c});
      tris.push_back({b, d, c});
    }
  std::shared_ptr<const TriangleMesh<T>> mesh;
  EXPECT_TRUE(cookTriangleMesh(v, tris, mesh).ok());
  return mesh;
}

template <class T> std::shared_ptr<const HeightField<T>> bumpyField() {
  HeightFieldDesc<T> d;
  d.rows = 6;
  d.columns = 6;
  for (std::uint32_t r = 0; r < d.rows; ++r)
    for (std::uint32_t c = 0; c < d.columns; ++c) d.heights.push_back(T(0.1) * T((r * 3 + c * 5) % 4));
  std::shared_ptr<const HeightField<T>> hf;
  EXPECT_TRUE(cookHeightField(d, hf).ok());
  return hf;
}

// One geometry of every type (the custom one a ready-made cylinder; a second hull scaled).
template <class T> std::vector<Geometry<T>> everyGeometry() {
  std::vector<Geometry<T>> out;
  out.push_back(SphereGeometry<T>(T(0.5)));
  out.push_back(PlaneGeometry<T>());
  out.push_back(CapsuleGeometry<T>(T(0.3), T(0.5)));
  out.push_back(BoxGeometry<T>(T(0.5), T(0.4), T(0.3)));
  out.push_back(ConvexMeshGeometry<T>(octahedronHull<T>()));
  out.push_back(ConvexMeshGeometry<T>(octahedronHull<T>(), MeshScale<T>(Vec3<T>(T(1.5), T(0.7), T(1.1)))));
  out.push_back(TriangleMeshGeometry<T>(wavyMesh<T>()));
  out.push_back(HeightFieldGeometry<T>(bumpyField<T>(), T(1), T(0.4), T(0.4)));
  CustomGeometry<T> cylinder;
  EXPECT_TRUE(makeCylinder(T(0.3), T(0.4), cylinder).ok());
  out.push_back(cylinder);
  return out;
}

template <class T> std::vector<Shape<T>> prepare(const std::vector<Geometry<T>>& geoms) {
  std::vector<Shape<T>> out(geoms.size());
  for (std::size_t i = 0; i < geoms.size(); ++i) EXPECT_TRUE(Shape<T>::make(geoms[i], out[i]).ok());
  return out;
}

void expectSameStatus(const Status& prepared, const Status& plain, const std::string& where) {
  EXPECT_EQ(prepared.code, plain.code) << where;
  EXPECT_EQ(prepared.toString(), plain.toString()) << where;
}

template <class T> void expectSame(const Vec3<T>& a, const Vec3<T>& b, const std::string& where) {
  EXPECT_TRUE(a == b) << where << ": " << a.transpose() << " vs " << b.transpose();
}

std::string label(GeometryType a, GeometryType b, int k) {
  return std::string(toString(a)) + "-" + toString(b) + " pose " + std::to_string(k);
}

TYPED_TEST(PreparedShape, FactoryRejectsBadGeometryWithValidateGeometrysStatus) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const std::vector<Geometry<T>> bad = {SphereGeometry<T>(T(-1)),
                                        SphereGeometry<T>(nan),
                                        CapsuleGeometry<T>(T(0.5), T(-0.1)),
                                        BoxGeometry<T>(T(1), T(0), T(1)),
                                        ConvexMeshGeometry<T>(nullptr),
                                        ConvexMeshGeometry<T>(octahedronHull<T>(), MeshScale<T>(T(0))),
                                        TriangleMeshGeometry<T>(nullptr),
                                        CustomGeometry<T>(nullptr),
                                        Geometry<T>()};
  for (const Geometry<T>& g : bad) {
    Shape<T> s;
    const Status made = Shape<T>::make(g, s);
    const Status validated = validateGeometry(g);
    ASSERT_FALSE(validated.ok()) << toString(g.type());
    EXPECT_FALSE(made.ok()) << toString(g.type());
    expectSameStatus(made, validated, toString(g.type()));
    EXPECT_TRUE(s.empty()) << "a rejected geometry leaves the output unchanged";
  }
  Shape<T> box;
  ASSERT_TRUE(makeShape(Geometry<T>(BoxGeometry<T>(T(1), T(2), T(3))), box).ok());
  EXPECT_FALSE(box.empty());
  EXPECT_EQ(box.type(), GeometryType::Box);
  EXPECT_EQ(box.featureRadius(), detail::featureRadius(box.geometry()));
  EXPECT_TRUE(box.localBounds().min == Vec3<T>(T(-1), T(-2), T(-3)));
  EXPECT_TRUE(box.localBounds().max == Vec3<T>(T(1), T(2), T(3)));
}

TYPED_TEST(PreparedShape, PairQueriesAnswerAsTheGeometryOverloadsBitForBit) {
  using T = TypeParam;
  const std::vector<Geometry<T>> geoms = everyGeometry<T>();
  const std::vector<Shape<T>> shapes = prepare(geoms);
  Rng rng(20261129);
  constexpr int kPoses = 24;
  for (std::size_t i = 0; i < geoms.size(); ++i)
    for (std::size_t j = 0; j < geoms.size(); ++j)
      for (int k = 0; k < kPoses; ++k) {
        const Transform<T> p0 = rng.pose<T>(1.0), p1 = rng.pose<T>(1.0);
        const std::string where = label(geoms[i].type(), geoms[j].type(), k);

        bool hitPrepared = false, hitPlain = false;
        expectSameStatus(overlap(shapes[i], p0, shapes[j], p1, hitPrepared), overlap(geoms[i], p0, geoms[j], p1, hitPlain),
                         "overlap " + where);
        EXPECT_EQ(hitPrepared, hitPlain) << "overlap " << where;

        PenetrationResult<T> penPrepared, penPlain;
        expectSameStatus(computePenetration(penPrepared, shapes[i], p0, shapes[j], p1),
                         computePenetration(penPlain, geoms[i], p0, geoms[j], p1), "penetration " + where);
        EXPECT_EQ(penPrepared.penetrating, penPlain.penetrating) << where;
        EXPECT_EQ(penPrepared.depth, penPlain.depth) << where;
        expectSame(penPrepared.direction, penPlain.direction, "penetration " + where);

        DistanceResult<T> dPrepared, dPlain;
        GjkCache<T> cPrepared, cPlain;
        expectSameStatus(distance(dPrepared, shapes[i], p0, shapes[j], p1, &cPrepared),
                         distance(dPlain, geoms[i], p0, geoms[j], p1, &cPlain), "distance " + where);
        EXPECT_EQ(dPrepared.distance, dPlain.distance) << where;
        expectSame(dPrepared.point0, dPlain.point0, "distance " + where);
        expectSame(dPrepared.point1, dPlain.point1, "distance " + where);
        expectSame(dPrepared.normal, dPlain.normal, "distance " + where);
        expectSame(cPrepared.direction, cPlain.direction, "distance cache " + where);

        bool beyondPrepared = false, beyondPlain = false;
        const T bound = T(0.25);
        expectSameStatus(distanceWithin(dPrepared, beyondPrepared, bound, shapes[i], p0, shapes[j], p1),
                         distanceWithin(dPlain, beyondPlain, bound, geoms[i], p0, geoms[j], p1),
                         "distanceWithin " + where);
        EXPECT_EQ(beyondPrepared, beyondPlain) << where;
        EXPECT_EQ(dPrepared.distance, dPlain.distance) << where;

        const Vec3<T> dir = rng.unitVector<T>();
        SweepHit<T> hPrepared, hPlain;
        bool hasPrepared = false, hasPlain = false;
        const HitFlags flags = kDefaultHitFlags | HitFlag::Mtd;
        expectSameStatus(sweep(dir, T(2), shapes[i], p0, shapes[j], p1, hPrepared, hasPrepared, flags),
                         sweep(dir, T(2), geoms[i], p0, geoms[j], p1, hPlain, hasPlain, flags), "sweep " + where);
        EXPECT_EQ(hasPrepared, hasPlain) << where;
        if (hasPrepared && hasPlain) {
          EXPECT_EQ(hPrepared.distance, hPlain.distance) << where;
          expectSame(hPrepared.normal, hPlain.normal, "sweep " + where);
          expectSame(hPrepared.position, hPlain.position, "sweep " + where);
        }
      }
}

TYPED_TEST(PreparedShape, SingleShapeQueriesAnswerAsTheGeometryOverloadsBitForBit) {
  using T = TypeParam;
  const std::vector<Geometry<T>> geoms = everyGeometry<T>();
  const std::vector<Shape<T>> shapes = prepare(geoms);
  Rng rng(39);
  for (std::size_t i = 0; i < geoms.size(); ++i)
    for (int k = 0; k < 32; ++k) {
      const Transform<T> pose = rng.pose<T>(1.0);
      const std::string where = std::string(toString(geoms[i].type())) + " pose " + std::to_string(k);

      const Vec3<T> origin = rng.inBox<T>(2.0);
      const Vec3<T> dir = rng.unitVector<T>();
      RaycastHit<T> hitsPrepared[4], hitsPlain[4];
      std::uint32_t nPrepared = 0, nPlain = 0;
      const HitFlags flags = kDefaultHitFlags | HitFlag::MeshMultiple;
      expectSameStatus(raycast(origin, dir, shapes[i], pose, T(5), flags, 4, hitsPrepared, nPrepared),
                       raycast(origin, dir, geoms[i], pose, T(5), flags, 4, hitsPlain, nPlain), "raycast " + where);
      ASSERT_EQ(nPrepared, nPlain) << where;
      for (std::uint32_t h = 0; h < nPrepared; ++h) {
        EXPECT_EQ(hitsPrepared[h].distance, hitsPlain[h].distance) << where;
        expectSame(hitsPrepared[h].position, hitsPlain[h].position, "raycast " + where);
        expectSame(hitsPrepared[h].normal, hitsPlain[h].normal, "raycast " + where);
      }

      PointDistanceResult<T> pdPrepared, pdPlain;
      expectSameStatus(pointDistance(origin, shapes[i], pose, pdPrepared), pointDistance(origin, geoms[i], pose, pdPlain),
                       "pointDistance " + where);
      EXPECT_EQ(pdPrepared.distance, pdPlain.distance) << where;
      expectSame(pdPrepared.closestPoint, pdPlain.closestPoint, "pointDistance " + where);

      Bounds3<T> bPrepared{}, bPlain{};
      expectSameStatus(computeGeomBounds(bPrepared, shapes[i], pose, T(0.1), T(1.01)),
                       computeGeomBounds(bPlain, geoms[i], pose, T(0.1), T(1.01)), "bounds " + where);
      expectSame(bPrepared.min, bPlain.min, "bounds " + where);
      expectSame(bPrepared.max, bPlain.max, "bounds " + where);
    }
}

// A mesh shape with no scale and an identity pose rotation takes its own one-hit cast (no instance frame): its
// hits must be the geometry path's bit for bit, every field and flag, for every hit-flag combination, on single- and
// double-sided meshes, closest and any hit, with MeshMultiple asking for one hit or several (the instance-frame
// cast), maxDist finite, infinite or 0, and directions with exactly zero, negative zero and tied components.
TYPED_TEST(PreparedShape, OneHitMeshRaycastsPlacedAsCookedAnswerAsTheGeometryOverloadBitForBit) {
  using T = TypeParam;
  const T inf = std::numeric_limits<T>::infinity();
  const T r = T(1) / std::sqrt(T(2));
  const Vec3<T> special[] = {Vec3<T>(0, -1, 0), Vec3<T>(T(-0.0), 1, T(-0.0)), Vec3<T>(r, -r, 0),
                             Vec3<T>(0, r, -r),  Vec3<T>(-r, T(-0.0), r),      Vec3<T>(1, 0, 0)};
  Rng rng(44);
  int hits = 0;
  for (MeshGeometryFlag sides : {MeshGeometryFlag::None, MeshGeometryFlag::DoubleSided}) {
    const Geometry<T> geom = TriangleMeshGeometry<T>(wavyMesh<T>(), MeshScale<T>(), sides);
    Shape<T> shape;
    ASSERT_TRUE(Shape<T>::make(geom, shape).ok());
    for (int k = 0; k < 600; ++k) {
      const Transform<T> pose(rng.inBox<T>(1.0), Quat<T>::Identity());
      // Origins 2 units from a point on or near the sheet, aimed at it (about half come from behind its faces).
      const Vec3<T> target = pose.p + rng.inBox<T>(1.2);
      const Vec3<T> dir = k % 4 == 0 ? special[(k / 4) % 6] : rng.unitVector<T>();
      const Vec3<T> origin = target - dir * T(2);
      const std::uint32_t bits = std::uint32_t(k) % 64u;
      HitFlags flags;
      if (bits & 1u) flags |= HitFlag::Position;
      if (bits & 2u) flags |= HitFlag::Normal;
      if (bits & 4u) flags |= HitFlag::UV;
      if (bits & 8u) flags |= HitFlag::AnyHit;
      if (bits & 16u) flags |= HitFlag::MeshBothSides;
      if (bits & 32u) flags |= HitFlag::MeshMultiple;
      const std::uint32_t maxHits = k % 5 == 1 ? 3u : 1u;  // 3 without MeshMultiple: one hit all the same
      const T maxDist = k % 7 == 3 ? inf : k % 7 == 5 ? T(0) : T(5);
      const std::string where = std::string(sides == MeshGeometryFlag::None ? "single" : "double") + "-sided ray " +
                                std::to_string(k);
      RaycastHit<T> cooked[3], plain[3];
      std::uint32_t nCooked = 0, nPlain = 0;
      expectSameStatus(raycast(origin, dir, shape, pose, maxDist, flags, maxHits, cooked, nCooked),
                       raycast(origin, dir, geom, pose, maxDist, flags, maxHits, plain, nPlain), where);
      ASSERT_EQ(nCooked, nPlain) << where;
      if (maxDist == T(0)) EXPECT_EQ(nCooked, 0u) << where;
      for (std::uint32_t h = 0; h < nCooked; ++h) {
        ++hits;
        EXPECT_EQ(std::memcmp(&cooked[h].distance, &plain[h].distance, sizeof(T)), 0) << where;
        expectSame(cooked[h].position, plain[h].position, where);
        expectSame(cooked[h].normal, plain[h].normal, where);
        EXPECT_EQ(std::memcmp(&cooked[h].u, &plain[h].u, sizeof(T)), 0) << where;
        EXPECT_EQ(std::memcmp(&cooked[h].v, &plain[h].v, sizeof(T)), 0) << where;
        EXPECT_EQ(cooked[h].faceIndex, plain[h].faceIndex) << where;
        EXPECT_EQ(cooked[h].flags.bits(), plain[h].flags.bits()) << where;
      }
    }
  }
  EXPECT_GT(hits, 500);
}

// A ray marched from its last hit passes that hit's position (and here its normal, as the direction) to the next
// raycast, which writes the same hit: the answer must be the one for copies of those inputs.
TYPED_TEST(PreparedShape, MeshRaycastsReadTheirRayBeforeWritingAHitItAliases) {
  using T = TypeParam;
  Shape<T> shape;
  ASSERT_TRUE(Shape<T>::make(TriangleMeshGeometry<T>(wavyMesh<T>(), MeshScale<T>(), MeshGeometryFlag::DoubleSided),
                             shape)
                  .ok());
  const HitFlags flags = kDefaultHitFlags;
  for (const Transform<T>& pose :
       {Transform<T>(Vec3<T>(T(0.1), 0, 0), Quat<T>::Identity()),  // the one-hit cast placed as cooked
        // the instance-frame cast
        Transform<T>(Vec3<T>(T(0.1), 0, 0), Quat<T>(Eigen::AngleAxis<T>(T(0.2), Vec3<T>::UnitX())))}) {
    const Vec3<T> origin(T(0.3), T(2), T(0.2)), dir(0, -1, 0);
    RaycastHit<T> expected;
    std::uint32_t n = 0;
    ASSERT_TRUE(raycast(origin, dir, shape, pose, T(10), flags, 1, &expected, n).ok());
    ASSERT_EQ(n, 1u);
    RaycastHit<T> hit;
    hit.position = origin;
    hit.normal = dir;
    ASSERT_TRUE(raycast(hit.position, hit.normal, shape, pose, T(10), flags, 1, &hit, n).ok());
    ASSERT_EQ(n, 1u);
    EXPECT_EQ(hit.distance, expected.distance);
    expectSame(hit.position, expected.position, "aliased origin");
    expectSame(hit.normal, expected.normal, "aliased direction");
  }
}

TYPED_TEST(PreparedShape, BadPosesAndDirectionsAreRejectedAsOnTheGeometryPath) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const Geometry<T> sphere = SphereGeometry<T>(T(0.5)), box = BoxGeometry<T>(T(0.5), T(0.4), T(0.3));
  Shape<T> s, b;
  ASSERT_TRUE(Shape<T>::make(sphere, s).ok());
  ASSERT_TRUE(Shape<T>::make(box, b).ok());
  const Transform<T> good(Vec3<T>(T(0.1), T(0), T(0)));
  const std::vector<Transform<T>> badPoses = {
      Transform<T>(Vec3<T>(nan, T(0), T(0))),
      Transform<T>(Vec3<T>::Zero(), Quat<T>(T(2), T(0), T(0), T(0))),
      Transform<T>(Vec3<T>(std::numeric_limits<T>::infinity(), T(0), T(0))),
      Transform<T>(Vec3<T>(T(std::is_same_v<T, float> ? 1e10 : 1e76), T(0), T(0)))};  // beyond a pair's offsets
  for (std::size_t k = 0; k < badPoses.size(); ++k) {
    const Transform<T>& bad = badPoses[k];
    const std::string where = "bad pose " + std::to_string(k);
    for (int side = 0; side < 2; ++side) {
      const Transform<T>& p0 = side ? good : bad;
      const Transform<T>& p1 = side ? bad : good;
      bool hit = true;
      const Status st = overlap(s, p0, b, p1, hit);
      EXPECT_EQ(st.code, StatusCode::InvalidArgument) << where;
      EXPECT_TRUE(hit) << "no output on failure";
      bool hit2 = true;
      expectSameStatus(st, overlap(sphere, p0, box, p1, hit2), "overlap " + where);
      PenetrationResult<T> pen;
      EXPECT_EQ(computePenetration(pen, s, p0, b, p1).code, StatusCode::InvalidArgument) << where;
      DistanceResult<T> d;
      EXPECT_EQ(distance(d, s, p0, b, p1).code, StatusCode::InvalidArgument) << where;
      SweepHit<T> h;
      bool has = false;
      EXPECT_EQ(sweep(Vec3<T>(Vec3<T>::UnitX()), T(1), s, p0, b, p1, h, has).code, StatusCode::InvalidArgument) << where;
    }
    if (k < 2) {  // single-shape queries accept far poses
      RaycastHit<T> hit;
      std::uint32_t n = 0;
      EXPECT_EQ(raycast(Vec3<T>(Vec3<T>::Zero()), Vec3<T>(Vec3<T>::UnitX()), s, bad, T(1), kDefaultHitFlags, 1, &hit, n).code,
                StatusCode::InvalidArgument) << where;
      PointDistanceResult<T> pd;
      EXPECT_EQ(pointDistance(Vec3<T>(Vec3<T>::Zero()), s, bad, pd).code, StatusCode::InvalidArgument) << where;
      Bounds3<T> bounds{};
      EXPECT_EQ(computeGeomBounds(bounds, s, bad).code, StatusCode::InvalidArgument) << where;
    }
  }
  // Directions and distances.
  SweepHit<T> h;
  bool has = false;
  EXPECT_EQ(sweep(Vec3<T>(T(1), T(1), T(0)), T(1), s, good, b, good, h, has).code, StatusCode::InvalidArgument);
  EXPECT_EQ(sweep(Vec3<T>(Vec3<T>::UnitX()), T(-1), s, good, b, good, h, has).code, StatusCode::InvalidArgument);
  RaycastHit<T> hit;
  std::uint32_t n = 0;
  EXPECT_EQ(raycast(Vec3<T>(Vec3<T>::Zero()), Vec3<T>(T(0), T(2), T(0)), b, good, T(1), kDefaultHitFlags, 1, &hit, n).code,
            StatusCode::InvalidArgument);
  DistanceResult<T> d;
  bool beyond = false;
  EXPECT_EQ(distanceWithin(d, beyond, nan, s, good, b, good).code, StatusCode::InvalidArgument);
}

TYPED_TEST(PreparedShape, EmptyShapesAreRejectedByEveryQuery) {
  using T = TypeParam;
  const Shape<T> empty;
  Shape<T> s;
  ASSERT_TRUE(Shape<T>::make(Geometry<T>(SphereGeometry<T>(T(1))), s).ok());
  const Transform<T> pose;
  bool hit = false;
  EXPECT_EQ(overlap(empty, pose, s, pose, hit).code, StatusCode::InvalidArgument);
  EXPECT_EQ(overlap(s, pose, empty, pose, hit).code, StatusCode::InvalidArgument);
  PenetrationResult<T> pen;
  EXPECT_EQ(computePenetration(pen, empty, pose, s, pose).code, StatusCode::InvalidArgument);
  DistanceResult<T> d;
  EXPECT_EQ(distance(d, s, pose, empty, pose).code, StatusCode::InvalidArgument);
  bool beyond = false;
  EXPECT_EQ(distanceWithin(d, beyond, T(1), empty, pose, s, pose).code, StatusCode::InvalidArgument);
  SweepHit<T> h;
  bool has = false;
  EXPECT_EQ(sweep(Vec3<T>(Vec3<T>::UnitX()), T(1), empty, pose, s, pose, h, has).code, StatusCode::InvalidArgument);
  RaycastHit<T> rh;
  std::uint32_t n = 0;
  EXPECT_EQ(raycast(Vec3<T>(Vec3<T>::Zero()), Vec3<T>(Vec3<T>::UnitX()), empty, pose, T(1), kDefaultHitFlags, 1, &rh, n).code,
            StatusCode::InvalidArgument);
  PointDistanceResult<T> pd;
  EXPECT_EQ(pointDistance(Vec3<T>(Vec3<T>::Zero()), empty, pose, pd).code, StatusCode::InvalidArgument);
  Bounds3<T> b{};
  EXPECT_EQ(computeGeomBounds(b, empty, pose).code, StatusCode::InvalidArgument);
}

TYPED_TEST(PreparedShape, PairQueriesRejectAShapeTooLargeForThemAsTheGeometryPathDoes) {
  using T = TypeParam;
  const Geometry<T> huge = SphereGeometry<T>(T(std::is_same_v<T, float> ? 1e12 : 1e80));
  const Geometry<T> unit = SphereGeometry<T>(T(1));
  Shape<T> h, u;
  ASSERT_TRUE(Shape<T>::make(huge, h).ok()) << "valid for raycasts and bounds";
  ASSERT_TRUE(Shape<T>::make(unit, u).ok());
  bool a = false, b = false;
  const Status prepared = overlap(u, Transform<T>(), h, Transform<T>(), a);
  EXPECT_EQ(prepared.code, StatusCode::InvalidArgument);
  expectSameStatus(prepared, overlap(unit, Transform<T>(), huge, Transform<T>(), b), "huge sphere");
  Bounds3<T> bounds{};
  EXPECT_TRUE(computeGeomBounds(bounds, h, Transform<T>()).ok());
}

TYPED_TEST(PreparedShape, HullBallsAreBuiltOnceUnderConcurrentFirstUse) {
  using T = TypeParam;
  Shape<T> hull;
  ASSERT_TRUE(Shape<T>::make(Geometry<T>(ConvexMeshGeometry<T>(roundHull<T>(), MeshScale<T>(T(2)))), hull).ok());
  const Shape<T> copy = hull;  // copies share the derived data
  const detail::ShapeDerived<T>* derived = detail::ShapeAccess<T>::derived(hull);
  ASSERT_NE(derived, nullptr);
  EXPECT_EQ(derived, detail::ShapeAccess<T>::derived(copy));
  EXPECT_EQ(derived->builds, 0u) << "nothing is built before a query asks";

  constexpr int kThreads = 4;
  std::vector<ShapeBalls<T>> seen(kThreads);
  std::atomic<int> ready{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      ready.fetch_add(1);
      while (ready.load() < kThreads) std::this_thread::yield();
      seen[t] = (t % 2 ? copy : hull).hullBalls();
    });
  for (std::thread& t : threads) t.join();
  EXPECT_EQ(derived->builds, 1u);
  EXPECT_NE(derived->supportStartTable, nullptr) << "a 200-point hull has a start table";
  const ConvexMesh<T>& mesh = *hull.geometry().template get<ConvexMeshGeometry<T>>().mesh;
  for (const ShapeBalls<T>& b : seen) {
    expectSame(b.center, Vec3<T>(mesh.center * T(2)), "ball centre");
    EXPECT_EQ(b.inner, T(2) * mesh.innerRadius);
    EXPECT_EQ(b.outer, T(2) * mesh.outerRadius);
  }
  Shape<T> sphere;
  ASSERT_TRUE(Shape<T>::make(Geometry<T>(SphereGeometry<T>(T(1))), sphere).ok());
  EXPECT_EQ(sphere.hullBalls().outer, std::numeric_limits<T>::infinity()) << "not a hull: the balls prove nothing";
}

}  // namespace
}  // namespace gq
