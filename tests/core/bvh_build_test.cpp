// The BVH builder splits at the centroid median where the SAH cannot split (coincident centroids) and past its
// depth limit, so every tree stays within the depth the ray walk's fixed stack is sized for (bvh/traverse.h,
// kBvhStackSize) and holds every triangle in exactly one leaf. Rays through skewed and coincident meshes find every
// triangle they cross.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "bvh/build.h"
#include "bvh/traverse.h"
#include "gq/query.h"
#include "gq/shape.h"
#include "mesh_test_helpers.h"

namespace gq {
namespace {

using meshtest::Scalars;

// Shape of a tree: inner-node levels on the deepest path, and the most stack entries a walk that pushes every other
// child of each node on its path can hold (7 per 8-wide node, plus the 8 entries sortHits and pushLanes write past
// the top).
struct TreeShape {
  int depth = 0;
  int stackEntries = 0;
  std::vector<int> leafCount;  // per cooked position: how many leaves hold it
  std::uint32_t largestLeaf = 0;
};

void measure(const Bvh8& bvh, std::uint32_t ref, int depth, int entries, TreeShape& shape) {
  if (Bvh8Node::isLeaf(ref)) {
    shape.largestLeaf = std::max(shape.largestLeaf, Bvh8Node::leafCount(ref));
    for (std::uint32_t k = 0; k < Bvh8Node::leafCount(ref); ++k) ++shape.leafCount[Bvh8Node::leafFirst(ref) + k];
    return;
  }
  const Bvh8Node& n = bvh.nodes[ref];
  int children = 0;
  for (std::uint32_t c : n.child) children += c != Bvh8Node::kEmpty;
  shape.depth = std::max(shape.depth, depth + 1);
  const int here = entries + children - 1;
  shape.stackEntries = std::max(shape.stackEntries, here + 8);
  for (std::uint32_t c : n.child)
    if (c != Bvh8Node::kEmpty) measure(bvh, c, depth + 1, here, shape);
}

TreeShape shapeOf(const std::vector<Bounds3<float>>& prims, const detail::BvhBuildSettings& settings = {}) {
  std::vector<std::uint32_t> order;
  const Bvh8 bvh = detail::buildBvh8(prims, order, settings);
  TreeShape shape;
  shape.leafCount.assign(prims.size(), 0);
  measure(bvh, bvh.rootChild, 0, 1, shape);
  return shape;
}

bool eachInOneLeaf(const TreeShape& shape) {
  return std::all_of(shape.leafCount.begin(), shape.leafCount.end(), [](int c) { return c == 1; });
}

// Boxes along x at 1.02^i, each a thousandth of its coordinate wide: the SAH's splits of such a range take off its
// far end, so its tree is deeper than a balanced one.
std::vector<Bounds3<float>> geometricBoxes(int n) {
  std::vector<Bounds3<float>> prims;
  for (int i = 0; i < n; ++i) {
    const float x = std::pow(1.02f, float(i));
    prims.push_back(Bounds3<float>::fromMinMax(Vec3<float>(x, -1.0f, -1.0f), Vec3<float>(x * 1.001f, 1.0f, 1.0f)));
  }
  return prims;
}

// Median splits: a node's first split halves its range, so each level at least halves the largest range below it and
// n primitives in leaves of at most s are at most ceil(log2(n / s)) + 1 levels deep (the bound the walk's stack
// assumes).
int medianDepthBound(std::size_t n, std::uint32_t leafSize = 4) {
  return int(std::ceil(std::log2(double(n) / double(leafSize)))) + 1;
}

// Settings with leaves of at most leafSize primitives (4: triangles; 1: scene instances).
detail::BvhBuildSettings leavesOf(std::uint32_t leafSize) {
  detail::BvhBuildSettings settings;
  settings.maxLeafSize = leafSize;
  return settings;
}

TEST(BvhBuild, LeavesHoldAtMostTheLeafSizeClampedToOneToFour) {
  std::vector<Bounds3<float>> prims;
  for (int i = 0; i < 1000; ++i) {  // a 10 x 10 x 10 grid of unit boxes
    const Vec3<float> lo(float(i % 10), float(i / 10 % 10), float(i / 100));
    prims.push_back(Bounds3<float>::fromMinMax(lo, lo + Vec3<float>::Constant(0.9f)));
  }
  using Sizes = std::pair<std::uint32_t, std::uint32_t>;  // asked, expected
  for (const auto& [asked, expected] : {Sizes{1, 1}, Sizes{2, 2}, Sizes{4, 4}, Sizes{0, 1}, Sizes{9, 4}}) {
    SCOPED_TRACE(asked);
    detail::BvhBuildSettings settings;
    settings.maxLeafSize = asked;
    const TreeShape shape = shapeOf(prims, settings);
    EXPECT_EQ(shape.largestLeaf, expected);
    EXPECT_TRUE(eachInOneLeaf(shape));
  }
}

TEST(BvhBuild, RangesPastTheSahDepthLimitAreSplitAtTheMedian) {
  const std::vector<Bounds3<float>> prims = geometricBoxes(3000);
  const TreeShape sah = shapeOf(prims);
  detail::BvhBuildSettings medianOnly;
  medianOnly.maxSahDepth = 0;
  const TreeShape median = shapeOf(prims, medianOnly);
  EXPECT_GT(sah.depth, medianDepthBound(prims.size())) << "the SAH tree of this input is deeper than median splits";
  EXPECT_LE(median.depth, medianDepthBound(prims.size()));
  EXPECT_TRUE(eachInOneLeaf(median));
  detail::BvhBuildSettings sahTwoLevels;
  sahTwoLevels.maxSahDepth = 2;
  const TreeShape mixed = shapeOf(prims, sahTwoLevels);
  EXPECT_LE(mixed.depth, 2 + medianDepthBound(prims.size()));
  EXPECT_TRUE(eachInOneLeaf(mixed));
}

// The SAH tree of a skewed input (deeper than a balanced one) within the stack the walk has: a guard for changes to
// the builder or to the stack's size.
TEST(BvhBuild, SkewedInputsStayWithinTheWalkStack) {
  for (const std::uint32_t leafSize : {4u, 1u}) {
    SCOPED_TRACE(leafSize);
    const TreeShape shape = shapeOf(geometricBoxes(3000), leavesOf(leafSize));
    EXPECT_LE(shape.depth, detail::BvhBuildSettings().maxSahDepth + 28);
    EXPECT_LE(shape.stackEntries, detail::kBvhStackSize);
    EXPECT_TRUE(eachInOneLeaf(shape));
  }
}

TEST(BvhBuild, CoincidentCentroidsAreSplitAtTheMedian) {
  const std::vector<Bounds3<float>> prims(
      3000, Bounds3<float>::fromMinMax(Vec3<float>(-1.0f, -2.0f, -3.0f), Vec3<float>(1.0f, 2.0f, 3.0f)));
  for (const std::uint32_t leafSize : {4u, 1u}) {
    SCOPED_TRACE(leafSize);
    const TreeShape shape = shapeOf(prims, leavesOf(leafSize));
    EXPECT_LE(shape.depth, medianDepthBound(prims.size(), leafSize));
    EXPECT_TRUE(eachInOneLeaf(shape));
  }
}

template <class T> class BvhBuildRays : public ::testing::Test {};
TYPED_TEST_SUITE(BvhBuildRays, Scalars);

// A triangle across the x axis in the plane x = c.
template <class T> void addCrossing(MeshData<T>& m, T c) {
  const auto b = std::uint32_t(m.vertices.size());
  m.vertices.push_back({c, T(-1), T(-1)});
  m.vertices.push_back({c, T(-1), T(2)});
  m.vertices.push_back({c, T(2), T(-1)});
  m.triangles.push_back({b, b + 1, b + 2});
}

// The hits of the ray from the origin along +x, sorted by distance (MeshMultiple with room for every triangle).
template <class T> std::vector<RaycastHit<T>> allHits(const Shape<T>& shape, std::size_t n) {
  std::vector<RaycastHit<T>> hits(n + 1);
  std::uint32_t count = 0;
  const Status s = raycast(Vec3<T>(Vec3<T>::Zero()), Vec3<T>(Vec3<T>::UnitX()), shape, Transform<T>(),
                           std::numeric_limits<T>::max(),
                           kDefaultHitFlags | HitFlag::MeshBothSides | HitFlag::MeshMultiple, std::uint32_t(n + 1),
                           hits.data(), count);
  EXPECT_TRUE(s.ok()) << s.toString();
  hits.resize(count);
  return hits;
}

// A mesh shape of crossings at the planes x = c for each c of `planes` (input order).
template <class T> bool crossingsShape(const std::vector<T>& planes, MeshData<T>& m, Shape<T>& shape) {
  for (const T c : planes) addCrossing(m, c);
  const auto mesh = meshtest::cook(m.vertices, m.triangles);
  return mesh != nullptr && Shape<T>::make(TriangleMeshGeometry<T>(mesh), shape).ok();
}

TYPED_TEST(BvhBuildRays, ARayThroughADeepTreeCrossesEveryTriangleInOrder) {
  using T = TypeParam;
  const int n = 3000;
  std::vector<T> planes;
  for (int i = 0; i < n; ++i) planes.push_back(T(std::pow(1.02, double(i))));
  MeshData<T> m;
  Shape<T> shape;
  ASSERT_TRUE(crossingsShape(planes, m, shape));
  const std::vector<RaycastHit<T>> hits = allHits(shape, std::size_t(n));
  ASSERT_EQ(hits.size(), std::size_t(n));
  for (int i = 0; i < n; ++i) {
    EXPECT_EQ(hits[std::size_t(i)].faceIndex, std::uint32_t(i));
    // The plane x = c: the watertight test's distance within a few units of c.
    const T c = m.vertices[3 * std::size_t(i)].x();
    EXPECT_NEAR(hits[std::size_t(i)].distance, c, 8 * std::numeric_limits<T>::epsilon() * c);
  }
}

TYPED_TEST(BvhBuildRays, CoincidentTrianglesAreAllHitAndTheClosestIsTheFirstInInputOrder) {
  using T = TypeParam;
  const int n = 1000;
  MeshData<T> m;
  Shape<T> shape;
  ASSERT_TRUE(crossingsShape(std::vector<T>(std::size_t(n), T(2)), m, shape));
  const std::vector<RaycastHit<T>> hits = allHits(shape, std::size_t(n));
  ASSERT_EQ(hits.size(), std::size_t(n));
  std::vector<int> seen(std::size_t(n), 0);
  for (const auto& h : hits) {
    ASSERT_LT(h.faceIndex, std::uint32_t(n));
    ++seen[h.faceIndex];
    EXPECT_NEAR(h.distance, T(2), 8 * std::numeric_limits<T>::epsilon());
  }
  EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int c) { return c == 1; }));
  RaycastHit<T> closest;
  std::uint32_t count = 0;
  ASSERT_TRUE(raycast(Vec3<T>(Vec3<T>::Zero()), Vec3<T>(Vec3<T>::UnitX()), shape, Transform<T>(), T(10),
                      kDefaultHitFlags | HitFlag::MeshBothSides, 1u, &closest, count)
                  .ok());
  ASSERT_EQ(count, 1u);
  EXPECT_EQ(closest.faceIndex, 0u);
}

}  // namespace
}  // namespace gq
