#pragma once
// Mesh and heightfield queries (the spec's PxMeshQuery).
#include <cstdint>
#include <functional>

#include "gq/geometry.h"
#include "gq/hit.h"
#include "gq/math.h"
#include "gq/query.h"
#include "gq/status.h"
#include "gq/transform.h"

namespace gq {

template <class T> struct Triangle {
  Vec3<T> verts[3];
  Vec3<T> pointFromUV(T u, T v) const { return (T(1) - u - v) * verts[0] + u * verts[1] + v * verts[2]; }
  Vec3<T> normal() const { return (verts[1] - verts[0]).cross(verts[2] - verts[0]).normalized(); }
};

// World-space triangle `triangleIndex` (an input triangle index, as reported in faceIndex) of a mesh instance.
// A mirrored scale swaps vertices 1 and 2 (and the reported vertex indices), so the winding stays outward.
template <class T>
Status getTriangle(const TriangleMeshGeometry<T>& mesh, const Transform<T>& pose, std::uint32_t triangleIndex,
                   Triangle<T>& triangle, std::uint32_t* vertexIndices = nullptr) noexcept;

// World-space triangle of a heightfield; vertex indices are sample indices (row * columns + column).
template <class T>
Status getTriangle(const HeightFieldGeometry<T>& heightField, const Transform<T>& pose,
                   std::uint32_t triangleIndex, Triangle<T>& triangle, std::uint32_t* vertexIndices = nullptr) noexcept;


// ---- Mesh and heightfield overlaps (PxMeshQuery::findOverlapTriangleMesh / findOverlapHeightField) ------------
// Triangles of the instance that a sphere, capsule or box (`geom`, other types: Unsupported) touches or crosses.
// Indices are input triangle indices (heightfield: 2*cell or 2*cell+1), enumerated in a fixed order for a given
// input. Paging: the first `startIndex` overlapping triangles are skipped, then up to `bufferSize` are written to
// `results` and `count` receives how many; `overflow` is set when more overlapping triangles remain (call again with
// startIndex += count). `results` may be null only when bufferSize is 0.
template <class T>
Status findOverlapTriangleMesh(const Geometry<T>& geom, const Transform<T>& pose, const TriangleMeshGeometry<T>& mesh,
                               const Transform<T>& meshPose, std::uint32_t* results, std::uint32_t bufferSize,
                               std::uint32_t startIndex, bool& overflow, std::uint32_t& count) noexcept;
template <class T>
Status findOverlapHeightField(const Geometry<T>& geom, const Transform<T>& pose,
                              const HeightFieldGeometry<T>& heightField, const Transform<T>& heightFieldPose,
                              std::uint32_t* results, std::uint32_t bufferSize, std::uint32_t startIndex,
                              bool& overflow, std::uint32_t& count) noexcept;

// ---- Mesh vs mesh triangle pairs (PxMeshQuery::findOverlapTriangleMesh with a report callback) ----------------
// Receives (triangle of mesh0, triangle of mesh1), input indices; return false to stop the query.
using TrianglePairCallback = std::function<bool(std::uint32_t triangle0, std::uint32_t triangle1)>;

// Reports every pair of intersecting (touching counts) triangles, found by a dual BVH traversal and an exact
// triangle-triangle test. tolerance > 0 makes it a proximity query: pairs whose distance is <= tolerance.
// `overlapFound` says whether any pair was reported. The order of the pairs is unspecified.
template <class T>
Status findOverlapTriangleMeshPairs(const TrianglePairCallback& callback, const TriangleMeshGeometry<T>& mesh0,
                                    const Transform<T>& pose0, const TriangleMeshGeometry<T>& mesh1,
                                    const Transform<T>& pose1, bool& overlapFound, T tolerance = T(0)) noexcept;

// ---- Iterative mesh / heightfield penetration (PxComputeTriangleMeshPenetration, PxComputeHeightFieldPenetration)
// `geom` is a sphere, capsule, box, convex mesh or convex custom shape. Each iteration takes the triangles the shape
// (moved by the translation so far) touches, ignores those whose plane has the shape's centre behind it (unless the
// surface is double-sided), and moves the shape by the deepest per-triangle MTD. It stops when nothing is left to
// push out of, or after maxIter (>= 1) iterations. result.penetrating is false when no triangle counted at the
// start (result then holds no direction); otherwise direction * depth is the total translation (approximate MTD,
// exact when one triangle decides). `iterations` (optional) receives the number of iterations that moved the shape.
template <class T>
Status computeTriangleMeshPenetration(PenetrationResult<T>& result, const Geometry<T>& geom, const Transform<T>& pose,
                                      const TriangleMeshGeometry<T>& mesh, const Transform<T>& meshPose,
                                      std::uint32_t maxIter = 4, std::uint32_t* iterations = nullptr) noexcept;
template <class T>
Status computeHeightFieldPenetration(PenetrationResult<T>& result, const Geometry<T>& geom, const Transform<T>& pose,
                                     const HeightFieldGeometry<T>& heightField, const Transform<T>& heightFieldPose,
                                     std::uint32_t maxIter = 4, std::uint32_t* iterations = nullptr) noexcept;

// ---- Sweep against an array of triangles (PxGeometryQuery::sweep with a PxTriangle buffer) ---------------------
// Sweeps a sphere, capsule or box (others: Unsupported) against `triangleCount` world-space triangles (front face
// counter-clockwise). Flags: defaults, assumeNoInitialOverlap, preciseSweep, meshBothSides, anyHit (meshMultiple and
// mtd: InvalidArgument). `cachedIndex` (optional, < triangleCount) is tested first; anyHit returns the first hit
// found, otherwise the closest (ties: the triangle facing the sweep most, then the smaller index) with its array
// index in faceIndex. doubleSided (or meshBothSides) disables back-face culling. `hasHit` says whether `hit` was written.
template <class T>
Status sweepTriangles(const Vec3<T>& unitDir, T maxDist, const Geometry<T>& geom, const Transform<T>& pose,
                      const Triangle<T>* triangles, std::uint32_t triangleCount, SweepHit<T>& hit, bool& hasHit,
                      HitFlags hitFlags = kDefaultHitFlags, const std::uint32_t* cachedIndex = nullptr,
                      T inflation = T(0), bool doubleSided = false) noexcept;

}  // namespace gq
