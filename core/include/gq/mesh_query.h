#pragma once
// Mesh and heightfield queries (the spec's PxMeshQuery).
#include <cstdint>
#include <functional>
#include <type_traits>

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
// One page of a triangle-overlap query: the first `start` overlapping triangles are skipped, then up to `capacity`
// indices are written to `indices`. `indices` may be null only when capacity is 0 (a count-only call: overflow then
// says whether any overlapping triangle exists past `start`).
struct TriangleOverlapPage {
  std::uint32_t* indices = nullptr;  // caller's buffer of `capacity` entries
  std::uint32_t capacity = 0;        // entries `indices` holds
  std::uint32_t start = 0;           // overlapping triangles to skip (the previous pages' counts)
};
// What a page received: `count` indices written; `overflow` is set when more overlapping triangles remain (ask for
// the next page with start += count).
struct TriangleOverlapPageResult {
  std::uint32_t count = 0;
  bool overflow = false;
};

// Triangles of the instance that a sphere, capsule or box (`geom`, other types: Unsupported) touches or crosses.
// Indices are input triangle indices (heightfield: 2*cell or 2*cell+1), enumerated in a fixed order for a given
// input, so pages are consistent across calls.
template <class T>
Status findOverlapTriangleMesh(const Geometry<T>& geom, const Transform<T>& pose, const TriangleMeshGeometry<T>& mesh,
                               const Transform<T>& meshPose, const TriangleOverlapPage& page,
                               TriangleOverlapPageResult& result) noexcept;
template <class T>
Status findOverlapHeightField(const Geometry<T>& geom, const Transform<T>& pose,
                              const HeightFieldGeometry<T>& heightField, const Transform<T>& heightFieldPose,
                              const TriangleOverlapPage& page, TriangleOverlapPageResult& result) noexcept;

template <class T>
[[deprecated("pass a TriangleOverlapPage and receive a TriangleOverlapPageResult")]] inline Status
findOverlapTriangleMesh(const Geometry<T>& geom, const Transform<T>& pose, const TriangleMeshGeometry<T>& mesh,
                        const Transform<T>& meshPose, std::uint32_t* results, std::uint32_t bufferSize,
                        std::uint32_t startIndex, bool& overflow, std::uint32_t& count) noexcept {
  TriangleOverlapPageResult out;
  const Status s =
      findOverlapTriangleMesh(geom, pose, mesh, meshPose, TriangleOverlapPage{results, bufferSize, startIndex}, out);
  if (s.ok()) { overflow = out.overflow; count = out.count; }
  return s;
}
template <class T>
[[deprecated("pass a TriangleOverlapPage and receive a TriangleOverlapPageResult")]] inline Status
findOverlapHeightField(const Geometry<T>& geom, const Transform<T>& pose, const HeightFieldGeometry<T>& heightField,
                       const Transform<T>& heightFieldPose, std::uint32_t* results, std::uint32_t bufferSize,
                       std::uint32_t startIndex, bool& overflow, std::uint32_t& count) noexcept {
  TriangleOverlapPageResult out;
  const Status s = findOverlapHeightField(geom, pose, heightField, heightFieldPose,
                                          TriangleOverlapPage{results, bufferSize, startIndex}, out);
  if (s.ok()) { overflow = out.overflow; count = out.count; }
  return s;
}

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
// The optional part of a triangle sweep.
template <class T> struct TriangleSweepSettings {
  // Defaults, AssumeNoInitialOverlap, PreciseSweep, MeshBothSides, AnyHit (MeshMultiple and Mtd: InvalidArgument).
  HitFlags flags = kDefaultHitFlags;
  // Optional, < triangleCount: this triangle is tested first (the previous frame's hit).
  const std::uint32_t* cachedIndex = nullptr;
  // >= 0, a length: grows the swept shape by a rounded shell.
  T inflation = T(0);
  // Disables back-face culling (as MeshBothSides does).
  bool doubleSided = false;
};

// Sweeps a sphere, capsule or box (others: Unsupported) against `triangleCount` world-space triangles (front face
// counter-clockwise). The cached triangle is tested first; AnyHit returns the first hit found, otherwise the closest
// (ties: the triangle facing the sweep most, then the smaller index) with its array index in faceIndex. `hasHit`
// says whether `hit` was written. The required arguments keep sweep()'s order (motion, swept shape, target, outputs).
template <class T>
Status sweepTriangles(const Vec3<T>& unitDir, T maxDist, const Geometry<T>& geom, const Transform<T>& pose,
                      const Triangle<T>* triangles, std::uint32_t triangleCount, SweepHit<T>& hit, bool& hasHit,
                      const TriangleSweepSettings<T>& settings = TriangleSweepSettings<T>()) noexcept;

// (Flags is deduced, so a braced `{}` after hasHit selects the settings form.)
template <class T, class Flags, std::enable_if_t<std::is_convertible_v<Flags, HitFlags>, int> = 0>
[[deprecated("pass the flags, cachedIndex, inflation and doubleSided in a TriangleSweepSettings")]] inline Status
sweepTriangles(const Vec3<T>& unitDir, T maxDist, const Geometry<T>& geom, const Transform<T>& pose,
               const Triangle<T>* triangles, std::uint32_t triangleCount, SweepHit<T>& hit, bool& hasHit,
               Flags hitFlags, const std::uint32_t* cachedIndex = nullptr, T inflation = T(0),
               bool doubleSided = false) noexcept {
  TriangleSweepSettings<T> settings;
  settings.flags = HitFlags(hitFlags);
  settings.cachedIndex = cachedIndex;
  settings.inflation = inflation;
  settings.doubleSided = doubleSided;
  return sweepTriangles(unitDir, maxDist, geom, pose, triangles, triangleCount, hit, hasHit, settings);
}

}  // namespace gq
