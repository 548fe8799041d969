// Sphere vs capsule: the ball at the sphere centre against the ball at the closest point of the capsule's segment.
// A centre on the segment reports a normal orthogonal to the capsule axis.
#include "distance/distance.h"

namespace gq::detail {

template <class T>
void distanceSphereCapsule(const SphereGeometry<T>& g0, const Transform<T>& pose0, const CapsuleGeometry<T>& g1,
                           const Transform<T>& pose1, DistanceResult<T>& out) {
  const Vec3<T> axis = pose1.rotate(Vec3<T>(g1.halfHeight, T(0), T(0)));
  const Vec3<T> c1 = closestOnSegment<T>(pose1.p - axis, pose1.p + axis, pose0.p);
  ballsDistance(pose0.p, g0.radius, c1, g1.radius, anyOrthogonal<T>(pose1.rotate(Vec3<T>(Vec3<T>::UnitX()))), out);
}

template void distanceSphereCapsule<float>(const SphereGeometry<float>&, const Transform<float>&, const CapsuleGeometry<float>&, const Transform<float>&, DistanceResult<float>&);
template void distanceSphereCapsule<double>(const SphereGeometry<double>&, const Transform<double>&, const CapsuleGeometry<double>&, const Transform<double>&, DistanceResult<double>&);

}  // namespace gq::detail
