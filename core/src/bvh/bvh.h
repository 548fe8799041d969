#pragma once
// Wide bounding volume hierarchies over triangles. Node bounds are stored in float (rounded outward) for both scalar
// types so that one SIMD instruction tests a ray against 4 (SSE) or 8 (AVX2) children. The layout is private to the
// library: a cooked TriangleMesh holds it behind an opaque pointer (TriangleMesh::accel), so it can change without
// changing the public headers.
#include <cstdint>
#include <limits>
#include <vector>

#include "gq/math.h"

namespace gq {

// W children per node. The trees built are 8-wide: 224 bytes of bounds and references padded to 256, 64-byte aligned
// (one AVX load per bound plane; a node is exactly 4 cache lines and its address a shift of its index).
template <int W> struct alignas(64) BvhNode {
  static constexpr int kWidth = W;
  // child[i]: an inner node index, or a leaf (kLeafBit set): first primitive and count, see bvh kernels. First, in the
  // cache line of minX, which every node test reads: the reference of the child a ray takes is then fetched with the
  // bounds, not after the test.
  std::uint32_t child[W];
  // Structure-of-arrays child bounds: lane i belongs to child i.
  float minX[W], minY[W], minZ[W];
  float maxX[W], maxY[W], maxZ[W];
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
using Bvh8Node = BvhNode<8>;

// The box of an empty lane: inverted (min +inf, max -inf). A slab test from finite float origins rejects it whatever
// its bound (on every axis its entry distance is +inf or its exit -inf), so the node tests need no mask for empty
// lanes, and it is the identity of box unions. A ray whose float slab distances are NaN on every axis (an origin or
// direction overflowing float, or a double origin just beyond float's range, whose float above it is +inf) may enter
// it: the walk skips kEmpty references.
inline Bounds3<float> emptyBvhLaneBox() {
  const float inf = std::numeric_limits<float>::infinity();
  return Bounds3<float>::fromMinMax(Vec3<float>::Constant(inf), Vec3<float>::Constant(-inf));
}

// Writes the box of a node's lane (its six planes).
template <int W> inline void setBvhLaneBox(BvhNode<W>& node, int lane, const Bounds3<float>& b) {
  node.minX[lane] = b.min.x();
  node.minY[lane] = b.min.y();
  node.minZ[lane] = b.min.z();
  node.maxX[lane] = b.max.x();
  node.maxY[lane] = b.max.y();
  node.maxZ[lane] = b.max.z();
}

template <int W> struct Bvh {
  std::vector<BvhNode<W>> nodes;  // nodes[0] is the root (absent when the mesh has one leaf's worth or less)
  std::uint32_t rootChild = BvhNode<W>::kEmpty;  // root reference: node index or a leaf
  std::size_t bytes() const { return nodes.size() * sizeof(BvhNode<W>); }
};
using Bvh8 = Bvh<8>;
// The tree cooked meshes hold (MeshAccel).
using MeshBvhNode = Bvh8Node;
using MeshBvh = Bvh8;

namespace detail {
// What cookTriangleMesh builds for the queries (declared opaque in gq/cooking.h): the BVH over the cooked
// triangles. Leaves hold no triangle data of their own: a leaf's triangles are contiguous in the mesh's
// leafVertices (cooked order, rows per leaf), which the ray kernels read directly (bvh/triangle_exact4.h).
// 8-wide: each node's children are tested by one AVX2 instruction per plane (or two SSE halves).
struct MeshAccel {
  Bvh8 bvh;
};
}  // namespace detail

}  // namespace gq
