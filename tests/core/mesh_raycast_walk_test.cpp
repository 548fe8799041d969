// Mesh raycasts walk a tree of 8-wide nodes: with AVX2 on CPUs that have it, on the SSE4.2 baseline as two 4-lane
// halves per node otherwise. Both walks must give the same hits (closest, any and multiple, both culling modes, float
// and double), and the tree must hold every triangle in exactly one leaf under boxes that contain it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <vector>

#include "bvh/build.h"
#include "gq/query.h"
#include "gq/shape.h"
#include "mesh/triangle.h"
#include "mesh_test_helpers.h"
#include "raycast/raycast.h"

namespace gq {
namespace {

using meshtest::Scalars;

template <class T> class MeshRaycastWalks : public ::testing::Test {};
TYPED_TEST_SUITE(MeshRaycastWalks, Scalars);

// Every field of the hits, bit for bit.
template <class T> bool sameHits(const std::vector<RaycastHit<T>>& a, const std::vector<RaycastHit<T>>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const RaycastHit<T>& x = a[i];
    const RaycastHit<T>& y = b[i];
    if (x.flags != y.flags || x.faceIndex != y.faceIndex) return false;
    if (std::memcmp(&x.distance, &y.distance, sizeof(T)) != 0 || std::memcmp(&x.u, &y.u, sizeof(T)) != 0 ||
        std::memcmp(&x.v, &y.v, sizeof(T)) != 0 || x.position != y.position || x.normal != y.normal)
      return false;
  }
  return true;
}

// Rays from a sphere around the mesh, half aimed at vertices (shared edges and vertices: ties between triangles),
// half at random points of the bounds.
template <class T> void rays(const MeshData<T>& m, int count, std::vector<Vec3<T>>& origins,
                             std::vector<Vec3<T>>& dirs) {
  Bounds3<double> b;
  for (const auto& v : m.vertices) b.include(v.template cast<double>());
  const Vec3<double> c = b.center();
  const double radius = (b.max - b.min).norm();
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> n;
  for (int i = 0; i < count; ++i) {
    const double x = n(rng), y = n(rng), z = n(rng);
    const Vec3<double> o = c + Vec3<double>(x, y, z).normalized() * radius;
    Vec3<double> target;
    if (i % 2 == 0) {
      target = m.vertices[std::size_t(u(rng) * double(m.vertices.size())) % m.vertices.size()].template cast<double>();
    } else {
      target = b.min + (b.max - b.min).cwiseProduct(Vec3<double>(u(rng), u(rng), u(rng)));
    }
    origins.push_back(o.cast<T>());
    dirs.push_back((target - o).normalized().cast<T>());
  }
}

// The hits of every ray in every mode, with the walk chosen by `baselineOnly`.
template <class T>
std::vector<std::vector<RaycastHit<T>>> castAll(const Shape<T>& shape, const std::vector<Vec3<T>>& origins,
                                                const std::vector<Vec3<T>>& dirs, bool baselineOnly) {
  detail::setMeshRaycastBaselineOnly(baselineOnly);
  const HitFlags base = kDefaultHitFlags | HitFlag::UV;
  const HitFlags modes[] = {base, base | HitFlag::MeshBothSides, base | HitFlag::AnyHit,
                            base | HitFlag::MeshBothSides | HitFlag::AnyHit,
                            base | HitFlag::MeshBothSides | HitFlag::MeshMultiple};
  std::vector<std::vector<RaycastHit<T>>> out;
  for (const HitFlags flags : modes) {
    const std::uint32_t maxHits = flags.has(HitFlag::MeshMultiple) ? 8 : 1;
    for (std::size_t i = 0; i < origins.size(); ++i) {
      std::vector<RaycastHit<T>> hits(maxHits);
      std::uint32_t n = 0;
      EXPECT_TRUE(raycast(origins[i], dirs[i], shape, Transform<T>(), T(100), flags, maxHits, hits.data(), n).ok());
      hits.resize(n);
      out.push_back(hits);
    }
  }
  detail::setMeshRaycastBaselineOnly(false);
  return out;
}

template <class T> void checkSameHits(const MeshData<T>& m, int rayCount) {
  Shape<T> shape;
  ASSERT_TRUE(Shape<T>::make(TriangleMeshGeometry<T>(meshtest::cook(m.vertices, m.triangles)), shape).ok());
  std::vector<Vec3<T>> origins, dirs;
  rays(m, rayCount, origins, dirs);
  const auto wide = castAll(shape, origins, dirs, false);
  const auto baseline = castAll(shape, origins, dirs, true);
  ASSERT_EQ(wide.size(), baseline.size());
  std::size_t hits = 0, differ = 0;
  for (std::size_t i = 0; i < wide.size(); ++i) {
    hits += wide[i].size();
    differ += !sameHits(wide[i], baseline[i]);
  }
  EXPECT_EQ(differ, 0u);
  EXPECT_GT(hits, wide.size() / 4);  // the rays do hit: the comparison is not of empty answers
}

TYPED_TEST(MeshRaycastWalks, Avx2AndBaselineWalksFindTheSameHitsOnAnIcosphere) {
  if (!__builtin_cpu_supports("avx2")) GTEST_SKIP() << "this CPU has no AVX2: both walks are the baseline";
  checkSameHits(meshtest::icosphere<TypeParam>(4), 4000);
}

TYPED_TEST(MeshRaycastWalks, Avx2AndBaselineWalksFindTheSameHitsOnTheBunny) {
  if (!__builtin_cpu_supports("avx2")) GTEST_SKIP() << "this CPU has no AVX2: both walks are the baseline";
  GQ_REQUIRE_BUNNY();
  checkSameHits(meshtest::bunny<TypeParam>(), 4000);
}

// Leaves of a tree (a set of references) and whether every child box contains its subtree's leaf boxes.
template <int W> struct TreeWalk {
  const Bvh<W>& bvh;
  const std::vector<Bounds3<float>>& leafBoxes;  // by first primitive: the union of the leaf's triangle boxes
  std::vector<std::uint32_t> leaves;
  bool contained = true;

  Bounds3<float> visit(std::uint32_t ref) {
    if (BvhNode<W>::isLeaf(ref)) {
      leaves.push_back(ref);
      return leafBoxes[BvhNode<W>::leafFirst(ref)];
    }
    const BvhNode<W>& n = bvh.nodes[ref];
    Bounds3<float> all;
    for (int i = 0; i < W; ++i) {
      if (n.child[i] == BvhNode<W>::kEmpty) continue;
      const Bounds3<float> inside = visit(n.child[i]);
      const Bounds3<float> box = Bounds3<float>::fromMinMax(Vec3<float>(n.minX[i], n.minY[i], n.minZ[i]),
                                                            Vec3<float>(n.maxX[i], n.maxY[i], n.maxZ[i]));
      contained = contained && (box.min.array() <= inside.min.array()).all() &&
                  (box.max.array() >= inside.max.array()).all();
      all.include(box);
    }
    return all;
  }
};

// The closest hit is the least distance, then the least input index, over every triangle the watertight test hits at
// t <= maxDist, bit for bit, whichever walk runs: brute force over all triangles, on rays aimed at vertices (ties
// between the triangles around them) and at random points, both culling modes, and maxDist equal to the hit distance
// itself (a hit at the bound is kept, by the any-hit and all-hits modes too, whose first hit has that distance).
TYPED_TEST(MeshRaycastWalks, ClosestHitIsTheLeastDistanceThenInputIndexOverAllTriangles) {
  using T = TypeParam;
  const MeshData<T> m = meshtest::icosphere<T>(3);
  const auto mesh = meshtest::cook(m.vertices, m.triangles);
  Shape<T> shape;
  ASSERT_TRUE(Shape<T>::make(TriangleMeshGeometry<T>(mesh), shape).ok());
  std::vector<Vec3<T>> origins, dirs;
  rays(m, 2000, origins, dirs);
  std::size_t hits = 0, differ = 0;
  for (const bool baselineOnly : {false, true}) {
    detail::setMeshRaycastBaselineOnly(baselineOnly);
    for (const bool bothSides : {false, true}) {
      for (std::size_t r = 0; r < origins.size(); ++r) {
        // Brute force: the least (t, input index).
        const detail::WatertightRay<T> ray = detail::makeWatertightRay(origins[r], dirs[r]);
        bool found = false;
        std::uint32_t bestCooked = 0;
        detail::TriangleRayHit<T> best;
        for (std::uint32_t c = 0; c < mesh->inputIndex.size(); ++c) {
          const Vec3<T> v[3] = {mesh->triangleVertex(c, 0), mesh->triangleVertex(c, 1), mesh->triangleVertex(c, 2)};
          detail::TriangleRayHit<T> h;
          if (!detail::intersectRayTriangle(ray, v[0], v[1], v[2], std::numeric_limits<T>::infinity(), !bothSides, h))
            continue;
          if (found && !(h.t < best.t || (h.t == best.t && mesh->inputIndex[c] < mesh->inputIndex[bestCooked]))) continue;
          found = true;
          best = h;
          bestCooked = c;
        }
        const HitFlags flags = kDefaultHitFlags | HitFlag::UV | (bothSides ? HitFlag::MeshBothSides : HitFlags());
        for (const T maxDist : {T(100), found ? best.t : T(100)}) {
          RaycastHit<T> hit;
          std::uint32_t n = 0;
          ASSERT_TRUE(raycast(origins[r], dirs[r], shape, Transform<T>(), maxDist, flags, 1, &hit, n).ok());
          hits += n;
          differ += n != (found ? 1u : 0u) ||
                    (found && (hit.faceIndex != mesh->inputIndex[bestCooked] ||
                               std::memcmp(&hit.distance, &best.t, sizeof(T)) != 0 ||
                               std::memcmp(&hit.u, &best.u, sizeof(T)) != 0 || std::memcmp(&hit.v, &best.v, sizeof(T)) != 0));
          // Any hit and all hits find one within the same bound (the closest one's distance included).
          RaycastHit<T> all[4];
          std::uint32_t anyCount = 0, allCount = 0;
          ASSERT_TRUE(raycast(origins[r], dirs[r], shape, Transform<T>(), maxDist, flags | HitFlag::AnyHit, 1, &hit,
                              anyCount).ok());
          ASSERT_TRUE(raycast(origins[r], dirs[r], shape, Transform<T>(), maxDist, flags | HitFlag::MeshMultiple, 4,
                              all, allCount).ok());
          differ += (anyCount == 1) != found || (anyCount == 1 && !(hit.distance <= maxDist));
          differ += (allCount >= 1) != found ||
                    (allCount >= 1 && std::memcmp(&all[0].distance, &best.t, sizeof(T)) != 0);
        }
      }
    }
  }
  detail::setMeshRaycastBaselineOnly(false);
  EXPECT_EQ(differ, 0u);
  EXPECT_GT(hits, origins.size());  // most rays hit: the comparison is not of empty answers
}

// A double ray whose origin is beyond float's range (1e39, the mesh's radius 1e38): its float slab distances are
// infinite or NaN on the axes whose origin overflows (all three for about a fifth of these rays), so node tests may
// enter empty lanes (emptyBvhLaneBox); the walk skips them (a leaf reference read from an empty lane would index far
// past the triangles) and both walks still find the closest hit of brute force, as closest, any and all hits.
TEST(MeshRaycastWalks, RaysFromBeyondTheFloatRangeSkipEmptyLanesAndFindTheClosestHit) {
  MeshData<double> m = meshtest::icosphere<double>(2);
  for (auto& v : m.vertices) v *= 1e38;
  const auto mesh = meshtest::cook(m.vertices, m.triangles);
  Shape<double> shape;
  ASSERT_TRUE(Shape<double>::make(TriangleMeshGeometry<double>(mesh), shape).ok());
  struct BaselineReset {
    ~BaselineReset() { detail::setMeshRaycastBaselineOnly(false); }
  } reset;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::mt19937_64 rng(11);
  std::normal_distribution<double> n;
  std::size_t hits = 0, differ = 0;
  for (const bool baselineOnly : {false, true}) {
    detail::setMeshRaycastBaselineOnly(baselineOnly);
    for (int r = 0; r < 200; ++r) {
      const Vec3<double> dir = -Vec3<double>(n(rng), n(rng), n(rng)).normalized();
      const Vec3<double> origin = -dir * 1e39 + Vec3<double>(n(rng), n(rng), n(rng)) * 2e37;
      const detail::WatertightRay<double> ray = detail::makeWatertightRay(origin, dir);
      double best = kInf;
      for (std::uint32_t c = 0; c < mesh->inputIndex.size(); ++c) {
        const Vec3<double> v[3] = {mesh->triangleVertex(c, 0), mesh->triangleVertex(c, 1), mesh->triangleVertex(c, 2)};
        detail::TriangleRayHit<double> h;
        if (detail::intersectRayTriangle(ray, v[0], v[1], v[2], kInf, true, h)) best = std::min(best, h.t);
      }
      const bool found = best < kInf;
      RaycastHit<double> hit, all[4];
      std::uint32_t count = 0, anyCount = 0, allCount = 0;
      ASSERT_TRUE(raycast(origin, dir, shape, Transform<double>(), kInf, kDefaultHitFlags, 1, &hit, count).ok());
      hits += count;
      differ += (count == 1) != found || (count == 1 && hit.distance != best);
      ASSERT_TRUE(raycast(origin, dir, shape, Transform<double>(), kInf, kDefaultHitFlags | HitFlag::AnyHit, 1, &hit,
                          anyCount).ok());
      differ += (anyCount == 1) != found;
      ASSERT_TRUE(raycast(origin, dir, shape, Transform<double>(), kInf, kDefaultHitFlags | HitFlag::MeshMultiple, 4,
                          all, allCount).ok());
      differ += (allCount >= 1) != found || (allCount >= 1 && all[0].distance != best);
    }
  }
  EXPECT_EQ(differ, 0u);
  EXPECT_GT(hits, 300u);  // the rays aim at the sphere: most hit
}

// The tree over the triangle boxes of an icosphere of 20,480 triangles.
Bvh8 icosphereTree(std::vector<Bounds3<float>>& prims, std::vector<std::uint32_t>& order) {
  const MeshData<float> m = meshtest::icosphere<float>(5);
  for (const auto& t : m.triangles) {
    Bounds3<float> b;
    for (std::uint32_t v : t) b.include(m.vertices[v]);
    prims.push_back(b);
  }
  return detail::buildBvh8(prims, order);
}

TEST(MeshRaycastWalks, EveryTriangleIsInOneLeafUnderContainingBoxes) {
  std::vector<Bounds3<float>> prims;
  std::vector<std::uint32_t> order;
  const Bvh8 bvh = icosphereTree(prims, order);
  std::vector<std::uint32_t> sortedOrder = order;
  std::sort(sortedOrder.begin(), sortedOrder.end());
  for (std::uint32_t i = 0; i < sortedOrder.size(); ++i) ASSERT_EQ(sortedOrder[i], i) << "order is a permutation";
  std::vector<Bounds3<float>> leafBoxes(prims.size());
  TreeWalk<8> collect{bvh, leafBoxes};
  collect.visit(bvh.rootChild);  // the leaves; their boxes are filled next
  std::vector<int> covered(prims.size(), 0);
  for (std::uint32_t ref : collect.leaves) {
    Bounds3<float> b;
    for (std::uint32_t k = 0; k < Bvh8Node::leafCount(ref); ++k) {
      b.include(prims[order[Bvh8Node::leafFirst(ref) + k]]);
      ++covered[Bvh8Node::leafFirst(ref) + k];
    }
    leafBoxes[Bvh8Node::leafFirst(ref)] = b;
  }
  EXPECT_TRUE(std::all_of(covered.begin(), covered.end(), [](int c) { return c == 1; }));
  TreeWalk<8> walk{bvh, leafBoxes};
  walk.visit(bvh.rootChild);
  EXPECT_TRUE(walk.contained);
}

// The SAH counts triangles in leaves of 4 (one leaf test covers 4): on a uniformly tessellated sphere the leaves are
// close to full and the nodes hold several children each.
TEST(MeshRaycastWalks, TreeFillsLeavesAndNodes) {
  std::vector<Bounds3<float>> prims;
  std::vector<std::uint32_t> order;
  const Bvh8 bvh = icosphereTree(prims, order);
  std::size_t leaves = 0, children = 0;
  for (const Bvh8Node& n : bvh.nodes)
    for (std::uint32_t ref : n.child) {
      children += ref != Bvh8Node::kEmpty;
      leaves += Bvh8Node::isLeaf(ref);
    }
  const double trianglesPerLeaf = double(prims.size()) / double(leaves);
  const double childrenPerNode = double(children) / double(bvh.nodes.size());
  EXPECT_GT(trianglesPerLeaf, 3.5);  // 3.82 on this mesh
  EXPECT_GT(childrenPerNode, 3.5);   // 3.84 on this mesh (a binary tree: 2)
}

}  // namespace
}  // namespace gq
