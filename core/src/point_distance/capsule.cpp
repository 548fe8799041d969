// Point vs capsule: the ball answer about the closest point of the core segment (local X axis); a point on the
// axis itself goes out along local Y.
#include "point_distance/point_distance.h"
#include "shapes/segment.h"

namespace gq::detail {

template <class T>
void pointDistanceCapsule(const CapsuleGeometry<T>& g, const Transform<T>& pose, const Vec3<T>& point,
                          PointDistanceResult<T>& out) {
  const Vec3<T> onAxis = closestPointOnCapsuleAxis(g.halfHeight, pose.transformInv(point));
  pointDistanceBall(pose.transform(onAxis), g.radius, point, pose.rotate(Vec3<T>(Vec3<T>::UnitY())), out);
}

template void pointDistanceCapsule<float>(const CapsuleGeometry<float>&, const Transform<float>&, const Vec3<float>&, PointDistanceResult<float>&);
template void pointDistanceCapsule<double>(const CapsuleGeometry<double>&, const Transform<double>&, const Vec3<double>&, PointDistanceResult<double>&);

}  // namespace gq::detail
