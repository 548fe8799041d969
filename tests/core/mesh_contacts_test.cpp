// generateMeshContacts: each crossing triangle pair of two surfaces gives one contact along the shallower of its two
// face normals. Closed forms: two box meshes overlapping by a known amount, a box mesh sunk into a flat heightfield.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "gq/contacts.h"
#include "gq/cooking.h"
#include "test_util.h"

namespace gq {
namespace {

template <class T> class MeshContacts : public ::testing::Test {};
TYPED_TEST_SUITE(MeshContacts, test::Scalars);

template <class T> T tol() { return std::is_same_v<T, float> ? T(2e-5) : T(1e-12); }

// A closed, outward-wound box mesh of half extents h centred at the origin (its own frame).
template <class T> Geometry<T> boxMesh(const Vec3<T>& h) {
  std::vector<Vec3<T>> v;
  for (int i = 0; i < 8; ++i)
    v.emplace_back((i & 1 ? 1 : -1) * h.x(), (i & 2 ? 1 : -1) * h.y(), (i & 4 ? 1 : -1) * h.z());
  const std::vector<TriangleIndices> t = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                                          {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  std::shared_ptr<const TriangleMesh<T>> mesh;
  EXPECT_TRUE(cookTriangleMesh(v, t, mesh).ok());
  return TriangleMeshGeometry<T>(mesh);
}

// One flat cell of height 0 spanning [-5, 5] in x and z (shape space: y up).
template <class T> Geometry<T> flatField() {
  HeightFieldDesc<T> desc;
  desc.rows = desc.columns = 2;
  desc.heights = {T(0), T(0), T(0), T(0)};
  std::shared_ptr<const HeightField<T>> field;
  EXPECT_TRUE(cookHeightField(desc, field).ok());
  return HeightFieldGeometry<T>(field, T(1), T(10), T(10));
}

template <class T>
std::vector<MeshContact<T>> contactsOf(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1,
                                       const Transform<T>& p1) {
  std::vector<MeshContact<T>> out;
  bool found = false;
  const Status s = generateMeshContacts<T>(
      [&](const MeshContact<T>& c) {
        out.push_back(c);
        return true;
      },
      g0, p0, g1, p1, found);
  EXPECT_TRUE(s.ok()) << s.toString();
  EXPECT_EQ(found, !out.empty());
  return out;
}

// Box A (half 1, 1, 1) at the origin and box B (half 1, 0.5, 0.5) at x = 1.8: B's sides cross A's +x face, and
// B enters A by 0.2 along x (A's +x face is nearer than any of B's side faces: those lie 0.5 inside A's sides).
// Every crossing pair is pushed out through A's face by 0.2; the contact sits midway, at x = 0.9.
TYPED_TEST(MeshContacts, OverlappingBoxMeshesGiveTheOverlapDepthAlongTheShallowerFace) {
  using T = TypeParam;
  const Geometry<T> a = boxMesh<T>(Vec3<T>(1, 1, 1)), b = boxMesh<T>(Vec3<T>(1, T(0.5), T(0.5)));
  test::Rng rng(7);
  for (int trial = 0; trial < 8; ++trial) {
    // Both boxes under one common rigid motion (identity first): the answer moves with it.
    const Transform<T> common = trial == 0 ? Transform<T>()
                                           : Transform<T>(rng.inBox<T>(3), Quat<T>(Eigen::AngleAxis<T>(
                                                                               T(rng.uniform(0, 3)), rng.unitVector<T>())));
    const Transform<T> poseB = common * Transform<T>(Vec3<T>(T(1.8), 0, 0));
    const std::vector<MeshContact<T>> contacts = contactsOf(a, common, b, poseB);
    ASSERT_FALSE(contacts.empty());
    const Vec3<T> normal = common.rotate(Vec3<T>(-1, 0, 0));  // from B towards A
    for (const MeshContact<T>& c : contacts) {
      EXPECT_NEAR(c.depth, T(0.2), tol<T>() * 4);
      EXPECT_NEAR((c.normal - normal).norm(), T(0), tol<T>());
      EXPECT_NEAR(common.transformInv(c.position).x(), T(0.9), tol<T>() * 4);
      EXPECT_LT(c.triangle0, 12u);
      EXPECT_LT(c.triangle1, 12u);
    }
  }
}

TYPED_TEST(MeshContacts, SwappingTheSurfacesTurnsTheNormalAndTheTriangles) {
  using T = TypeParam;
  const Geometry<T> a = boxMesh<T>(Vec3<T>(1, 1, 1)), b = boxMesh<T>(Vec3<T>(1, T(0.5), T(0.5)));
  const Transform<T> poseB(Vec3<T>(T(1.8), 0, 0));
  const auto forward = contactsOf(a, Transform<T>(), b, poseB);
  const auto backward = contactsOf(b, poseB, a, Transform<T>());
  ASSERT_EQ(forward.size(), backward.size());
  for (const MeshContact<T>& c : backward) {
    EXPECT_NEAR(c.depth, T(0.2), tol<T>() * 4);
    EXPECT_NEAR((c.normal - Vec3<T>(1, 0, 0)).norm(), T(0), tol<T>());
    EXPECT_LT(c.triangle1, 12u);
  }
}

// A unit box mesh whose bottom is 0.3 below a flat heightfield: its side triangles cross the field's huge triangles,
// which reach far into the box (4.5 and more along the box's side normals), so each pair is pushed up by 0.3.
TYPED_TEST(MeshContacts, BoxMeshSunkIntoAHeightFieldIsPushedUpByItsDepth) {
  using T = TypeParam;
  const Geometry<T> box = boxMesh<T>(Vec3<T>(T(0.5), T(0.5), T(0.5)));
  const Geometry<T> field = flatField<T>();
  const Transform<T> fieldPose(Vec3<T>(-5, 0, -5));
  const Transform<T> boxPose(Vec3<T>(T(0.1), T(0.2), T(-0.3)));
  const auto contacts = contactsOf(box, boxPose, field, fieldPose);
  ASSERT_FALSE(contacts.empty());
  for (const MeshContact<T>& c : contacts) {
    EXPECT_NEAR(c.depth, T(0.3), tol<T>() * 4);
    EXPECT_NEAR((c.normal - Vec3<T>(0, 1, 0)).norm(), T(0), tol<T>());
    EXPECT_NEAR(c.position.y(), T(-0.15), tol<T>() * 4);
    EXPECT_LT(c.triangle1, 2u);
  }
  // The field as surface 0: the normal points from the box down into the field's side.
  for (const MeshContact<T>& c : contactsOf(field, fieldPose, box, boxPose)) {
    EXPECT_NEAR(c.depth, T(0.3), tol<T>() * 4);
    EXPECT_NEAR((c.normal - Vec3<T>(0, -1, 0)).norm(), T(0), tol<T>());
    EXPECT_LT(c.triangle0, 2u);
  }
}

TYPED_TEST(MeshContacts, SeparatedMeshesGiveNoContact) {
  using T = TypeParam;
  const Geometry<T> a = boxMesh<T>(Vec3<T>(1, 1, 1));
  EXPECT_TRUE(contactsOf(a, Transform<T>(), a, Transform<T>(Vec3<T>(T(2.1), 0, 0))).empty());
}

TYPED_TEST(MeshContacts, CallbackReturningFalseStopsTheQuery) {
  using T = TypeParam;
  const Geometry<T> a = boxMesh<T>(Vec3<T>(1, 1, 1)), b = boxMesh<T>(Vec3<T>(1, T(0.5), T(0.5)));
  int calls = 0;
  bool found = false;
  ASSERT_TRUE(generateMeshContacts<T>([&](const MeshContact<T>&) { return ++calls < 1; }, a, Transform<T>(), b,
                                      Transform<T>(Vec3<T>(T(1.8), 0, 0)), found)
                  .ok());
  EXPECT_EQ(calls, 1);
  EXPECT_TRUE(found);
}

TYPED_TEST(MeshContacts, NonSurfaceOrInvalidInputReportsAStatusAndNothingElse) {
  using T = TypeParam;
  const Geometry<T> a = boxMesh<T>(Vec3<T>(1, 1, 1));
  const Geometry<T> sphere = SphereGeometry<T>(T(1));
  int calls = 0;
  const MeshContactCallback<T> count = [&](const MeshContact<T>&) { return ++calls > 0; };
  bool found = true;
  EXPECT_EQ(generateMeshContacts<T>(count, a, Transform<T>(), sphere, Transform<T>(), found).code, StatusCode::Unsupported);
  Transform<T> bad;
  bad.p.x() = std::numeric_limits<T>::quiet_NaN();
  EXPECT_EQ(generateMeshContacts<T>(count, a, bad, a, Transform<T>(), found).code, StatusCode::InvalidArgument);
  EXPECT_EQ(generateMeshContacts<T>(MeshContactCallback<T>(), a, Transform<T>(), a, Transform<T>(), found).code,
            StatusCode::InvalidArgument);
  EXPECT_EQ(calls, 0);
  EXPECT_TRUE(found);  // untouched
}

}  // namespace
}  // namespace gq
