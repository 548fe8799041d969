// The positional forms of findOverlapTriangleMesh / findOverlapHeightField, sweepTriangles and
// generateTriangleContacts stay as deprecated inline overloads so existing host code compiles: they give the answers
// of the settings-struct forms, and on failure write nothing, as every query.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "gq/contacts.h"
#include "gq/cooking.h"
#include "gq/mesh_query.h"
#include "mesh_test_helpers.h"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"

namespace gq {
namespace {

template <class T> class DeprecatedForms : public ::testing::Test {};
TYPED_TEST_SUITE(DeprecatedForms, meshtest::Scalars);

TYPED_TEST(DeprecatedForms, PositionalPagingGivesThePagesOfTheSettingsForm) {
  using T = TypeParam;
  const MeshData<T> data = meshtest::icosphere<T>(2);
  const TriangleMeshGeometry<T> mesh(meshtest::cook(data.vertices, data.triangles));
  const Geometry<T> sphere = SphereGeometry<T>(T(0.5));
  const Transform<T> pose(Vec3<T>(T(0.8), T(0.1), T(0)));
  std::uint32_t a[5], b[5];
  for (std::uint32_t start = 0; start < 40; start += 5) {
    bool overflow = false;
    std::uint32_t count = 0;
    ASSERT_TRUE(findOverlapTriangleMesh(sphere, pose, mesh, Transform<T>(), a, 5u, start, overflow, count).ok());
    TriangleOverlapPageResult page;
    ASSERT_TRUE(
        findOverlapTriangleMesh(sphere, pose, mesh, Transform<T>(), TriangleOverlapPage{b, 5u, start}, page).ok());
    ASSERT_EQ(count, page.count);
    EXPECT_EQ(overflow, page.overflow);
    EXPECT_EQ(std::vector<std::uint32_t>(a, a + count), std::vector<std::uint32_t>(b, b + page.count));
  }
  // Failure: nothing written.
  bool overflow = true;
  std::uint32_t count = 77;
  EXPECT_EQ(findOverlapTriangleMesh(sphere, pose, mesh, Transform<T>(), nullptr, 5u, 0u, overflow, count).code,
            StatusCode::InvalidArgument);
  EXPECT_TRUE(overflow);
  EXPECT_EQ(count, 77u);
}

TYPED_TEST(DeprecatedForms, PositionalSweepFlagsGiveTheHitOfTheSettingsForm) {
  using T = TypeParam;
  std::vector<Triangle<T>> tris(2);
  for (int k = 0; k < 2; ++k) {
    const T x = T(3 + k);
    tris[k].verts[0] = Vec3<T>(x, T(-2), T(-2));
    tris[k].verts[1] = Vec3<T>(x, T(-2), T(2));  // facing -X (counter-clockwise seen from -X)
    tris[k].verts[2] = Vec3<T>(x, T(2), T(0));
  }
  const Geometry<T> box = BoxGeometry<T>(T(0.25), T(0.5), T(0.5));
  const std::uint32_t cached = 1;
  SweepHit<T> a, b;
  bool hasA = false, hasB = false;
  ASSERT_TRUE(sweepTriangles(Vec3<T>(Vec3<T>::UnitX()), T(10), box, Transform<T>(), tris.data(), 2u, a, hasA,
                             kDefaultHitFlags | HitFlag::AnyHit, &cached, T(0.1), true)
                  .ok());
  ASSERT_TRUE(sweepTriangles(Vec3<T>(Vec3<T>::UnitX()), T(10), box, Transform<T>(), tris.data(), 2u, b, hasB,
                             TriangleSweepSettings<T>{kDefaultHitFlags | HitFlag::AnyHit, &cached, T(0.1), true})
                  .ok());
  ASSERT_TRUE(hasA && hasB);
  EXPECT_EQ(a.faceIndex, 1u);  // the cached triangle, first with AnyHit
  EXPECT_EQ(a.faceIndex, b.faceIndex);
  EXPECT_EQ(a.distance, b.distance);
  EXPECT_EQ(a.normal, b.normal);
}

TYPED_TEST(DeprecatedForms, PositionalContactDistancesGiveTheContactsOfTheSettingsForm) {
  using T = TypeParam;
  Triangle<T> tri;
  tri.verts[0] = Vec3<T>(T(-5), T(-5), T(0));
  tri.verts[1] = Vec3<T>(T(5), T(-5), T(0));
  tri.verts[2] = Vec3<T>(T(0), T(5), T(0));
  const Geometry<T> box = BoxGeometry<T>(T(0.5), T(0.5), T(0.5));
  const Transform<T> pose(Vec3<T>(T(0), T(0), T(0.52)));
  ContactBuffer<T> a, b;
  bool has = false;
  ASSERT_TRUE(generateTriangleContacts(box, pose, tri, 9u, T(0.05), T(0.01), T(1), a, has).ok());
  ASSERT_TRUE(generateTriangleContacts(box, pose, tri, 9u, b, TriangleContactSettings<T>{T(0.05), T(0.01), T(1)}).ok());
  EXPECT_TRUE(has);
  ASSERT_EQ(a.count, 4u);
  ASSERT_EQ(a.count, b.count);
  for (std::uint32_t i = 0; i < a.count; ++i) {
    EXPECT_EQ(a.contacts[i].position, b.contacts[i].position);
    EXPECT_EQ(a.contacts[i].separation, b.contacts[i].separation);
    EXPECT_EQ(a.contacts[i].triangleIndex, 9u);
  }
  // Beyond contactDistance: ok, no contacts, hasContacts false.
  ASSERT_TRUE(generateTriangleContacts(box, Transform<T>(Vec3<T>(T(0), T(0), T(1))), tri, 9u, T(0.05), T(0.01), T(1),
                                       a, has)
                  .ok());
  EXPECT_FALSE(has);
  EXPECT_EQ(a.count, 0u);
}

}  // namespace
}  // namespace gq

#pragma GCC diagnostic pop
