// Distance between two balls: the building block of sphere/sphere, sphere/capsule and capsule/capsule.
#include <cmath>

#include "distance/distance.h"

namespace gq::detail {

template <class T> Vec3<T> anyOrthogonal(const Vec3<T>& d) {
  if (!(d.squaredNorm() > T(0))) return Vec3<T>::UnitX();
  // Cross with the coordinate axis least aligned with d.
  Eigen::Index i;
  d.cwiseAbs().minCoeff(&i);
  return d.cross(Vec3<T>::Unit(i)).normalized();
}

// d = |c1 - c0| - r0 - r1 along n = (c1 - c0) / |c1 - c0|; witnesses c0 + r0 n and c1 - r1 n.
template <class T>
void ballsDistance(const Vec3<T>& c0, T r0, const Vec3<T>& c1, T r1, const Vec3<T>& fallback, DistanceResult<T>& out) {
  const Vec3<T> delta = c1 - c0;
  const T len = delta.norm();
  out.normal = unitOr(delta, fallback);
  out.distance = len - r0 - r1;
  out.point0 = c0 + r0 * out.normal;
  out.point1 = c1 - r1 * out.normal;
}

template Vec3<float> anyOrthogonal<float>(const Vec3<float>&);
template Vec3<double> anyOrthogonal<double>(const Vec3<double>&);
template void ballsDistance<float>(const Vec3<float>&, float, const Vec3<float>&, float, const Vec3<float>&, DistanceResult<float>&);
template void ballsDistance<double>(const Vec3<double>&, double, const Vec3<double>&, double, const Vec3<double>&, DistanceResult<double>&);

}  // namespace gq::detail
