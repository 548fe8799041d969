// Ray vs plane (x = 0 in the plane's frame, normal +X): single-sided and including its boundary. An origin behind
// the plane (signed distance < 0) never hits; an origin on it hits at distance 0; otherwise the ray must move
// against the normal: t = -s / (n.d).
#include "raycast/raycast.h"
#include "shapes/ray_hit.h"

namespace gq::detail {

template <class T>
std::uint32_t raycastPlane(const PlaneGeometry<T>&, const Transform<T>& pose, const RayQuery<T>& ray,
                           RaycastHit<T>* hits) {
  const Vec3<T> n = pose.rotate(Vec3<T>::UnitX());
  const T s = n.dot(ray.origin - pose.p);
  if (s < T(0)) return 0;  // behind the single-sided plane
  T t = T(0);
  if (s > T(0)) {
    const T approach = n.dot(ray.dir);
    if (approach >= T(0)) return 0;  // parallel or moving away
    t = -s / approach;
    if (t > ray.maxDist) return 0;
  }
  writeSurfaceHit(ray, t, kInvalidFaceIndex, [&] { return n; }, hits[0]);
  return 1;
}

template std::uint32_t raycastPlane<float>(const PlaneGeometry<float>&, const Transform<float>&, const RayQuery<float>&, RaycastHit<float>*);
template std::uint32_t raycastPlane<double>(const PlaneGeometry<double>&, const Transform<double>&, const RayQuery<double>&, RaycastHit<double>*);

}  // namespace gq::detail
