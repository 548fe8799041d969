#pragma once
// Mesh and heightfield queries (the spec's PxMeshQuery).
#include <cstdint>

#include "gq/geometry.h"
#include "gq/hit.h"
#include "gq/math.h"
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
                   Triangle<T>& triangle, std::uint32_t* vertexIndices = nullptr);

// World-space triangle of a heightfield; vertex indices are sample indices (row * columns + column).
template <class T>
Status getTriangle(const HeightFieldGeometry<T>& heightField, const Transform<T>& pose,
                   std::uint32_t triangleIndex, Triangle<T>& triangle, std::uint32_t* vertexIndices = nullptr);

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
                      T inflation = T(0), bool doubleSided = false);

}  // namespace gq
