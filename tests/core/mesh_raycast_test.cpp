// Raycasts against triangle meshes: the rules of the spec section "Raycasts against Triangle Meshes", in float and
// double, on small meshes whose answers are known in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "gq/mesh_query.h"
#include "gq/query.h"
#include "gq/shape.h"
#include "mesh_test_helpers.h"

namespace gq {
namespace {

using meshtest::Scalars;

// Three draws of d in order, one per declarator: argument evaluation order is unspecified (GCC and clang differ).
template <class T, class Distribution> Vec3<T> draw3(Distribution& d, std::mt19937_64& rng) {
  const double x = d(rng), y = d(rng), z = d(rng);
  return Vec3<T>(T(x), T(y), T(z));
}

template <class T> class MeshRaycast : public ::testing::Test {
 protected:
  // Three unit-normal (+Z) squares at z = 0, 1, 2.
  MeshRaycast() {
    const MeshData<T> m = meshtest::quadStack<T>(3);
    mesh = meshtest::cook(m.vertices, m.triangles);
  }
  std::uint32_t cast(const Geometry<T>& g, const Transform<T>& pose, const Vec3<T>& o, const Vec3<T>& d, T maxDist,
                     HitFlags flags, std::uint32_t maxHits, RaycastHit<T>* hits) {
    std::uint32_t n = 0;
    const Status s = raycast(o, d, g, pose, maxDist, flags, maxHits, hits, n);
    EXPECT_TRUE(s.ok()) << s.toString();
    return n;
  }
  std::uint32_t castDown(const Geometry<T>& g, HitFlags flags, std::uint32_t maxHits, RaycastHit<T>* hits,
                         T maxDist = T(100)) {
    return cast(g, Transform<T>(), Vec3<T>(T(0.3), T(0.2), T(10)), Vec3<T>(0, 0, -1), maxDist, flags, maxHits, hits);
  }
  std::uint32_t castUp(const Geometry<T>& g, HitFlags flags, std::uint32_t maxHits, RaycastHit<T>* hits) {
    return cast(g, Transform<T>(), Vec3<T>(T(0.3), T(0.2), T(-10)), Vec3<T>(0, 0, 1), T(100), flags, maxHits, hits);
  }
  static constexpr T tol() { return std::is_same_v<T, float> ? T(2e-5) : T(1e-12); }
  std::shared_ptr<const TriangleMesh<T>> mesh;
};
TYPED_TEST_SUITE(MeshRaycast, Scalars);

TYPED_TEST(MeshRaycast, ClosestHitIsReturnedByDefault) {
  using T = TypeParam;
  RaycastHit<T> hit;
  ASSERT_EQ(this->castDown(TriangleMeshGeometry<T>(this->mesh), kDefaultHitFlags, 1, &hit), 1u);
  EXPECT_NEAR(hit.distance, T(8), this->tol());
  EXPECT_EQ(hit.faceIndex, 4u);  // top square, the y <= x half
  EXPECT_TRUE((hit.position - Vec3<T>(T(0.3), T(0.2), T(2))).norm() < this->tol());
  EXPECT_TRUE((hit.normal - Vec3<T>(0, 0, 1)).norm() < this->tol());
}

TYPED_TEST(MeshRaycast, AnyHitReturnsOneHitOnTheRay) {
  using T = TypeParam;
  RaycastHit<T> hit;
  ASSERT_EQ(this->castDown(TriangleMeshGeometry<T>(this->mesh), kDefaultHitFlags | HitFlag::AnyHit, 1, &hit), 1u);
  const T layer = T(10) - hit.distance;
  EXPECT_NEAR(layer, std::round(layer), this->tol());
  EXPECT_GE(std::round(layer), T(0));
  EXPECT_LE(std::round(layer), T(2));
  EXPECT_EQ(hit.faceIndex, std::uint32_t(2 * std::lround(layer)));
}

TYPED_TEST(MeshRaycast, MeshMultipleReturnsUpToMaxHitsClosestFirst) {
  using T = TypeParam;
  RaycastHit<T> hits[8];
  const TriangleMeshGeometry<T> g(this->mesh);
  ASSERT_EQ(this->castDown(g, kDefaultHitFlags | HitFlag::MeshMultiple, 2, hits), 2u);
  EXPECT_NEAR(hits[0].distance, T(8), this->tol());
  EXPECT_NEAR(hits[1].distance, T(9), this->tol());
  ASSERT_EQ(this->castDown(g, kDefaultHitFlags | HitFlag::MeshMultiple, 8, hits), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(hits[i].distance, T(8 + i), this->tol());
    EXPECT_EQ(hits[i].faceIndex, std::uint32_t(4 - 2 * i));
  }
  // maxHits > 1 without MeshMultiple still returns a single (closest) hit.
  ASSERT_EQ(this->castDown(g, kDefaultHitFlags, 8, hits), 1u);
  EXPECT_NEAR(hits[0].distance, T(8), this->tol());
}

TYPED_TEST(MeshRaycast, BackFacesAreCulledByDefault) {
  using T = TypeParam;
  RaycastHit<T> hit;
  EXPECT_EQ(this->castUp(TriangleMeshGeometry<T>(this->mesh), kDefaultHitFlags, 1, &hit), 0u);
  ASSERT_EQ(this->castDown(TriangleMeshGeometry<T>(this->mesh), kDefaultHitFlags, 1, &hit), 1u);
  EXPECT_LT(hit.normal.dot(Vec3<T>(0, 0, -1)), T(0));
}

TYPED_TEST(MeshRaycast, MeshBothSidesDisablesCullingWithoutFlippingTheNormal) {
  using T = TypeParam;
  RaycastHit<T> hit;
  ASSERT_EQ(this->castUp(TriangleMeshGeometry<T>(this->mesh), kDefaultHitFlags | HitFlag::MeshBothSides, 1, &hit),
            1u);
  EXPECT_NEAR(hit.distance, T(10), this->tol());
  EXPECT_TRUE((hit.normal - Vec3<T>(0, 0, 1)).norm() < this->tol());  // outward, along the ray
}

TYPED_TEST(MeshRaycast, DoubleSidedDisablesCullingAndFlipsBackFaceNormals) {
  using T = TypeParam;
  const TriangleMeshGeometry<T> g(this->mesh, MeshScale<T>(), MeshGeometryFlag::DoubleSided);
  RaycastHit<T> hit;
  ASSERT_EQ(this->castUp(g, kDefaultHitFlags, 1, &hit), 1u);
  EXPECT_NEAR(hit.distance, T(10), this->tol());
  EXPECT_TRUE((hit.normal - Vec3<T>(0, 0, -1)).norm() < this->tol());
  ASSERT_EQ(this->castDown(g, kDefaultHitFlags, 1, &hit), 1u);  // front faces keep their normal
  EXPECT_TRUE((hit.normal - Vec3<T>(0, 0, 1)).norm() < this->tol());
}

// The reported normal is (v1 - v0) x (v2 - v0) / sqrt(|.|^2) of the hit triangle's cooked vertices bit for bit, on
// both faces (negated on the back face of a double-sided mesh), through a prepared shape placed as cooked.
TYPED_TEST(MeshRaycast, NormalIsTheUnitCrossProductOfTheHitTriangleBitForBit) {
  using T = TypeParam;
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  int checked = 0;
  for (int k = 0; k < 300; ++k) {
    const std::vector<Vec3<T>> v = {draw3<T>(coordinate, rng), draw3<T>(coordinate, rng), draw3<T>(coordinate, rng)};
    const auto mesh = meshtest::cook(v, {{0u, 1u, 2u}});
    const Vec3<T> c[3] = {mesh->triangleVertex(0, 0), mesh->triangleVertex(0, 1), mesh->triangleVertex(0, 2)};
    const Vec3<T> n = (c[1] - c[0]).cross(c[2] - c[0]);
    if (!(n.squaredNorm() > T(1e-6))) continue;  // a sliver: its centroid ray may graze an edge
    const Vec3<T> unit = n / std::sqrt(n.squaredNorm());
    const Vec3<T> centroid = (c[0] + c[1] + c[2]) / T(3);
    for (const bool doubleSided : {false, true}) {
      Shape<T> shape;
      ASSERT_TRUE(Shape<T>::make(TriangleMeshGeometry<T>(mesh, MeshScale<T>(),
                                                         doubleSided ? MeshGeometryFlag::DoubleSided
                                                                     : MeshGeometryFlag::None),
                                 shape)
                      .ok());
      for (const T side : {T(1), T(-1)}) {  // +1: from the front, -1: from the back
        const Vec3<T> dir = -side * unit;
        RaycastHit<T> hit;
        std::uint32_t count = 0;
        ASSERT_TRUE(raycast(Vec3<T>(centroid - T(2) * dir), dir, shape, Transform<T>(), T(10),
                            kDefaultHitFlags | HitFlag::MeshBothSides, 1, &hit, count)
                        .ok());
        ASSERT_EQ(count, 1u);
        const Vec3<T> expected = doubleSided && side < T(0) ? Vec3<T>(-unit) : unit;
        EXPECT_EQ(hit.normal.x(), expected.x());
        EXPECT_EQ(hit.normal.y(), expected.y());
        EXPECT_EQ(hit.normal.z(), expected.z());
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 1000);
}

// Under an axis-aligned scale and a rotated pose the normal is R S^-1 ((v1 - v0) x (v2 - v0)) made unit as tryUnit
// does (n / sqrt(|n|^2)), bit for bit, and flipped for a double-sided mesh hit from the back.
TYPED_TEST(MeshRaycast, NormalUnderScaleAndPoseIsTheUnitTransformedCrossProductBitForBit) {
  using T = TypeParam;
  const MeshData<T> ico = meshtest::icosphere<T>(1);
  const auto mesh = meshtest::cook(ico.vertices, ico.triangles);
  const Vec3<T> s(T(1.5), T(0.7), T(2.2));
  const Transform<T> pose(Vec3<T>(1, -2, 3), Quat<T>(Eigen::AngleAxis<T>(T(1.1), Vec3<T>(-1, 0, 2).normalized())));
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(-1, 1);
  int checked = 0, flipped = 0;
  for (const bool doubleSided : {false, true}) {
    const TriangleMeshGeometry<T> g(mesh, MeshScale<T>(s),
                                    doubleSided ? MeshGeometryFlag::DoubleSided : MeshGeometryFlag::None);
    for (int i = 0; i < 200; ++i) {
      // Half the rays from outside (front faces), half from inside the closed mesh (back faces).
      const Vec3<T> target = pose.p + T(0.5) * draw3<T>(u, rng);
      const Vec3<T> o = i % 2 == 0 ? Vec3<T>(target + draw3<T>(u, rng).normalized() * T(10))
                                   : Vec3<T>(pose.p + T(0.1) * draw3<T>(u, rng));
      const Vec3<T> d = i % 2 == 0 ? Vec3<T>((target - o).normalized()) : Vec3<T>(draw3<T>(u, rng).normalized());
      RaycastHit<T> hit;
      if (this->cast(g, pose, o, d, T(100), kDefaultHitFlags | HitFlag::MeshBothSides, 1, &hit) == 0) continue;
      const std::uint32_t k = mesh->cookedIndex[hit.faceIndex];
      const Vec3<T> c[3] = {mesh->triangleVertex(k, 0), mesh->triangleVertex(k, 1), mesh->triangleVertex(k, 2)};
      Vec3<T> n = (c[1] - c[0]).cross(c[2] - c[0]);
      n = Vec3<T>(n.x() * (T(1) / s.x()), n.y() * (T(1) / s.y()), n.z() * (T(1) / s.z()));
      n = pose.rotate(n);
      Vec3<T> expected = n / std::sqrt(n.squaredNorm());
      if (doubleSided && expected.dot(d) > T(0)) {
        expected = -expected;
        ++flipped;
      }
      EXPECT_EQ(hit.normal.x(), expected.x());
      EXPECT_EQ(hit.normal.y(), expected.y());
      EXPECT_EQ(hit.normal.z(), expected.z());
      ++checked;
    }
  }
  EXPECT_GT(checked, 300);
  EXPECT_GT(flipped, 50);  // double-sided back hits: the flip is checked
}

TYPED_TEST(MeshRaycast, MaxDistZeroNeverHitsAMesh) {
  using T = TypeParam;
  RaycastHit<T> hit;
  // The origin lies exactly on the top square.
  EXPECT_EQ(this->cast(TriangleMeshGeometry<T>(this->mesh), Transform<T>(), Vec3<T>(T(0.3), T(0.2), T(2)),
                       Vec3<T>(0, 0, -1), T(0), kDefaultHitFlags, 1, &hit),
            0u);
}

TYPED_TEST(MeshRaycast, MaxDistBoundsTheHitDistance) {
  using T = TypeParam;
  RaycastHit<T> hit;
  const TriangleMeshGeometry<T> g(this->mesh);
  EXPECT_EQ(this->castDown(g, kDefaultHitFlags, 1, &hit, T(7.9)), 0u);
  ASSERT_EQ(this->castDown(g, kDefaultHitFlags, 1, &hit, T(8.1)), 1u);
  EXPECT_NEAR(hit.distance, T(8), this->tol());
}

TYPED_TEST(MeshRaycast, FlagsReportOnlyTheFieldsComputed) {
  using T = TypeParam;
  RaycastHit<T> hit;
  const TriangleMeshGeometry<T> g(this->mesh);
  ASSERT_EQ(this->castDown(g, HitFlags(HitFlag::FaceIndex), 1, &hit), 1u);
  EXPECT_FALSE(hit.flags.has(HitFlag::Position));
  EXPECT_FALSE(hit.flags.has(HitFlag::Normal));
  EXPECT_FALSE(hit.flags.has(HitFlag::UV));
  EXPECT_TRUE(hit.flags.has(HitFlag::FaceIndex));
  EXPECT_EQ(hit.position, Vec3<T>::Zero());  // skipped, left at the default
  EXPECT_EQ(hit.normal, Vec3<T>::Zero());
  EXPECT_NEAR(hit.distance, T(8), this->tol());
  RaycastHit<T> full;
  ASSERT_EQ(this->castDown(g, kDefaultHitFlags | HitFlag::UV, 1, &full), 1u);
  EXPECT_TRUE(full.flags.has(HitFlag::Position));
  EXPECT_TRUE(full.flags.has(HitFlag::Normal));
  EXPECT_TRUE(full.flags.has(HitFlag::UV));
}

TYPED_TEST(MeshRaycast, FaceIndexIsTheInputTriangleIndex) {
  using T = TypeParam;
  // Degenerate triangles first shift the cooked indices; the faces are listed top layer first.
  MeshData<T> m = meshtest::quadStack<T>(3);
  std::vector<TriangleIndices> tris = {{0, 0, 1}, {0, 1, 1}};
  for (int k = 2; k >= 0; --k) {
    tris.push_back(m.triangles[2 * k]);
    tris.push_back(m.triangles[2 * k + 1]);
  }
  const auto mesh = meshtest::cook(m.vertices, tris);
  RaycastHit<T> hits[3];
  ASSERT_EQ(this->castDown(TriangleMeshGeometry<T>(mesh), kDefaultHitFlags | HitFlag::MeshMultiple, 3, hits), 3u);
  EXPECT_EQ(hits[0].faceIndex, 2u);  // top square (z = 2), y <= x half
  EXPECT_EQ(hits[1].faceIndex, 4u);
  EXPECT_EQ(hits[2].faceIndex, 6u);
}

// Under pose, rotated non-uniform scale and mirroring: position = (1-u-v) v0 + u v1 + v v2 of getTriangle's
// triangle, the normal is getTriangle's (outward) normal, and the distance is the world distance.
TYPED_TEST(MeshRaycast, UVAndNormalMatchGetTriangleUnderScaleAndPose) {
  using T = TypeParam;
  const MeshData<T> ico = meshtest::icosphere<T>(2);
  const auto mesh = meshtest::cook(ico.vertices, ico.triangles);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  const T tolerance = std::is_same_v<T, float> ? T(2e-4) : T(1e-10);
  for (int mirrored = 0; mirrored < 2; ++mirrored) {
    const Vec3<T> s(T(mirrored ? -1.5 : 1.5), T(0.7), T(2.2));
    const MeshScale<T> scale(s, Quat<T>(Eigen::AngleAxis<T>(T(0.6), Vec3<T>(1, 2, 3).normalized())));
    const TriangleMeshGeometry<T> g(mesh, scale);
    const Transform<T> pose(Vec3<T>(1, -2, 3), Quat<T>(Eigen::AngleAxis<T>(T(1.1), Vec3<T>(-1, 0, 2).normalized())));
    int hitsSeen = 0;
    for (int i = 0; i < 200; ++i) {
      const Vec3<T> target = pose.p + draw3<T>(u, rng);
      const Vec3<T> o = target + draw3<T>(u, rng).normalized() * T(10);
      const Vec3<T> d = (target - o).normalized();
      RaycastHit<T> hit;
      if (this->cast(g, pose, o, d, T(100), kDefaultHitFlags | HitFlag::UV, 1, &hit) == 0) continue;
      ++hitsSeen;
      Triangle<T> tri;
      ASSERT_TRUE(getTriangle(g, pose, hit.faceIndex, tri).ok());
      EXPECT_LT((tri.pointFromUV(hit.u, hit.v) - hit.position).norm(), tolerance * T(10));
      EXPECT_LT((o + d * hit.distance - hit.position).norm(), tolerance * T(10));
      EXPECT_LT((tri.normal() - hit.normal).norm(), tolerance);
      EXPECT_LT(hit.normal.dot(d), T(0));
      EXPECT_GE(hit.u, -tolerance);
      EXPECT_GE(hit.v, -tolerance);
      EXPECT_LE(hit.u + hit.v, T(1) + tolerance);
    }
    EXPECT_GT(hitsSeen, 100);
  }
}

TYPED_TEST(MeshRaycast, NonUniformScaleReportsWorldDistance) {
  using T = TypeParam;
  // Scale (2, 3, 0.5) puts the squares at z = 0, 0.5, 1 and widens them to [-2,2] x [-3,3].
  const TriangleMeshGeometry<T> g(this->mesh, MeshScale<T>(Vec3<T>(2, 3, T(0.5))));
  const Transform<T> pose(Vec3<T>(0, 0, 5));
  RaycastHit<T> hit;
  ASSERT_EQ(this->cast(g, pose, Vec3<T>(T(1.5), T(-2.5), T(10)), Vec3<T>(0, 0, -1), T(100), kDefaultHitFlags, 1,
                       &hit),
            1u);
  EXPECT_NEAR(hit.distance, T(4), this->tol() * 10);
  EXPECT_TRUE((hit.position - Vec3<T>(T(1.5), T(-2.5), T(6))).norm() < this->tol() * 10);
}

TYPED_TEST(MeshRaycast, MirroredScaleSwapsVerticesAndKeepsNormalsOutward) {
  using T = TypeParam;
  const TriangleMeshGeometry<T> g(this->mesh, MeshScale<T>(Vec3<T>(-1, 1, 1)));
  Triangle<T> tri;
  std::uint32_t idx[3];
  ASSERT_TRUE(getTriangle(g, Transform<T>(), 4, tri, idx).ok());
  EXPECT_EQ(idx[0], 8u);
  EXPECT_EQ(idx[1], 10u);  // input triangle 4 is (8, 9, 10)
  EXPECT_EQ(idx[2], 9u);
  EXPECT_TRUE((tri.verts[1] - Vec3<T>(-1, 1, 2)).norm() < this->tol());
  EXPECT_TRUE((tri.normal() - Vec3<T>(0, 0, 1)).norm() < this->tol());
  RaycastHit<T> hit;
  // Mirrored, the y <= x half of the top square lies at x <= -y: (-0.3, 0.2) is in it.
  ASSERT_EQ(this->cast(g, Transform<T>(), Vec3<T>(T(-0.3), T(0.2), T(10)), Vec3<T>(0, 0, -1), T(100),
                       kDefaultHitFlags | HitFlag::UV, 1, &hit),
            1u);
  EXPECT_EQ(hit.faceIndex, 4u);
  EXPECT_TRUE((hit.normal - Vec3<T>(0, 0, 1)).norm() < this->tol());
  EXPECT_TRUE((tri.pointFromUV(hit.u, hit.v) - hit.position).norm() < this->tol() * 10);
}

TYPED_TEST(MeshRaycast, GetTriangleRejectsInvalidIndex) {
  using T = TypeParam;
  Triangle<T> tri;
  tri.verts[0] = Vec3<T>(7, 7, 7);
  const TriangleMeshGeometry<T> g(this->mesh);
  const Status s = getTriangle(g, Transform<T>(), 6, tri);
  EXPECT_EQ(s.code, StatusCode::InvalidArgument);
  EXPECT_NE(s.toString().find("6"), std::string::npos);
  EXPECT_EQ(tri.verts[0], Vec3<T>(7, 7, 7));  // untouched
}

// Rays aimed exactly at every vertex and every edge midpoint of a closed icosphere, from outside, must hit:
// the watertight test leaves no gap along shared edges or at shared vertices.
TYPED_TEST(MeshRaycast, WatertightRaysThroughEdgesAndVerticesOfAClosedMeshAlwaysHit) {
  using T = TypeParam;
  const MeshData<T> ico = meshtest::icosphere<T>(3);
  ASSERT_EQ(ico.triangles.size(), 1280u);
  const auto mesh = meshtest::cook(ico.vertices, ico.triangles);
  const TriangleMeshGeometry<T> g(mesh);
  std::vector<Vec3<T>> targets(ico.vertices);
  for (const auto& t : ico.triangles)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t[k], b = t[(k + 1) % 3];
      if (a < b) targets.push_back((ico.vertices[a] + ico.vertices[b]) * T(0.5));
    }
  ASSERT_EQ(targets.size(), 642u + 1920u);
  std::mt19937_64 rng(11);
  std::normal_distribution<double> n;
  int misses = 0;
  for (const Vec3<T>& target : targets) {
    for (int r = 0; r < 4; ++r) {
      // Origins outside the sphere, on the target's side (r = 0: exactly radial).
      // Others within ~45 degrees of it, so the ray enters the (convex) mesh at the target.
      Vec3<T> offset = target.normalized() * T(2);
      while (r > 0) {
        const Vec3<T> tilted = offset + draw3<T>(n, rng) * T(0.8);
        if (tilted.normalized().dot(target.normalized()) > T(0.7)) {
          offset = tilted;
          break;
        }
      }
      const Vec3<T> o = target + offset;
      const Vec3<T> d = (target - o).normalized();
      RaycastHit<T> hit;
      std::uint32_t count = 0;
      ASSERT_TRUE(raycast(o, d, Geometry<T>(g), Transform<T>(), T(10), kDefaultHitFlags, 1, &hit, count).ok());
      if (count == 0) {
        ++misses;
        continue;
      }
      const T distTol = std::is_same_v<T, float> ? T(1e-5) : T(1e-13);
      EXPECT_NEAR(hit.distance, (target - o).norm(), distTol);
    }
  }
  EXPECT_EQ(misses, 0);
}

}  // namespace
}  // namespace gq
