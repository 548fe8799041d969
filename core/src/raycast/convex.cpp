// Ray vs scaled convex hull. The ray goes into the unscaled hull frame with the inverse scale matrix S^-1 (an
// affine map, so the ray parameter t is unchanged and stays the world distance), then is clipped against every
// polygon plane n.x + d <= 0 (Cyrus-Beck): entering planes raise tNear, leaving planes lower tFar. The hit normal
// returns to shape space with the inverse-transpose S^-T (= S^-1, S is symmetric), then to world.
#include <cmath>
#include <limits>

#include "gq/cooking.h"
#include "raycast/raycast.h"
#include "shapes/hull_scale.h"
#include "shapes/ray_hit.h"

namespace gq::detail {

template <class T>
std::uint32_t raycastConvex(const ConvexMeshGeometry<T>& g, const Transform<T>& pose, const RayQuery<T>& ray,
                            RaycastHit<T>* hits) {
  const ConvexMesh<T>& hull = *g.mesh;
  const HullScale<T> scale(g.scale);
  const Vec3<T> o = scale.vectorToMesh(pose.transformInv(ray.origin));
  const Vec3<T> d = scale.vectorToMesh(pose.rotateInv(ray.dir));
  bool inside = true;
  T tNear = -std::numeric_limits<T>::infinity(), tFar = std::numeric_limits<T>::infinity();
  std::uint32_t face = kInvalidFaceIndex;
  for (std::uint32_t i = 0; i < hull.polygons.size(); ++i) {
    const HullPolygon<T>& poly = hull.polygons[i];
    const T dist = poly.normal.dot(o) + poly.d;  // > 0: origin in front of this plane
    const T approach = poly.normal.dot(d);
    if (dist > T(0)) inside = false;
    if (approach == T(0)) {
      if (dist > T(0)) return 0;  // parallel to and outside this plane
      continue;
    }
    const T t = -dist / approach;
    if (approach < T(0)) {
      if (t > tNear) {
        tNear = t;
        face = i;
      }
    } else {
      tFar = std::min(tFar, t);
    }
  }
  if (inside) {
    writeInsideHit(ray, hits[0]);
    return 1;
  }
  // An entry parameter that overflowed (a ray all but parallel to a face, far away in the hull's frame) is no hit
  // (found by fuzz_raycast, float). The façade's finite maxDist rejects an infinite one in every kernel; this test
  // also rejects NaN.
  if (face == kInvalidFaceIndex || !std::isfinite(tNear) || tNear > tFar || tNear < T(0) || tNear > ray.maxDist)
    return 0;
  const auto normal = [&] { return pose.rotate(scale.normalToShape(hull.polygons[face].normal)); };
  writeSurfaceHit(ray, tNear, face, normal, hits[0]);
  return 1;
}

template std::uint32_t raycastConvex<float>(const ConvexMeshGeometry<float>&, const Transform<float>&, const RayQuery<float>&, RaycastHit<float>*);
template std::uint32_t raycastConvex<double>(const ConvexMeshGeometry<double>&, const Transform<double>&, const RayQuery<double>&, RaycastHit<double>*);

}  // namespace gq::detail
