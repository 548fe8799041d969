// Sphere/capsule overlap: distance from the centre to the capsule segment <= r0 + r1.
#include "overlap/overlap.h"
#include "shapes/segment.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers

template <class T> bool overlapSphereCapsule(const Vec3<T>& c0, T r0, const Vec3<T>& c1, const Vec3<T>& a1, T r1) {
  const Vec3<T> q = closestPointOnSegment(Vec3<T>(c1 - a1), Vec3<T>(c1 + a1), c0);
  const T r = r0 + r1;
  return (c0 - q).squaredNorm() <= r * r;
}

template <class T>
bool overlapSphereCapsule(const SphereGeometry<T>& g0, const Transform<T>& p0, const CapsuleGeometry<T>& g1, const Transform<T>& p1) {
  return overlapSphereCapsule<T>(p0.p, g0.radius, p1.p, p1.rotate(Vec3<T>(g1.halfHeight, T(0), T(0))), g1.radius);
}

template bool overlapSphereCapsule<float>(const SphereGeometry<float>&, const Transform<float>&, const CapsuleGeometry<float>&, const Transform<float>&);
template bool overlapSphereCapsule<double>(const SphereGeometry<double>&, const Transform<double>&, const CapsuleGeometry<double>&, const Transform<double>&);
template bool overlapSphereCapsule<float>(const Vec3<float>&, float, const Vec3<float>&, const Vec3<float>&, float);
template bool overlapSphereCapsule<double>(const Vec3<double>&, double, const Vec3<double>&, const Vec3<double>&, double);

}  // namespace gq::kernels
