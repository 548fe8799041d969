// The bad-input contract of the mesh queries (gq/mesh_query.h) and triangle contacts (gq/contacts.h):
// docs/hardening.md, table "mesh queries", one test per row.
#include <gtest/gtest.h>

#include "hardening_fixtures.h"

namespace gq::hardening {
namespace {

template <class T> class BadInputMeshQueries : public ::testing::Test {};
TYPED_TEST_SUITE(BadInputMeshQueries, Scalars);

template <class T> TriangleMeshGeometry<T> cubeMesh() { return TriangleMeshGeometry<T>(Cooked<T>::get().mesh); }
template <class T> Transform<T> nanPose() { return Transform<T>(Vec3<T>(kNaN<T>, T(0), T(0))); }
template <class T> Triangle<T> sentinelTriangle() { return Triangle<T>{{sentinelVec<T>(), sentinelVec<T>(), sentinelVec<T>()}}; }
template <class T> Triangle<T> unitTriangle() {
  return Triangle<T>{{Vec3<T>(T(0), T(0), T(0)), Vec3<T>(T(1), T(0), T(0)), Vec3<T>(T(0), T(1), T(0))}};
}

TYPED_TEST(BadInputMeshQueries, TriangleIndexOutOfRangeIsInvalidArgument) {
  using T = TypeParam;
  Triangle<T> tri = sentinelTriangle<T>();
  std::uint32_t indices[3] = {7, 7, 7};
  EXPECT_EQ(getTriangle(cubeMesh<T>(), Transform<T>(), 12u, tri, indices).code, StatusCode::InvalidArgument);
  EXPECT_EQ(getTriangle(cubeMesh<T>(), Transform<T>(), 0xffffffffu, tri, indices).code, StatusCode::InvalidArgument);
  // 8 x 8 cells, 2 triangles each.
  EXPECT_EQ(getTriangle(heightFieldGeometry<T>(), Transform<T>(), 128u, tri, indices).code,
            StatusCode::InvalidArgument);
  EXPECT_TRUE(sameBits(tri, sentinelTriangle<T>()));
  EXPECT_EQ(indices[0], 7u);
  EXPECT_TRUE(getTriangle(cubeMesh<T>(), Transform<T>(), 11u, tri, indices).ok());
}

TYPED_TEST(BadInputMeshQueries, TriangleRemovedAtCookingIsInvalidArgument) {
  using T = TypeParam;
  std::vector<Vec3<T>> v = cubePoints<T>();
  std::vector<TriangleIndices> t = cubeTriangles();
  t.push_back({0, 1, 1});  // zero area: dropped by cooking, input index 12
  std::shared_ptr<const TriangleMesh<T>> mesh;
  ASSERT_TRUE(cookTriangleMesh(v, t, mesh).ok());
  Triangle<T> tri = sentinelTriangle<T>();
  EXPECT_EQ(getTriangle(TriangleMeshGeometry<T>(mesh), Transform<T>(), 12u, tri).code, StatusCode::InvalidArgument);
  EXPECT_TRUE(sameBits(tri, sentinelTriangle<T>()));
}

TYPED_TEST(BadInputMeshQueries, NaNPoseIsInvalidArgumentInEveryMeshQuery) {
  using T = TypeParam;
  const Geometry<T> sphere = SphereGeometry<T>(T(0.5));
  Triangle<T> tri = sentinelTriangle<T>();
  EXPECT_EQ(getTriangle(cubeMesh<T>(), nanPose<T>(), 0u, tri).code, StatusCode::InvalidArgument);
  EXPECT_EQ(getTriangle(heightFieldGeometry<T>(), nanPose<T>(), 0u, tri).code, StatusCode::InvalidArgument);
  EXPECT_TRUE(sameBits(tri, sentinelTriangle<T>()));

  std::uint32_t results[4] = {7, 7, 7, 7};
  TriangleOverlapPageResult received{4242, true};
  EXPECT_EQ(findOverlapTriangleMesh(sphere, nanPose<T>(), cubeMesh<T>(), Transform<T>(),
                                    TriangleOverlapPage{results, 4u, 0u}, received)
                .code,
            StatusCode::InvalidArgument);
  EXPECT_EQ(findOverlapHeightField(sphere, Transform<T>(), heightFieldGeometry<T>(), nanPose<T>(),
                                   TriangleOverlapPage{results, 4u, 0u}, received)
                .code,
            StatusCode::InvalidArgument);
  EXPECT_EQ(received.count, 4242u);
  EXPECT_TRUE(received.overflow);
  EXPECT_EQ(results[0], 7u);

  bool found = true;
  EXPECT_EQ(findOverlapTriangleMeshPairs<T>([](std::uint32_t, std::uint32_t) { return true; }, cubeMesh<T>(),
                                            nanPose<T>(), cubeMesh<T>(), Transform<T>(), found).code,
            StatusCode::InvalidArgument);
  EXPECT_TRUE(found);

  PenetrationResult<T> mtd = sentinelPenetration<T>();
  EXPECT_EQ(computeTriangleMeshPenetration(mtd, sphere, nanPose<T>(), cubeMesh<T>(), Transform<T>()).code,
            StatusCode::InvalidArgument);
  EXPECT_EQ(computeHeightFieldPenetration(mtd, sphere, Transform<T>(), heightFieldGeometry<T>(), nanPose<T>()).code,
            StatusCode::InvalidArgument);
  EXPECT_TRUE(sameBits(mtd, sentinelPenetration<T>()));

  const Triangle<T> triangles[1] = {unitTriangle<T>()};
  SweepHit<T> hit = sentinelSweepHit<T>();
  bool hasHit = true;
  EXPECT_EQ(sweepTriangles<T>(Vec3<T>::UnitZ(), T(10), sphere, nanPose<T>(), triangles, 1u, hit, hasHit).code,
            StatusCode::InvalidArgument);
  EXPECT_TRUE(hasHit && sameBits(hit, sentinelSweepHit<T>()));

  ContactBuffer<T> contacts;
  contacts.count = 4242;
  EXPECT_EQ(generateTriangleContacts(Geometry<T>(BoxGeometry<T>(T(1), T(1), T(1))), nanPose<T>(), unitTriangle<T>(), 0u,
                                     contacts, TriangleContactSettings<T>{T(0.1), T(0.01), T(1)})
                .code,
            StatusCode::InvalidArgument);
  EXPECT_EQ(contacts.count, 4242u);
}

TYPED_TEST(BadInputMeshQueries, NullResultBufferWithNonZeroSizeIsInvalidArgument) {
  using T = TypeParam;
  TriangleOverlapPageResult received{4242, true};
  const Geometry<T> sphere = SphereGeometry<T>(T(0.5));
  EXPECT_EQ(findOverlapTriangleMesh(sphere, Transform<T>(), cubeMesh<T>(), Transform<T>(),
                                    TriangleOverlapPage{nullptr, 4u, 0u}, received)
                .code,
            StatusCode::InvalidArgument);
  EXPECT_EQ(findOverlapHeightField(sphere, Transform<T>(), heightFieldGeometry<T>(), Transform<T>(),
                                   TriangleOverlapPage{nullptr, 4u, 0u}, received)
                .code,
            StatusCode::InvalidArgument);
  EXPECT_EQ(received.count, 4242u);
  // Capacity 0 with a null buffer is a valid "count only" call.
  EXPECT_TRUE(findOverlapTriangleMesh(sphere, Transform<T>(Vec3<T>(T(1), T(0), T(0))), cubeMesh<T>(), Transform<T>(),
                                      TriangleOverlapPage{nullptr, 0u, 0u}, received)
                  .ok());
}

TYPED_TEST(BadInputMeshQueries, ShapesOutsideTheSpecsListReturnUnsupported) {
  using T = TypeParam;
  std::uint32_t results[2];
  TriangleOverlapPageResult received{4242, true};
  const Geometry<T> hull = ConvexMeshGeometry<T>(Cooked<T>::get().hull);
  EXPECT_EQ(findOverlapTriangleMesh(hull, Transform<T>(), cubeMesh<T>(), Transform<T>(),
                                    TriangleOverlapPage{results, 2u, 0u}, received)
                .code,
            StatusCode::Unsupported);
  SweepHit<T> hit = sentinelSweepHit<T>();
  bool hasHit = true;
  const Triangle<T> triangles[1] = {unitTriangle<T>()};
  EXPECT_EQ(sweepTriangles<T>(Vec3<T>::UnitZ(), T(1), Geometry<T>(PlaneGeometry<T>()), Transform<T>(), triangles, 1u, hit,
                           hasHit).code, StatusCode::Unsupported);
  PenetrationResult<T> mtd = sentinelPenetration<T>();
  EXPECT_EQ(computeTriangleMeshPenetration(mtd, Geometry<T>(cubeMesh<T>()), Transform<T>(), cubeMesh<T>(),
                                           Transform<T>()).code, StatusCode::Unsupported);
  ContactBuffer<T> contacts;
  EXPECT_EQ(generateTriangleContacts(Geometry<T>(SphereGeometry<T>(T(1))), Transform<T>(), unitTriangle<T>(), 0u,
                                     contacts, TriangleContactSettings<T>{T(0.1), T(0.01), T(1)})
                .code,
            StatusCode::Unsupported);
  EXPECT_EQ(received.count, 4242u);
  EXPECT_TRUE(hasHit && sameBits(mtd, sentinelPenetration<T>()));
}

TYPED_TEST(BadInputMeshQueries, EmptyCallbackOrNegativeToleranceIsInvalidArgument) {
  using T = TypeParam;
  bool found = true;
  EXPECT_EQ(findOverlapTriangleMeshPairs<T>(TrianglePairCallback(), cubeMesh<T>(), Transform<T>(), cubeMesh<T>(),
                                            Transform<T>(), found).code, StatusCode::InvalidArgument);
  for (const T tol : {T(-1), kNaN<T>, kInf<T>})
    EXPECT_EQ(findOverlapTriangleMeshPairs<T>([](std::uint32_t, std::uint32_t) { return true; }, cubeMesh<T>(),
                                              Transform<T>(), cubeMesh<T>(), Transform<T>(), found, tol).code,
              StatusCode::InvalidArgument);
  EXPECT_TRUE(found);
}

TYPED_TEST(BadInputMeshQueries, ZeroIterationsIsInvalidArgument) {
  using T = TypeParam;
  PenetrationResult<T> mtd = sentinelPenetration<T>();
  const Geometry<T> sphere = SphereGeometry<T>(T(0.5));
  EXPECT_EQ(computeTriangleMeshPenetration(mtd, sphere, Transform<T>(), cubeMesh<T>(), Transform<T>(), 0u).code,
            StatusCode::InvalidArgument);
  EXPECT_EQ(computeHeightFieldPenetration(mtd, sphere, Transform<T>(), heightFieldGeometry<T>(), Transform<T>(), 0u).code,
            StatusCode::InvalidArgument);
  EXPECT_TRUE(sameBits(mtd, sentinelPenetration<T>()));
}

TYPED_TEST(BadInputMeshQueries, SweepTrianglesRejectsNullArraysNaNVerticesAndBadCachedIndex) {
  using T = TypeParam;
  const Geometry<T> sphere = SphereGeometry<T>(T(0.5));
  SweepHit<T> hit = sentinelSweepHit<T>();
  bool hasHit = true;
  Triangle<T> triangles[2] = {unitTriangle<T>(), unitTriangle<T>()};
  const Transform<T> above(Vec3<T>(T(0.2), T(0.2), T(2)));
  EXPECT_EQ(sweepTriangles<T>(-Vec3<T>::UnitZ(), T(10), sphere, above, static_cast<const Triangle<T>*>(nullptr), 2u, hit,
                           hasHit).code, StatusCode::InvalidArgument);
  const std::uint32_t cached = 2;
  EXPECT_EQ(sweepTriangles<T>(-Vec3<T>::UnitZ(), T(10), sphere, above, triangles, 2u, hit, hasHit,
                              TriangleSweepSettings<T>{kDefaultHitFlags, &cached})
                .code,
            StatusCode::InvalidArgument);
  EXPECT_EQ(sweepTriangles<T>(-Vec3<T>::UnitZ(), T(10), sphere, above, triangles, 2u, hit, hasHit,
                              TriangleSweepSettings<T>{kDefaultHitFlags | HitFlag::Mtd})
                .code,
            StatusCode::InvalidArgument);
  EXPECT_EQ(sweepTriangles<T>(-Vec3<T>::UnitZ(), T(-1), sphere, above, triangles, 2u, hit, hasHit).code,
            StatusCode::InvalidArgument);
  EXPECT_EQ(sweepTriangles<T>(Vec3<T>(T(0), T(0), T(-2)), T(10), sphere, above, triangles, 2u, hit, hasHit).code,
            StatusCode::InvalidArgument);
  triangles[1].verts[2].x() = kNaN<T>;
  EXPECT_EQ(sweepTriangles<T>(-Vec3<T>::UnitZ(), T(10), sphere, above, triangles, 2u, hit, hasHit).code,
            StatusCode::InvalidArgument);
  EXPECT_TRUE(hasHit && sameBits(hit, sentinelSweepHit<T>()));
}

TYPED_TEST(BadInputMeshQueries, TriangleContactsRejectBadDistancesAndDegenerateOrNaNTriangles) {
  using T = TypeParam;
  const Geometry<T> box = BoxGeometry<T>(T(1), T(1), T(1));
  ContactBuffer<T> contacts;
  contacts.count = 4242;
  auto call = [&](const Triangle<T>& tri, T contactDistance, T margin, T toleranceLength) {
    return generateTriangleContacts(box, Transform<T>(), tri, 0u, contacts,
                                    TriangleContactSettings<T>{contactDistance, margin, toleranceLength})
        .code;
  };
  EXPECT_EQ(call(unitTriangle<T>(), T(-0.1), T(0), T(1)), StatusCode::InvalidArgument);
  EXPECT_EQ(call(unitTriangle<T>(), T(0.1), kNaN<T>, T(1)), StatusCode::InvalidArgument);
  EXPECT_EQ(call(unitTriangle<T>(), T(0.1), T(0), T(0)), StatusCode::InvalidArgument);
  Triangle<T> collinear = unitTriangle<T>();
  collinear.verts[2] = T(2) * collinear.verts[1];
  EXPECT_EQ(call(collinear, T(0.1), T(0), T(1)), StatusCode::InvalidArgument);
  Triangle<T> nan = unitTriangle<T>();
  nan.verts[0].y() = kNaN<T>;
  EXPECT_EQ(call(nan, T(0.1), T(0), T(1)), StatusCode::InvalidArgument);
  EXPECT_EQ(contacts.count, 4242u);
}

// A raw triangle is a pair query's second geometry: vertices more than 1e9 (float) / 1e75 (double) from the shape's
// pose are InvalidArgument, as pair offsets are (fuzz_mesh_queries: a float triangle reaching z = +-4e28 gave four
// contacts at -inf, Ok). The same holds for sweepTriangles; sizes beyond the bound are rejected by both.
TYPED_TEST(BadInputMeshQueries, RawTrianglesBeyondThePairMagnitudeAreInvalidArgument) {
  using T = TypeParam;
  const T far = std::is_same_v<T, float> ? T(4.0886929e28) : T(1e76);
  Triangle<T> tri;
  tri.verts[0] = Vec3<T>(T(-5.0625), T(-5.0625), -far);
  tri.verts[1] = Vec3<T>(T(0.5), T(0.5), T(0.5));
  tri.verts[2] = Vec3<T>(T(-5.0625), T(-5.0625), far);
  const Transform<T> pose(Vec3<T>(T(3.1875), T(-1.125), T(1.39797e+10)),
                          Quat<T>(T(-0.767184), T(0.422382), T(0.482723), T(0)).normalized());
  ContactBuffer<T> contacts;
  contacts.count = 4242;
  const Geometry<T> box = BoxGeometry<T>(T(1), T(1), T(1));
  const Status s =
      generateTriangleContacts(box, pose, tri, 0u, contacts, TriangleContactSettings<T>{T(0.5), T(0.5), T(0.5)});
  EXPECT_EQ(s.code, StatusCode::InvalidArgument) << s.toString();
  EXPECT_NE(s.toString().find("too far"), std::string::npos) << s.toString();
  EXPECT_EQ(contacts.count, 4242u);
  SweepHit<T> hit = sentinelSweepHit<T>();
  bool hasHit = true;
  EXPECT_EQ(sweepTriangles<T>(Vec3<T>::UnitZ(), T(1), Geometry<T>(SphereGeometry<T>(T(1))), pose, &tri, 1u, hit, hasHit).code,
            StatusCode::InvalidArgument);
  EXPECT_TRUE(hasHit && sameBits(hit, sentinelSweepHit<T>()));
  const Geometry<T> hugeBox = BoxGeometry<T>(far, T(1), T(1));
  EXPECT_EQ(generateTriangleContacts(hugeBox, Transform<T>(), unitTriangle<T>(), 0u, contacts,
                                     TriangleContactSettings<T>{T(0.5), T(0.5), T(0.5)})
                .code,
            StatusCode::InvalidArgument);
  // At the bound: accepted, finite contacts.
  const T bound = std::is_same_v<T, float> ? T(1e9) : T(1e75);
  Triangle<T> wide;
  wide.verts[0] = Vec3<T>(-bound, -bound, T(0));
  wide.verts[1] = Vec3<T>(bound, -bound, T(0));
  wide.verts[2] = Vec3<T>(T(0), bound, T(0));
  ASSERT_TRUE(generateTriangleContacts(box, Transform<T>(Vec3<T>(T(0), T(0), T(0.9))), wide, 0u, contacts,
                                       TriangleContactSettings<T>{T(0.5), T(0.5), T(0.5)})
                  .ok());
  for (std::uint32_t i = 0; i < contacts.count; ++i)
    EXPECT_TRUE(isFinite(contacts.contacts[i].position) && isFinite(contacts.contacts[i].normal) &&
                std::isfinite(contacts.contacts[i].separation));
}

}  // namespace
}  // namespace gq::hardening
