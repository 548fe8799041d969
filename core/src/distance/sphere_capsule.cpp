// Sphere vs capsule: the ball at the sphere centre against the ball at the closest point of the capsule's segment.
// A centre on the segment reports a normal orthogonal to the capsule axis.
#include "distance/distance.h"
#include "shapes/segment.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers

template <class T>
void distanceSphereCapsule(const Vec3<T>& c0, T r0, const CapsuleAxis<T>& capsule1, DistanceResult<T>& out) {
  const Vec3<T> a = capsule1.halfHeight * capsule1.axis;
  const Vec3<T> c1 = closestPointOnSegment<T>(capsule1.centre - a, capsule1.centre + a, c0);
  // A centre on the segment (|c1 - c0| = 0) takes a normal orthogonal to the axis.
  ballsDistanceOr(c0, r0, c1, capsule1.radius, [&] { return anyPerpendicular<T>(capsule1.axis); }, out);
}

template <class T>
void distanceSphereCapsule(const SphereGeometry<T>& g0, const Transform<T>& pose0, const CapsuleGeometry<T>& g1,
                           const Transform<T>& pose1, DistanceResult<T>& out) {
  const CapsuleAxis<T> capsule{pose1.p, pose1.rotate(Vec3<T>(Vec3<T>::UnitX())), g1.halfHeight, g1.radius};
  distanceSphereCapsule(pose0.p, g0.radius, capsule, out);
}

template void distanceSphereCapsule<float>(const SphereGeometry<float>&, const Transform<float>&, const CapsuleGeometry<float>&, const Transform<float>&, DistanceResult<float>&);
template void distanceSphereCapsule<double>(const SphereGeometry<double>&, const Transform<double>&, const CapsuleGeometry<double>&, const Transform<double>&, DistanceResult<double>&);
template void distanceSphereCapsule<float>(const Vec3<float>&, float, const CapsuleAxis<float>&, DistanceResult<float>&);
template void distanceSphereCapsule<double>(const Vec3<double>&, double, const CapsuleAxis<double>&, DistanceResult<double>&);

}  // namespace gq::kernels
