// Ray vs box: slab test in the box frame. The entry distance is the largest per-axis entry, the exit the smallest
// per-axis exit; the normal is the face of the axis that set the entry.
#include <limits>

#include "raycast/raycast.h"
#include "shapes/ray_hit.h"

namespace gq::detail {

template <class T>
std::uint32_t raycastBox(const BoxGeometry<T>& g, const Transform<T>& pose, const RayQuery<T>& ray,
                         RaycastHit<T>* hits) {
  const Vec3<T> o = pose.transformInv(ray.origin);
  const Vec3<T> d = pose.rotateInv(ray.dir);
  const Vec3<T>& h = g.halfExtents;
  if ((o.cwiseAbs().array() <= h.array()).all()) {
    writeInsideHit(ray, hits[0]);
    return 1;
  }
  T tNear = -std::numeric_limits<T>::infinity(), tFar = std::numeric_limits<T>::infinity();
  int axis = -1;
  for (int i = 0; i < 3; ++i) {
    if (d[i] == T(0)) {
      if (std::abs(o[i]) > h[i]) return 0;  // parallel to and outside this slab
      continue;
    }
    const T t0 = (-h[i] - o[i]) / d[i], t1 = (h[i] - o[i]) / d[i];
    const T enter = std::min(t0, t1), exit = std::max(t0, t1);
    if (enter > tNear) {
      tNear = enter;
      axis = i;
    }
    tFar = std::min(tFar, exit);
  }
  if (axis < 0 || tNear > tFar || tNear < T(0) || tNear > ray.maxDist) return 0;
  const auto normal = [&] {
    Vec3<T> n = Vec3<T>::Zero();
    n[axis] = d[axis] > T(0) ? T(-1) : T(1);
    return pose.rotate(n);
  };
  writeSurfaceHit(ray, tNear, kInvalidFaceIndex, normal, hits[0]);
  return 1;
}

template std::uint32_t raycastBox<float>(const BoxGeometry<float>&, const Transform<float>&, const RayQuery<float>&, RaycastHit<float>*);
template std::uint32_t raycastBox<double>(const BoxGeometry<double>&, const Transform<double>&, const RayQuery<double>&, RaycastHit<double>*);

}  // namespace gq::detail
