#pragma once
// Overlap kernels with a triangle mesh or a heightfield (thin surfaces: a shape overlaps when it touches or crosses
// any triangle; a solid fully enclosed by a closed mesh does not overlap it, as in the spec). They have the
// dispatch table's signature (dispatch/overlap.cpp) and take the geometries as validated by the façade. Touching
// counts as overlapping. Plane vs mesh/heightfield stays Unsupported (the spec).
#include "gq/geometry.h"
#include "gq/status.h"
#include "gq/transform.h"

namespace gq::detail {

// Sphere, capsule, box, convex mesh or convex custom (g0) vs triangle mesh (g1).
template <class T>
Status overlapConvexTriangleMesh(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1,
                                 const Transform<T>& p1, bool& overlapping);
// Sphere, capsule, box, convex mesh or convex custom (g0) vs heightfield (g1).
template <class T>
Status overlapConvexHeightField(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1,
                                const Transform<T>& p1, bool& overlapping);
// Mesh vs mesh: dual BVH traversal, exact triangle-triangle test.
template <class T>
Status overlapTriangleMeshTriangleMesh(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1,
                                       const Transform<T>& p1, bool& overlapping);
// Mesh vs heightfield (the spec's engine does not support it): mesh triangles near the heightfield, each against
// the heightfield cells under its box.
template <class T>
Status overlapTriangleMeshHeightField(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1,
                                      const Transform<T>& p1, bool& overlapping);
template <class T>
Status overlapHeightFieldHeightField(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1,
                                     const Transform<T>& p1, bool& overlapping);

}  // namespace gq::detail
