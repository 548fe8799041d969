// Point vs box: clamp the local point to [-h, h]; the clamped point is the closest one, and equals the point when
// it is inside.
#include "point_distance/point_distance.h"

namespace gq::detail {

template <class T>
void pointDistanceBox(const BoxGeometry<T>& g, const Transform<T>& pose, const Vec3<T>& point,
                      PointDistanceResult<T>& out) {
  const Vec3<T> local = pose.transformInv(point);
  const Vec3<T> clamped = local.cwiseMax(-g.halfExtents).cwiseMin(g.halfExtents);
  out.closestIndex = kInvalidFaceIndex;
  if (clamped == local) {
    out.distance = T(0);
    out.closestPoint = point;
    return;
  }
  out.distance = (local - clamped).norm();
  out.closestPoint = pose.transform(clamped);
}

template void pointDistanceBox<float>(const BoxGeometry<float>&, const Transform<float>&, const Vec3<float>&, PointDistanceResult<float>&);
template void pointDistanceBox<double>(const BoxGeometry<double>&, const Transform<double>&, const Vec3<double>&, PointDistanceResult<double>&);

}  // namespace gq::detail
