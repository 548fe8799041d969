// Point vs capsule: the sphere answer around the closest point of the core segment (local X axis).
#include "point_distance/point_distance.h"
#include "shapes/segment.h"
#include "common/unit_vector.h"

namespace gq::detail {

template <class T>
void pointDistanceCapsule(const CapsuleGeometry<T>& g, const Transform<T>& pose, const Vec3<T>& point,
                          PointDistanceResult<T>& out) {
  const Vec3<T> local = pose.transformInv(point);
  const Vec3<T> onAxis = closestPointOnCapsuleAxis(g.halfHeight, local);
  const Vec3<T> m = local - onAxis;
  const T len = m.norm();
  out.closestIndex = kInvalidFaceIndex;
  if (len <= g.radius) {
    out.distance = T(0);
    out.closestPoint = point;
    return;
  }
  out.distance = len - g.radius;
  out.closestPoint = pose.transform(Vec3<T>(onAxis + g.radius * unitOr(m, Vec3<T>(Vec3<T>::UnitY()))));
}

template void pointDistanceCapsule<float>(const CapsuleGeometry<float>&, const Transform<float>&, const Vec3<float>&, PointDistanceResult<float>&);
template void pointDistanceCapsule<double>(const CapsuleGeometry<double>&, const Transform<double>&, const Vec3<double>&, PointDistanceResult<double>&);

}  // namespace gq::detail
