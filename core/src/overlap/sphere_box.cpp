// Sphere/box overlap: clamp the centre into the box (its frame) for the closest point.
#include "overlap/overlap.h"

namespace gq::detail {

template <class T>
bool overlapSphereBox(const SphereGeometry<T>& g0, const Transform<T>& p0, const BoxGeometry<T>& g1, const Transform<T>& p1) {
  const Vec3<T> c = p1.transformInv(p0.p);
  const Vec3<T> q = c.cwiseMax(-g1.halfExtents).cwiseMin(g1.halfExtents);
  return (c - q).squaredNorm() <= g0.radius * g0.radius;
}

template bool overlapSphereBox<float>(const SphereGeometry<float>&, const Transform<float>&, const BoxGeometry<float>&, const Transform<float>&);
template bool overlapSphereBox<double>(const SphereGeometry<double>&, const Transform<double>&, const BoxGeometry<double>&, const Transform<double>&);

}  // namespace gq::detail
