#pragma once
// Wide (4-way) bounding volume hierarchy over triangles. Node bounds are stored in float (rounded outward) for
// both scalar types so that one SSE instruction tests a ray against four children. The layout is private to the
// library: a cooked TriangleMesh holds it behind an opaque pointer (TriangleMesh::accel), so it can change without
// changing the public headers.
#include <cstdint>
#include <vector>

namespace gq {

// 64-byte aligned: a node is exactly two cache lines (112 bytes used).
struct alignas(64) Bvh4Node {
  // Structure-of-arrays child bounds: lane i belongs to child i.
  float minX[4], minY[4], minZ[4];
  float maxX[4], maxY[4], maxZ[4];
  // child[i]: an inner node index, or a leaf (kLeafBit set): first primitive and count, see bvh kernels.
  std::uint32_t child[4];
  static constexpr std::uint32_t kLeafBit = 0x80000000u;
  static constexpr std::uint32_t kEmpty = 0xffffffffu;
  // Leaf reference layout: kLeafBit | (count - 1) << kLeafCountShift | first primitive (28 bits).
  static constexpr std::uint32_t kLeafCountShift = 28;
  static constexpr std::uint32_t kMaxLeafSize = 4;
  static constexpr std::uint32_t kLeafFirstMask = (1u << kLeafCountShift) - 1u;

  static constexpr std::uint32_t makeLeaf(std::uint32_t first, std::uint32_t count) {
    return kLeafBit | ((count - 1u) << kLeafCountShift) | first;
  }
  static constexpr bool isLeaf(std::uint32_t ref) { return (ref & kLeafBit) != 0 && ref != kEmpty; }
  static constexpr std::uint32_t leafFirst(std::uint32_t ref) { return ref & kLeafFirstMask; }
  static constexpr std::uint32_t leafCount(std::uint32_t ref) { return ((ref >> kLeafCountShift) & 7u) + 1u; }
};

struct Bvh4 {
  std::vector<Bvh4Node> nodes;  // nodes[0] is the root (absent when the mesh has one leaf's worth or less)
  std::uint32_t rootChild = Bvh4Node::kEmpty;  // root reference: node index or a leaf
  std::size_t bytes() const { return nodes.size() * sizeof(Bvh4Node); }
};

namespace detail {
// What cookTriangleMesh builds for the queries (declared opaque in gq/cooking.h): the BVH over the cooked
// triangles. Leaves hold no triangle data of their own: a leaf's triangles are contiguous in the mesh's
// triangleVertices (cooked order), which the ray kernels read directly (bvh/triangle_exact4.h).
struct MeshAccel {
  Bvh4 bvh;
};
}  // namespace detail

}  // namespace gq
