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
  // leafPacket[i]: index of child i's TrianglePacket4 when child i is a leaf (fills the node's spare 16 bytes).
  std::uint32_t leafPacket[4];
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

// The (up to 4) triangles of one leaf in float structure-of-arrays form for a SIMD ray pre-test: lane i holds
// vertex v0 and the edges e1 = v1 - v0, e2 = v2 - v0 of triangle first + i (rounded to float). Unused lanes are 0.
struct alignas(16) TrianglePacket4 {
  float v0x[4], v0y[4], v0z[4];
  float e1x[4], e1y[4], e1z[4];
  float e2x[4], e2y[4], e2z[4];
};

// The (up to 4) triangles of one leaf of a float mesh, exact vertex copies in structure-of-arrays form: lane i holds
// v0, v1, v2 of triangle first + i. The float watertight test runs on them 4 lanes at a time (bvh/triangle_exact4.h).
// Unused lanes are 0.
struct alignas(16) TriangleVertices4 {
  float v[3][3][4];  // v[vertex][axis][lane]
};

struct Bvh4 {
  std::vector<Bvh4Node> nodes;  // nodes[0] is the root (absent when the mesh has one leaf's worth or less)
  std::uint32_t rootChild = Bvh4Node::kEmpty;  // root reference: node index or a leaf
  std::uint32_t rootPacket = 0;                // packet of the root when it is a leaf
  std::uint32_t leafCount = 0;                 // leaves, numbered 0..leafCount-1 (their packet indices)
  std::size_t bytes() const { return nodes.size() * sizeof(Bvh4Node); }
};

namespace detail {
// What cookTriangleMesh builds for the queries (declared opaque in gq/cooking.h): the BVH over the cooked
// triangles and the float SoA copies of each leaf's triangles for the SIMD ray tests (index: Bvh4Node::leafPacket,
// Bvh4::rootPacket). A double mesh has trianglePackets (the conservative float pre-test, bvh/triangle_packet.h); a
// float mesh has vertexPackets instead (its exact vertices, tested 4-wide by the exact test itself).
struct MeshAccel {
  Bvh4 bvh;
  std::vector<TrianglePacket4> trianglePackets;
  std::vector<TriangleVertices4> vertexPackets;
};
}  // namespace detail

}  // namespace gq
