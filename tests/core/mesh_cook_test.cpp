// cookTriangleMesh: validation messages, degenerate-triangle removal, index maps, and BVH invariants.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

#include "bvh/bvh.h"
#include "gq/cooking.h"
#include "mesh_test_helpers.h"

namespace gq {
namespace {

using meshtest::Scalars;

template <class T> class MeshCook : public ::testing::Test {};
TYPED_TEST_SUITE(MeshCook, Scalars);

TYPED_TEST(MeshCook, OutOfRangeIndexIsInvalidArgumentNamingTheTriangle) {
  using T = TypeParam;
  const MeshData<T> m = meshtest::quadStack<T>(1);
  std::vector<TriangleIndices> tris = m.triangles;
  tris[1][2] = 4;
  std::shared_ptr<const TriangleMesh<T>> out;
  const Status s = cookTriangleMesh(m.vertices, tris, out);
  EXPECT_EQ(s.code, StatusCode::InvalidArgument);
  EXPECT_NE(s.toString().find("triangle 1"), std::string::npos) << s.toString();
  EXPECT_EQ(out, nullptr);
}

TYPED_TEST(MeshCook, NonFiniteVertexIsInvalidArgumentNamingTheVertex) {
  using T = TypeParam;
  MeshData<T> m = meshtest::quadStack<T>(1);
  m.vertices[2].y() = std::numeric_limits<T>::quiet_NaN();
  std::shared_ptr<const TriangleMesh<T>> out;
  const Status s = cookTriangleMesh(m.vertices, m.triangles, out);
  EXPECT_EQ(s.code, StatusCode::InvalidArgument);
  EXPECT_NE(s.toString().find("vertex 2"), std::string::npos) << s.toString();
  EXPECT_EQ(out, nullptr);
}

TYPED_TEST(MeshCook, DegenerateTrianglesAreRemovedAndCounted) {
  using T = TypeParam;
  MeshData<T> m = meshtest::quadStack<T>(2);
  m.vertices.push_back({T(0.5), T(-1), T(0)});  // on the edge 0-1: collinear with it
  std::vector<TriangleIndices> tris = {{0, 0, 1}, m.triangles[0], {0, 8, 1}, m.triangles[1], m.triangles[2],
                                       m.triangles[3]};
  std::shared_ptr<const TriangleMesh<T>> out;
  MeshCookReport report;
  ASSERT_TRUE(cookTriangleMesh(m.vertices, tris, out, &report).ok());
  EXPECT_EQ(report.inputTriangles, 6u);
  EXPECT_EQ(report.removedDegenerate, 2u);
  EXPECT_EQ(report.cookedTriangles, 4u);
  EXPECT_EQ(out->triangles.size(), 4u);
  EXPECT_EQ(out->cookedIndex[0], kRemovedTriangle);
  EXPECT_EQ(out->cookedIndex[2], kRemovedTriangle);
  // The maps are inverse of each other and cooked triangles are the input ones.
  for (std::uint32_t c = 0; c < out->triangles.size(); ++c) {
    EXPECT_EQ(out->cookedIndex[out->inputIndex[c]], c);
    EXPECT_EQ(out->triangles[c], tris[out->inputIndex[c]]);
  }
}

TYPED_TEST(MeshCook, AllDegenerateOrEmptyMeshIsDegenerateMesh) {
  using T = TypeParam;
  const std::vector<Vec3<T>> v = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  std::shared_ptr<const TriangleMesh<T>> out;
  EXPECT_EQ(cookTriangleMesh(v, {{0, 1, 2}, {1, 1, 2}}, out).code, StatusCode::DegenerateMesh);
  EXPECT_EQ(cookTriangleMesh(v, {}, out).code, StatusCode::DegenerateMesh);
  EXPECT_EQ(out, nullptr);
}

// Every cooked triangle sits in exactly one leaf of <= 4 triangles, inside the float box of every ancestor slot
// (compared in T: the float boxes are rounded outward, so double vertices are inside too).
template <class T> void checkBvh(const TriangleMesh<T>& mesh) {
  std::vector<int> seen(mesh.triangles.size(), 0);
  std::function<void(std::uint32_t, const Bounds3<T>&)> walk = [&](std::uint32_t ref, const Bounds3<T>& box) {
    if (MeshBvhNode::isLeaf(ref)) {
      const std::uint32_t first = MeshBvhNode::leafFirst(ref), count = MeshBvhNode::leafCount(ref);
      ASSERT_LE(count, 4u);
      for (std::uint32_t c = first; c < first + count; ++c) {
        ASSERT_LT(c, mesh.triangles.size());
        ++seen[c];
        for (std::uint32_t v : mesh.triangles[c]) ASSERT_TRUE(box.contains(mesh.vertices[v]));
      }
      return;
    }
    ASSERT_LT(ref, mesh.accel->bvh.nodes.size());
    const MeshBvhNode& n = mesh.accel->bvh.nodes[ref];
    for (int i = 0; i < MeshBvhNode::kWidth; ++i) {
      if (n.child[i] == MeshBvhNode::kEmpty) continue;
      Bounds3<T> b = Bounds3<T>::fromMinMax(Vec3<T>(T(n.minX[i]), T(n.minY[i]), T(n.minZ[i])),
                                            Vec3<T>(T(n.maxX[i]), T(n.maxY[i]), T(n.maxZ[i])));
      ASSERT_TRUE(box.contains(b.min) && box.contains(b.max));
      walk(n.child[i], b);
    }
  };
  const T inf = std::numeric_limits<T>::infinity();
  walk(mesh.accel->bvh.rootChild, Bounds3<T>::fromMinMax(Vec3<T>::Constant(-inf), Vec3<T>::Constant(inf)));
  for (int s : seen) ASSERT_EQ(s, 1);
}

TYPED_TEST(MeshCook, BvhLeavesHoldEveryTriangleOnceInsideTheirBoxes) {
  using T = TypeParam;
  // Coordinates like 0.1 are not floats: the double mesh checks the outward rounding.
  MeshData<T> m = meshtest::icosphere<T>(3);
  for (auto& v : m.vertices) v = v * T(0.1) + Vec3<T>(T(0.3), T(-0.7), T(1.1));
  const auto mesh = meshtest::cook(m.vertices, m.triangles);
  checkBvh(*mesh);
  const auto small = meshtest::cook(meshtest::quadStack<T>(1).vertices, meshtest::quadStack<T>(1).triangles);
  EXPECT_TRUE(MeshBvhNode::isLeaf(small->accel->bvh.rootChild));  // 2 triangles: one leaf, no nodes
  checkBvh(*small);
}

// TriangleMesh::leafVertices: each leaf of n triangles holds rows of n values from 10 x its first cooked index on (row
// 3 k + a: vertex k's axis a; row 9: input indices, which inputIndexIn reads back, here normal numbers), leafLane
// names each triangle's lane and leaf size, triangleVertex reads the input vertex back, as vertexIn does from
// leafValues (the leaf's rows) and from triangleValues, and 3 zeros follow the last leaf.
template <class T> void checkLeafVertices(const TriangleMesh<T>& mesh) {
  const std::size_t n = mesh.triangles.size();
  ASSERT_EQ(mesh.leafVertices.size(), 10 * n + 3);
  ASSERT_EQ(mesh.leafLane.size(), n);
  for (std::size_t i = 10 * n; i < mesh.leafVertices.size(); ++i) EXPECT_EQ(mesh.leafVertices[i], T(0));
  std::vector<int> seen(n, 0);
  auto check = [&](std::uint32_t ref) {
    if (!MeshBvhNode::isLeaf(ref)) return;
    const std::uint32_t first = MeshBvhNode::leafFirst(ref), count = MeshBvhNode::leafCount(ref);
    for (std::uint32_t lane = 0; lane < count; ++lane) {
      const std::uint32_t c = first + lane;
      ++seen[c];
      EXPECT_EQ(mesh.leafLane[c], lane | count << 2);
      std::uint32_t stride = 0;
      const T* values = mesh.triangleValues(c, stride);
      EXPECT_EQ(stride, count);
      EXPECT_EQ(values, mesh.leafValues(first) + lane);
      for (int k = 0; k < 3; ++k) {
        const Vec3<T>& v = mesh.vertices[mesh.triangles[c][k]];
        EXPECT_EQ(mesh.triangleVertex(c, k), v);
        EXPECT_EQ(TriangleMesh<T>::vertexIn(mesh.leafValues(first) + lane, count, k), v);
        for (int a = 0; a < 3; ++a) EXPECT_EQ(mesh.leafVertices[10 * first + (3 * k + a) * count + lane], v[a]);
      }
      const T index = mesh.leafVertices[10 * first + 9 * count + lane];
      EXPECT_TRUE(std::isnormal(index)) << index;
      EXPECT_EQ(TriangleMesh<T>::inputIndexIn(values, stride), mesh.inputIndex[c]);
      EXPECT_EQ(TriangleMesh<T>::inputIndexIn(mesh.leafValues(first) + lane, count), mesh.inputIndex[c]);
    }
  };
  check(mesh.accel->bvh.rootChild);
  for (const MeshBvhNode& node : mesh.accel->bvh.nodes)
    for (std::uint32_t ref : node.child) check(ref);
  for (int s : seen) EXPECT_EQ(s, 1);
}

TYPED_TEST(MeshCook, LeafVerticesAreEachLeafsTrianglesAsRowsInCookedOrder) {
  using T = TypeParam;
  const MeshData<T> sphere = meshtest::icosphere<T>(3);
  const auto mesh = meshtest::cook(sphere.vertices, sphere.triangles);
  ASSERT_NE(mesh, nullptr);
  checkLeafVertices(*mesh);
  // Leaves of every size occur: one leaf of 1, 2 and 3 triangles (a root leaf), and a mesh whose leaves vary.
  for (std::uint32_t count : {1u, 2u, 3u}) {
    MeshData<T> m = meshtest::quadStack<T>(2);
    m.triangles.resize(count);
    const auto small = meshtest::cook(m.vertices, m.triangles);
    ASSERT_NE(small, nullptr);
    ASSERT_EQ(MeshBvhNode::leafCount(small->accel->bvh.rootChild), count);
    checkLeafVertices(*small);
  }
  std::vector<int> sizes(5, 0);
  for (const MeshBvhNode& node : mesh->accel->bvh.nodes)
    for (std::uint32_t ref : node.child)
      if (MeshBvhNode::isLeaf(ref)) ++sizes[MeshBvhNode::leafCount(ref)];
  EXPECT_GT(sizes[4], 0);
  EXPECT_GT(sizes[1] + sizes[2] + sizes[3], 0) << "the sphere's leaves are all full: the strides below 4 go untested";
}

// Row 9's encoding reads back every index, and is never a denormal for any index in double and any below 2^30 in
// float (a normal number in double).
TYPED_TEST(MeshCook, LeafIndexValuesReadBackAndAreNeverDenormal) {
  using T = TypeParam;
  using Mesh = TriangleMesh<T>;
  for (std::uint32_t index : {0u, 1u, 2u, 12345u, (1u << 23) - 1, 1u << 23, (1u << 24) + 1, (1u << 30) - 1, 1u << 30,
                              0x7fffffffu, 0x80000000u, 0xfffffffeu, 0xffffffffu}) {
    const T stored[10] = {T(1), T(2), T(3), T(4), T(5), T(6), T(7), T(8), T(9), Mesh::indexValue(index)};
    EXPECT_EQ(Mesh::inputIndexIn(stored, 1), index);
    if (sizeof(T) == 8 || index < (1u << 30)) EXPECT_NE(std::fpclassify(stored[9]), FP_SUBNORMAL) << index;
    if (sizeof(T) == 8) EXPECT_TRUE(std::isnormal(stored[9])) << index;
  }
}

// The bunny from the shared data folder (skipped when it is missing).
template <class T> class MeshCookData : public ::testing::Test {};
TYPED_TEST_SUITE(MeshCookData, Scalars);

TYPED_TEST(MeshCookData, BunnyBvhUsesAtMost32BytesPerTriangle) {
  using T = TypeParam;
  GQ_REQUIRE_BUNNY();
  const MeshData<T> b = meshtest::bunny<T>();
  ASSERT_EQ(b.triangles.size(), 69451u);
  std::shared_ptr<const TriangleMesh<T>> mesh;
  MeshCookReport report;
  ASSERT_TRUE(cookTriangleMesh(b.vertices, b.triangles, mesh, &report).ok());
  const double perTriangle = double(report.bvhBytes) / double(report.cookedTriangles);
  std::printf("bunny: %u triangles cooked, %u removed, BVH %zu bytes = %.2f bytes/triangle, %zu hull vertices\n",
              report.cookedTriangles, report.removedDegenerate, report.bvhBytes, perTriangle,
              mesh->hullVertices.size());
  EXPECT_LE(perTriangle, 32.0);
  EXPECT_EQ(mesh->bvhBytes, report.bvhBytes);  // public on the mesh as well
  checkBvh(*mesh);
}

}  // namespace
}  // namespace gq
