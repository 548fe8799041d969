// Sphere/capsule overlap: distance from the centre to the capsule segment <= r0 + r1 (overlap/sphere_capsule.h).
#include "overlap/sphere_capsule.h"

#include "overlap/overlap.h"

namespace gq::kernels {

template <class T> bool overlapSphereCapsule(const Vec3<T>& c0, T r0, const Vec3<T>& c1, const Vec3<T>& a1, T r1) {
  return detail::sphereCapsuleOverlaps<T>(c0, r0, c1, a1, r1);
}

template <class T>
bool overlapSphereCapsule(const SphereGeometry<T>& g0, const Transform<T>& p0, const CapsuleGeometry<T>& g1, const Transform<T>& p1) {
  return detail::sphereCapsuleOverlaps<T>(g0, p0, g1, p1);
}

template bool overlapSphereCapsule<float>(const SphereGeometry<float>&, const Transform<float>&, const CapsuleGeometry<float>&, const Transform<float>&);
template bool overlapSphereCapsule<double>(const SphereGeometry<double>&, const Transform<double>&, const CapsuleGeometry<double>&, const Transform<double>&);
template bool overlapSphereCapsule<float>(const Vec3<float>&, float, const Vec3<float>&, const Vec3<float>&, float);
template bool overlapSphereCapsule<double>(const Vec3<double>&, double, const Vec3<double>&, const Vec3<double>&, double);

}  // namespace gq::kernels
