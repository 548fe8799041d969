#pragma once
// Cooking: convex hulls (qhull), validated triangle meshes with a BVH, heightfields, and mesh files (assimp).
// Cooked data is immutable and shared: std::shared_ptr<const X>, safe to use from any number of threads.
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "gq/geometry.h"
#include "gq/math.h"
#include "gq/status.h"

namespace gq {

namespace detail {
struct MeshAccel;  // core/src/bvh/bvh.h
}  // namespace detail

// ---- Convex hull -------------------------------------------------------------------------------------------
template <class T> struct HullPolygon {
  Vec3<T> normal;           // outward unit normal
  T d;                      // plane: dot(normal, x) + d = 0; inside: dot(normal, x) + d <= 0
  std::uint32_t indexBase;  // first entry in ConvexMesh::polygonVertices
  std::uint32_t indexCount; // number of vertices, counter-clockwise seen from outside
};

template <class T> struct ConvexMesh {
  std::vector<Vec3<T>> vertices;
  std::vector<HullPolygon<T>> polygons;       // faceIndex of a convex hit is an index in here
  std::vector<std::uint32_t> polygonVertices; // vertex indices of every polygon, concatenated
  // Vertex adjacency along hull edges (CSR), for hill-climbing support mapping.
  std::vector<std::uint32_t> adjacencyOffsets;  // size vertices.size() + 1
  std::vector<std::uint32_t> adjacency;
  Bounds3<T> localBounds;
  Vec3<T> center;  // a strictly interior point (centroid of the vertices)
  // Balls about `center`: the hull contains the inner one and lies in the outer one (rounded inward and outward).
  // A hull not made by cookConvexMesh keeps 0 and infinity, which prove nothing.
  T innerRadius = T(0);
  T outerRadius = std::numeric_limits<T>::infinity();
};

struct ConvexCookParams {
  // Facets whose planes agree within this distance, relative to the hull size, merge into one polygon.
  double planeTolerance = 1e-9;
};

// Cooks the convex hull of `points` with qhull. Fails with DegenerateMesh for < 4 points or coplanar sets, and
// InvalidArgument for non-finite points.
template <class T>
Status cookConvexMesh(const std::vector<Vec3<T>>& points, std::shared_ptr<const ConvexMesh<T>>& out,
                      const ConvexCookParams& params = ConvexCookParams());

// ---- Triangle mesh -----------------------------------------------------------------------------------------
using TriangleIndices = std::array<std::uint32_t, 3>;
inline constexpr std::uint32_t kRemovedTriangle = 0xffffffffu;

template <class T> struct TriangleMesh {
  std::vector<Vec3<T>> vertices;           // as given
  std::vector<TriangleIndices> triangles;  // cooked order (BVH leaf order), degenerate triangles removed
  std::vector<std::uint32_t> inputIndex;   // cooked -> input triangle index (reported as faceIndex)
  std::vector<std::uint32_t> cookedIndex;  // input -> cooked index, kRemovedTriangle if removed
  // The BVH over the cooked triangles (a private layout, built by cookTriangleMesh; null in a mesh not made by
  // it, which validation rejects), and its size in bytes with leafLane's.
  std::shared_ptr<const detail::MeshAccel> accel;
  std::size_t bvhBytes = 0;
  Bounds3<T> localBounds;
  // Vertices on the convex hull of the used vertices (all used vertices when the mesh is flat): the exact
  // world AABB under any scale and pose is the AABB of these.
  std::vector<std::uint32_t> hullVertices;
  // Copies of the cooked triangles' vertices and input indices, leaf by leaf, as rows: the BVH leaf of n triangles
  // (n <= 4) whose first is cooked triangle f holds 10 n values from 10 f on, row 3 k + a being vertex k's axis a of
  // its n triangles in cooked order and row 9 their input indices (indexValue). A ray test loads a row of 4 lanes per
  // instruction with no transpose (lanes past n belong to the next row or leaf and are ignored), and its hit reads
  // the input index from the rows it tested; 3 zeros (a 4-lane load less one) follow the last leaf so such a load
  // never reads past the end.
  std::vector<T> leafVertices;
  // Per cooked triangle: its lane in its leaf (bits 0-1) and the leaf's triangle count (bits 2-4).
  std::vector<std::uint8_t> leafLane;
  std::uint32_t inputTriangleCount() const { return static_cast<std::uint32_t>(cookedIndex.size()); }
  // The rows of the leaf whose first triangle is cooked triangle `first`.
  const T* leafValues(std::uint32_t first) const { return leafVertices.data() + 10 * std::size_t(first); }
  T* leafValues(std::uint32_t first) { return leafVertices.data() + 10 * std::size_t(first); }
  // Vertex k (0-2) of the triangle whose values start at `values`, rows `stride` apart (as triangleValues gives
  // them, or a leaf's rows from leafValues plus the triangle's lane, its stride the leaf's triangle count).
  static Vec3<T> vertexIn(const T* values, std::uint32_t stride, int k) {
    const T* v = values + std::size_t(3 * std::uint32_t(k) * stride);
    return Vec3<T>(v[0], v[stride], v[2 * stride]);
  }
  // An input index as row 9 stores it: the index's bits with T's highest exponent bit flipped, so that the value is
  // never a denormal (masked lanes of a row load compute on it, and denormal operands are slow) for any index in
  // double and any below 2^30 in float; inputIndexIn reads it back from the values vertexIn reads.
  static T indexValue(std::uint32_t index) {
    Bits bits = Bits(index) ^ kIndexFlip;
    T value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
  }
  static std::uint32_t inputIndexIn(const T* values, std::uint32_t stride) {
    Bits bits;
    std::memcpy(&bits, values + 9 * std::size_t(stride), sizeof bits);
    return std::uint32_t(bits ^ kIndexFlip);
  }
  // Where cooked triangle `cooked`'s values are: vertex k's axis a at [(3 k + a) stride] from the pointer returned.
  const T* triangleValues(std::uint32_t cooked, std::uint32_t& stride) const {
    const std::uint32_t code = leafLane[cooked], lane = code & 3u;
    stride = code >> 2;
    return leafVertices.data() + (10 * std::size_t(cooked) - 9 * std::size_t(lane));  // 10 (cooked - lane) + lane
  }
  // Vertex k (0-2) of cooked triangle `cooked`, as stored (the input vertex; triangles[cooked][k] indexes it).
  Vec3<T> triangleVertex(std::uint32_t cooked, int k) const {
    std::uint32_t n;
    const T* x = triangleValues(cooked, n);
    return vertexIn(x, n, k);
  }

 private:
  using Bits = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;
  static constexpr Bits kIndexFlip = Bits(1) << (8 * sizeof(T) - 2);
};

struct MeshCookReport {
  std::uint32_t inputTriangles = 0;
  std::uint32_t removedDegenerate = 0;  // zero-area (or collinear) triangles dropped
  std::uint32_t cookedTriangles = 0;
  std::size_t bvhBytes = 0;
};

// Validates and cooks a triangle mesh: indices out of range and non-finite vertices fail (InvalidArgument);
// zero-area triangles are removed and counted; a mesh with no triangle left fails (DegenerateMesh).
template <class T>
Status cookTriangleMesh(const std::vector<Vec3<T>>& vertices, const std::vector<TriangleIndices>& triangles,
                        std::shared_ptr<const TriangleMesh<T>>& out, MeshCookReport* report = nullptr);

// ---- Heightfield -------------------------------------------------------------------------------------------
template <class T> struct HeightFieldDesc {
  std::uint32_t rows = 0;     // samples along local X
  std::uint32_t columns = 0;  // samples along local Z
  std::vector<T> heights;     // rows * columns, row-major: heights[row * columns + column]
  std::vector<std::uint32_t> holes;  // cell indices (row * (columns - 1) + column) with no triangles
};

// Cell (r, c) has corners v00=(r,c), v01=(r,c+1), v10=(r+1,c), v11=(r+1,c+1) and two triangles:
// 2*cell = (v00, v01, v10) and 2*cell+1 = (v01, v11, v10); both face +Y when the scales are positive.
template <class T> struct HeightField {
  std::uint32_t rows = 0, columns = 0;
  std::vector<T> heights;
  std::vector<std::uint8_t> hole;  // per cell
  T minHeight = T(0), maxHeight = T(0);
  // Per-block height range for raycast/overlap culling: blocks of kBlock x kBlock cells.
  static constexpr std::uint32_t kBlock = 8;
  std::uint32_t blockRows = 0, blockColumns = 0;
  std::vector<T> blockMin, blockMax;
  T height(std::uint32_t r, std::uint32_t c) const { return heights[std::size_t(r) * columns + c]; }
  bool isHole(std::uint32_t r, std::uint32_t c) const { return hole[std::size_t(r) * (columns - 1) + c] != 0; }
};

template <class T>
Status cookHeightField(const HeightFieldDesc<T>& desc, std::shared_ptr<const HeightField<T>>& out);

// ---- Mesh files --------------------------------------------------------------------------------------------
template <class T> struct MeshData {
  std::vector<Vec3<T>> vertices;
  std::vector<TriangleIndices> triangles;
};

// Mesh files are loaded into MeshData by loadMeshFile, declared in gq/io.h (library gq_io, target gq::io).

}  // namespace gq
