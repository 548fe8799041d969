// Sphere/capsule overlap: distance from the centre to the capsule segment <= r0 + r1.
#include "overlap/overlap.h"
#include "overlap/closest_points.h"

namespace gq::detail {

template <class T>
bool overlapSphereCapsule(const SphereGeometry<T>& g0, const Transform<T>& p0, const CapsuleGeometry<T>& g1, const Transform<T>& p1) {
  const Vec3<T> axis = p1.rotate(Vec3<T>(g1.halfHeight, T(0), T(0)));
  const Vec3<T> q = closestPointOnSegment(Segment<T>{p1.p - axis, p1.p + axis}, p0.p);
  const T r = g0.radius + g1.radius;
  return (p0.p - q).squaredNorm() <= r * r;
}

template bool overlapSphereCapsule<float>(const SphereGeometry<float>&, const Transform<float>&, const CapsuleGeometry<float>&, const Transform<float>&);
template bool overlapSphereCapsule<double>(const SphereGeometry<double>&, const Transform<double>&, const CapsuleGeometry<double>&, const Transform<double>&);

}  // namespace gq::detail
