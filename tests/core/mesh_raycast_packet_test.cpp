// The wide watertight test of a leaf's 4 triangles (bvh/triangle_exact4.h) must never drop a triangle that the scalar
// watertight test in T hits (otherwise mesh raycasts would leak or lose the closest hit), the hits it decides alone
// must be the scalar test's bit for bit, and it must drop triangles the ray misses. Checked on 4-triangle meshes (one
// leaf) of many sizes and offsets, with rays aimed at vertices, edge points and interiors, grazing rays and tight maxT,
// in float (4 lanes per register) and double (2; 4 in the AVX2 walk's form, which must give the same bits).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "bvh/build.h"
#include "bvh/triangle_exact4.h"
#include "mesh/triangle.h"
#include "mesh_test_helpers.h"

namespace gq {
namespace {

using meshtest::Scalars;

template <class T> class MeshRaycastPacket : public ::testing::Test {};
TYPED_TEST_SUITE(MeshRaycastPacket, Scalars);

// Three draws of n in order, one per declarator: argument evaluation order is unspecified (GCC and clang differ).
Eigen::Vector3d normal3(std::normal_distribution<double>& n, std::mt19937_64& rng) {
  const double x = n(rng), y = n(rng), z = n(rng);
  return {x, y, z};
}

// Four random triangles of edge length ~size around `center` (a fan sharing vertex 0 plus one apart).
template <class T> MeshData<T> randomLeaf(std::mt19937_64& rng, const Vec3<T>& center, double size) {
  std::normal_distribution<double> n;
  auto jitter = [&]() -> Eigen::Vector3d { return normal3(n, rng) * size; };
  MeshData<T> m;
  const Eigen::Vector3d c = center.template cast<double>();
  for (int i = 0; i < 6; ++i) m.vertices.push_back((c + jitter()).template cast<T>());
  m.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {5, 4, 1}};
  return m;
}

#ifdef GQ_SSE42
// The test as the AVX2 walk runs it (double 4 lanes to a register), inlined into AVX2 code as there.
template <class T>
__attribute__((target("avx2"), flatten)) int exactTriangleHitsAvx2(const detail::LeafRows<T>& tris,
                                                                   const detail::WatertightRay4<T>& ray, T maxT,
                                                                   bool cull, detail::TriangleHits4<T>& hits) {
  return detail::exactTriangleHits<T, true>(tris, ray, maxT, cull, hits);
}
#endif

// The AVX2 form's mask and decided hits equal the baseline's, bit for bit (CPUs without AVX2 run only the baseline).
// Double: a different kernel (4 lanes to a 256-bit register). Float: the same 4-lane kernel compiled into AVX2 code,
// which must not change an operation (no contraction to FMA); the AVX2 walk's float loader is checked apart below.
template <class T>
void expectAvx2FormAgrees(const detail::LeafRows<T>& tris, const detail::WatertightRay4<T>& ray, T maxT,
                          bool cull, int mask, const detail::TriangleHits4<T>& hits) {
#ifdef GQ_SSE42
  if (!__builtin_cpu_supports("avx2")) return;
  detail::TriangleHits4<T> wide;
  EXPECT_EQ(exactTriangleHitsAvx2(tris, ray, maxT, cull, wide), mask);
  EXPECT_EQ(wide.decided, hits.decided);
  EXPECT_EQ(wide.frontMask, hits.frontMask);
  for (int i = 0; i < 4; ++i) {
    if (!((hits.decided >> i) & 1)) continue;
    EXPECT_EQ(std::memcmp(&wide.t[i], &hits.t[i], sizeof(T)), 0);
    EXPECT_EQ(std::memcmp(&wide.u[i], &hits.u[i], sizeof(T)), 0);
    EXPECT_EQ(std::memcmp(&wide.v[i], &hits.v[i], sizeof(T)), 0);
  }
#else
  (void)tris, (void)ray, (void)maxT, (void)cull, (void)mask, (void)hits;
#endif
}

struct Counts {
  int exactHits = 0, missed = 0, rejected = 0, tested = 0;
  int decided = 0;  // hits the wide test computed itself
};

// The root leaf's triangles as the raycast reads them: the mesh's leaf rows, stride the leaf's triangle count.
template <class T> detail::LeafRows<T> leafTriangles(const TriangleMesh<T>& mesh) {
  return {mesh.leafVertices.data(), MeshBvhNode::leafCount(mesh.accel->bvh.rootChild)};
}

// Fires the rays at the leaf and checks the wide test against the scalar test for both culling modes.
template <class T>
void checkLeaf(const TriangleMesh<T>& mesh, const std::vector<Vec3<T>>& origins, const std::vector<Vec3<T>>& targets,
               bool tightMaxT, Counts& counts) {
  ASSERT_TRUE(MeshBvhNode::isLeaf(mesh.accel->bvh.rootChild));
  const std::uint32_t count = MeshBvhNode::leafCount(mesh.accel->bvh.rootChild);
  const detail::LeafRows<T> tris = leafTriangles(mesh);
  for (std::size_t r = 0; r < origins.size(); ++r) {
    const Vec3<T> dir = (targets[r] - origins[r]).normalized();
    const detail::WatertightRay<T> exactRay = detail::makeWatertightRay(origins[r], dir);
    const detail::WatertightRay4<T> wideRay = detail::makeWatertightRay4(exactRay);
    for (bool cull : {false, true}) {
      T maxT = std::numeric_limits<T>::max() / T(4);
      if (tightMaxT) {  // the exact distance of the first triangle hit, so t == maxT must still be kept
        for (std::uint32_t i = 0; i < count; ++i) {
          detail::TriangleRayHit<T> h;
          if (detail::intersectRayTriangle(exactRay, mesh.triangleVertex(i, 0), mesh.triangleVertex(i, 1),
                                           mesh.triangleVertex(i, 2), maxT, cull, h)) {
            maxT = h.t;
            break;
          }
        }
      }
      detail::TriangleHits4<T> laneHits;
      const int mask = detail::exactTriangleHits(tris, wideRay, maxT, cull, laneHits);
      expectAvx2FormAgrees(tris, wideRay, maxT, cull, mask, laneHits);
      for (std::uint32_t i = 0; i < count; ++i) {
        detail::TriangleRayHit<T> h;
        const bool exact = detail::intersectRayTriangle(exactRay, mesh.triangleVertex(i, 0), mesh.triangleVertex(i, 1),
                                                        mesh.triangleVertex(i, 2), maxT, cull, h);
        if ((laneHits.decided >> i) & 1) {  // a lane decided wide: the scalar test's hit, bit for bit
          ++counts.decided;
          EXPECT_TRUE(exact) << "the wide test decided a lane the scalar test rejects";
          if (exact) {
            EXPECT_EQ(laneHits.t[i], h.t);
            EXPECT_EQ(laneHits.u[i], h.u);
            EXPECT_EQ(laneHits.v[i], h.v);
            EXPECT_EQ(((laneHits.frontMask >> i) & 1) != 0, h.frontFace);
          }
        }
        const bool kept = (mask >> i) & 1;
        ++counts.tested;
        counts.exactHits += exact;
        counts.rejected += !kept;
        if (exact && !kept) ++counts.missed;
      }
    }
  }
}

TYPED_TEST(MeshRaycastPacket, WideTestKeepsEveryTriangleTheScalarTestHitsAndDecidesItsHitsBitForBit) {
  using T = TypeParam;
  std::mt19937_64 rng(77);
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> n;
  Counts counts;
  for (int leaf = 0; leaf < 300; ++leaf) {
    const double size = std::pow(10.0, -4.0 + 4.0 * u(rng));      // edge lengths 1e-4 .. 1
    const double offset = size * std::pow(10.0, 3.0 * u(rng));     // mesh 1 .. 1000 sizes away from the frame origin
    const Vec3<T> center = (normal3(n, rng).normalized() * offset).template cast<T>();
    const MeshData<T> m = randomLeaf<T>(rng, center, size);
    const auto mesh = meshtest::cook(m.vertices, m.triangles);
    ASSERT_NE(mesh, nullptr);
    ASSERT_EQ(mesh->triangles.size(), 4u);
    std::vector<Vec3<T>> origins, targets;
    for (int r = 0; r < 40; ++r) {
      const auto& tri = mesh->triangles[r % 4];
      const Vec3<T>& a = mesh->vertices[tri[0]];
      const Vec3<T>& b = mesh->vertices[tri[1]];
      const Vec3<T>& c = mesh->vertices[tri[2]];
      Vec3<T> target;
      switch (r % 5) {
        case 0: target = a; break;                                     // a shared vertex
        case 1: target = a + (b - a) * T(u(rng)); break;               // an edge point (rounded in T)
        case 2: target = b + (c - b) * T(0.5); break;                  // an edge midpoint
        case 3: {                                                       // an interior point
          double s = u(rng), t = u(rng);
          if (s + t > 1) { s = 1 - s; t = 1 - t; }
          target = a + (b - a) * T(s) + (c - a) * T(t);
          break;
        }
        default: target = c + (c - a) * T(0.01); break;                // just outside a vertex
      }
      // Origins from very near (grazing, close range) to far (100x the offset) away.
      const double dist = size * std::pow(10.0, -2.0 + 6.0 * u(rng));
      Eigen::Vector3d away = normal3(n, rng).normalized();
      if (r % 7 == 0) {  // nearly in the plane of the triangle
        const Eigen::Vector3d nrm = (b - a).cross(c - a).template cast<double>().normalized();
        away = (away - nrm * nrm.dot(away) * (1.0 - 1e-6)).normalized();
      }
      origins.push_back((target.template cast<double>() + away * dist).template cast<T>());
      targets.push_back(target);
    }
    checkLeaf(*mesh, origins, targets, leaf % 2 == 0, counts);
  }
  EXPECT_EQ(counts.missed, 0);
  EXPECT_GT(counts.exactHits, counts.tested / 10);  // the rays do hit: the check is not vacuous
  EXPECT_GT(counts.decided, counts.exactHits / 2);
}

TYPED_TEST(MeshRaycastPacket, WideTestRejectsTrianglesTheRayMisses) {
  using T = TypeParam;
  // Four unit triangles side by side in z = 0 (x in [0,1], [2,3], [4,5], [6,7]), seen from far above: a ray at the
  // interior of one of them must keep only that one.
  MeshData<T> m;
  for (int i = 0; i < 4; ++i) {
    const T x = T(2 * i);
    const auto base = std::uint32_t(m.vertices.size());
    m.vertices.push_back(Vec3<T>(x, T(0), T(0)));
    m.vertices.push_back(Vec3<T>(x + T(1), T(0), T(0)));
    m.vertices.push_back(Vec3<T>(x, T(1), T(0)));
    m.triangles.push_back({base, base + 1, base + 2});
  }
  const auto mesh = meshtest::cook(m.vertices, m.triangles);
  ASSERT_NE(mesh, nullptr);
  ASSERT_TRUE(MeshBvhNode::isLeaf(mesh->accel->bvh.rootChild));
  const detail::LeafRows<T> tris = leafTriangles(*mesh);
  auto candidates = [&](const Vec3<T>& origin, const Vec3<T>& dir, T maxT, bool cull) {
    detail::TriangleHits4<T> hits;
    return detail::exactTriangleHits(tris, detail::makeWatertightRay4(detail::makeWatertightRay(origin, dir)), maxT,
                                     cull, hits);
  };
  for (int i = 0; i < 4; ++i) {
    const Vec3<T> target(T(2 * i) + T(0.25), T(0.25), T(0));
    const Vec3<T> origin = target + Vec3<T>(T(0.3), T(-0.2), T(100));
    const Vec3<T> dir = (target - origin).normalized();
    const int mask = candidates(origin, dir, T(1e6), false);
    // The cooked order may differ from the input order: map the kept lane back to the input triangle.
    ASSERT_EQ(__builtin_popcount(unsigned(mask)), 1);
    EXPECT_EQ(mesh->inputIndex[std::uint32_t(__builtin_ctz(unsigned(mask)))], std::uint32_t(i));
    // The triangles face +z: a ray going up (-dir from below) sees back faces only, so culling drops them all.
    const Vec3<T> below = target - Vec3<T>(T(0.3), T(-0.2), T(100));
    EXPECT_EQ(candidates(below, Vec3<T>(-dir), T(1e6), true), 0);
    // maxT short of the plane drops the triangle too.
    EXPECT_EQ(candidates(origin, dir, T(50), false), 0);
  }
}

#ifdef GQ_SSE42
// The float mesh caster's watertight constants come from SSE registers (makeWatertightRay4Sse): the dominant axis,
// the swap and the shear must be makeWatertightRay's bit for bit, ties between components and signed zeros included,
// or the wide and scalar tests would disagree with the scalar test on shared edges.
TEST(WatertightRaySse, ConstantsAreTheScalarConstructionsBitForBit) {
  std::mt19937_64 rng(41);
  std::normal_distribution<double> n;
  std::uniform_int_distribution<int> pick(0, 5);
  const float special[6] = {0.0f, -0.0f, 0.5f, -0.5f, 1.0f, -1.0f};
  int checked = 0;
  for (int i = 0; i < 200000; ++i) {
    const Eigen::Vector3d g = normal3(n, rng);
    Vec3<float> dir = g.normalized().cast<float>();
    // Every third ray has components drawn from a few values, so ties (|x| = |y|, ...) and signed zeros occur.
    if (i % 3 == 0) dir = Vec3<float>(special[pick(rng)], special[pick(rng)], special[pick(rng)]);
    if (dir.cwiseAbs().maxCoeff() == 0.0f) continue;
    const Vec3<float> org = (normal3(n, rng) * 10.0).cast<float>();
    const detail::WatertightRay4<float> expected = detail::makeWatertightRay4(detail::makeWatertightRay(org, dir));
    const detail::WatertightRay4<float> sse =
        detail::makeWatertightRay4Sse(_mm_setr_ps(org.x(), org.y(), org.z(), 0.0f),
                                      _mm_setr_ps(dir.x(), dir.y(), dir.z(), 0.0f));
    ASSERT_EQ(std::memcmp(&expected, &sse, sizeof sse), 0)
        << "dir " << dir.transpose() << ": kx " << sse.ray.kx << " ky " << sse.ray.ky << " kz " << sse.ray.kz
        << " (expected " << expected.ray.kx << " " << expected.ray.ky << " " << expected.ray.kz << ")";
    ++checked;
  }
  EXPECT_GT(checked, 190000);
}
#endif

}  // namespace
}  // namespace gq
