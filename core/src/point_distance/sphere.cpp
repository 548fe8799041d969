// Point vs sphere: the ball answer about the center.
#include "point_distance/point_distance.h"

namespace gq::detail {

template <class T>
void pointDistanceSphere(const SphereGeometry<T>& g, const Transform<T>& pose, const Vec3<T>& point,
                         PointDistanceResult<T>& out) {
  pointDistanceBall(pose.p, g.radius, point, Vec3<T>(Vec3<T>::UnitX()), out);
}

template void pointDistanceSphere<float>(const SphereGeometry<float>&, const Transform<float>&, const Vec3<float>&, PointDistanceResult<float>&);
template void pointDistanceSphere<double>(const SphereGeometry<double>&, const Transform<double>&, const Vec3<double>&, PointDistanceResult<double>&);

}  // namespace gq::detail
