// Ray vs custom geometry: the callbacks answer in the shape's local frame; the hit comes back to world here.
// A callback answer outside [0, maxDist] (or NaN) counts as a miss, and non-finite optional fields are dropped, so
// no NaN leaves the query.
#include "raycast/raycast.h"

namespace gq::detail {

template <class T>
std::uint32_t raycastCustom(const CustomGeometry<T>& g, const Transform<T>& pose, const RayQuery<T>& ray,
                            RaycastHit<T>* hits) {
  const Vec3<T> o = pose.transformInv(ray.origin);
  const Vec3<T> d = pose.rotateInv(ray.dir);
  RaycastHit<T> local;
  if (!g.callbacks->raycast(o, d, ray.maxDist, ray.flags, local)) return 0;
  if (!(local.distance >= T(0) && local.distance <= ray.maxDist)) return 0;
  // Only what the caller asked for: fields it did not request stay untouched, except that a hit from inside
  // (distance 0) always carries position and normal (the solid rule).
  const bool inside = local.distance == T(0);
  HitFlags written = local.flags.without(HitFlag::Position | HitFlag::Normal);
  RaycastHit<T>& hit = hits[0];
  hit.distance = local.distance;
  hit.faceIndex = local.faceIndex;
  hit.u = local.u;
  hit.v = local.v;
  if ((inside || ray.flags.has(HitFlag::Position)) && local.flags.has(HitFlag::Position) && isFinite(local.position)) {
    hit.position = pose.transform(local.position);
    written |= HitFlag::Position;
  }
  if ((inside || ray.flags.has(HitFlag::Normal)) && local.flags.has(HitFlag::Normal) && isFinite(local.normal)) {
    hit.normal = pose.rotate(local.normal);
    written |= HitFlag::Normal;
  }
  hit.flags = written;
  return 1;
}

template std::uint32_t raycastCustom<float>(const CustomGeometry<float>&, const Transform<float>&, const RayQuery<float>&, RaycastHit<float>*);
template std::uint32_t raycastCustom<double>(const CustomGeometry<double>&, const Transform<double>&, const RayQuery<double>&, RaycastHit<double>*);

}  // namespace gq::detail
