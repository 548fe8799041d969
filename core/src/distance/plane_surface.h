#pragma once
// The plane (the solid half-space x <= 0 of its frame) against the thin surfaces: a triangle mesh or a heightfield.
// Both queries reduce to the lowest vertex of the surface over the plane: a triangle reaches the half-space exactly
// when one of its vertices does (a triangle is the hull of its vertices, and height over the plane is linear).
//  - overlap: some vertex of a triangle has height <= 0 (touching counts);
//  - distance: the minimum signed height of the surface's vertices (the same sign as plane-convex distance:
//    > 0 the gap, < 0 minus the depth of the deepest vertex below the plane); normal = the plane's +X (from the
//    plane towards the surface), point1 = that vertex, point0 = its projection on the plane.
// Heights are taken in the surface's own space as one linear function of its vertices (h = m . v + k): one dot
// product a vertex, and a lower bound over a box of vertices that never exceeds a vertex inside it (every rounding
// step is monotone), so culling never drops the lowest vertex.
#include <cstdint>
#include <limits>

#include "gq/geometry.h"
#include "gq/query.h"
#include "gq/status.h"
#include "gq/transform.h"

namespace gq::detail {

template <class T> struct LowestVertex {
  T height = std::numeric_limits<T>::infinity();  // +inf: no vertex (a heightfield whose cells are all holes)
  Vec3<T> point = Vec3<T>::Zero();                 // the vertex, in the frame of the poses given
};

// The lowest vertex of the surface's triangles over the plane at `planePose`; stops at the first vertex with height
// <= stopAtOrBelow (overlap passes 0, distance -inf).
template <class T>
LowestVertex<T> lowestVertexTriangleMesh(const TriangleMeshGeometry<T>& mesh, const Transform<T>& meshPose,
                                         const Transform<T>& planePose, T stopAtOrBelow);
template <class T>
LowestVertex<T> lowestVertexHeightField(const HeightFieldGeometry<T>& hf, const Transform<T>& hfPose,
                                        const Transform<T>& planePose, T stopAtOrBelow);

// The distance answer from the lowest vertex (plane = geom0): DegenerateMesh when there is none.
template <class T>
Status distanceFromLowestVertex(const LowestVertex<T>& lowest, const Transform<T>& planePose, GjkCache<T>* cache,
                                DistanceResult<T>& out) {
  if (!(lowest.height < std::numeric_limits<T>::infinity()))
    return Status::degenerate("the surface has no triangles (every heightfield cell is a hole)");
  const Vec3<T> n = planePose.rotate(Vec3<T>::UnitX());
  out.distance = lowest.height;
  out.normal = n;
  out.point1 = lowest.point;
  out.point0 = lowest.point - lowest.height * n;
  if (cache) cache->iterations = 0;
  return Status();
}

// Dispatch-table kernels (plane = geom0): overlap/plane_triangle_mesh.cpp, overlap/plane_height_field.cpp,
// distance/plane_triangle_mesh.cpp, distance/plane_height_field.cpp.
template <class T>
Status overlapPlaneTriangleMesh(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1,
                                const Transform<T>& p1, bool& overlapping);
template <class T>
Status overlapPlaneHeightField(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1,
                               const Transform<T>& p1, bool& overlapping);
template <class T>
Status distancePlaneTriangleMesh(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1,
                                 const Transform<T>& p1, GjkCache<T>* cache, DistanceResult<T>& out, T farEnough);
template <class T>
Status distancePlaneHeightField(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1,
                                const Transform<T>& p1, GjkCache<T>* cache, DistanceResult<T>& out, T farEnough);

}  // namespace gq::detail
