// Point vs sphere: |p - c| - r, closest point c + r (p - c)/|p - c|; the point itself when inside.
#include "point_distance/point_distance.h"
#include "common/unit_vector.h"

namespace gq::detail {

template <class T>
void pointDistanceSphere(const SphereGeometry<T>& g, const Transform<T>& pose, const Vec3<T>& point,
                         PointDistanceResult<T>& out) {
  const Vec3<T> m = point - pose.p;
  const T len = m.norm();
  out.closestIndex = kInvalidFaceIndex;
  if (len <= g.radius) {
    out.distance = T(0);
    out.closestPoint = point;
    return;
  }
  out.distance = len - g.radius;
  out.closestPoint = pose.p + g.radius * unitOr(m, Vec3<T>(Vec3<T>::UnitX()));
}

template void pointDistanceSphere<float>(const SphereGeometry<float>&, const Transform<float>&, const Vec3<float>&, PointDistanceResult<float>&);
template void pointDistanceSphere<double>(const SphereGeometry<double>&, const Transform<double>&, const Vec3<double>&, PointDistanceResult<double>&);

}  // namespace gq::detail
