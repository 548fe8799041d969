#pragma once
// Distance kernels with a triangle mesh or heightfield (dispatch table signature of dispatch/distance.cpp).
// A mesh or heightfield is a thin surface: the distance is the minimum over its triangles, >= 0. In contact the
// distance is 0 (no depth: a surface has no inside), point0 = point1 is a contact point on the surface and the
// normal is the deepest triangle's MTD direction from the shape towards the surface (mesh-mesh: the first mesh's
// triangle normal). Mesh-heightfield and heightfield-heightfield distance are Unsupported.
#include <cmath>
#include <limits>

#include "gq/geometry.h"
#include "gq/query.h"
#include "gq/status.h"
#include "gq/transform.h"

namespace gq::detail {

// Sphere, capsule, box, convex mesh or convex custom (g0) vs triangle mesh or heightfield (g1): best-first BVH
// traversal (cell rings for heightfields) bounded by the best distance so far; exact closed forms for sphere and
// capsule triangles, GJK for the rest. `farEnough`: the search starts bounded by it (a heightfield's rings stop
// growing past it), and a surface with no triangle within it gets only out.distance, just above it
// (distanceWithin's contract).
template <class T>
Status distanceConvexSurface(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1,
                             const Transform<T>& p1, GjkCache<T>* cache, DistanceResult<T>& out,
                             T farEnough = std::numeric_limits<T>::infinity());

// What a bounded surface search reports when no triangle lies within farEnough (distanceWithin's stop): a lower
// bound above it. A surface's distance is >= 0, so 0 for a negative bound (nothing to search); otherwise every
// triangle was proven farther (strictly), and the next number up bounds the distance.
template <class T> T surfaceBoundBeyond(T farEnough) {
  return farEnough < T(0) ? T(0) : std::nextafter(farEnough, std::numeric_limits<T>::infinity());
}

// Triangle mesh vs triangle mesh: best-first dual BVH traversal, exact triangle-triangle distance; `farEnough` as
// distanceConvexSurface's for a mesh.
template <class T>
Status distanceTriangleMeshTriangleMesh(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1,
                                        const Transform<T>& p1, GjkCache<T>* cache, DistanceResult<T>& out,
                                        T farEnough = std::numeric_limits<T>::infinity());

}  // namespace gq::detail
