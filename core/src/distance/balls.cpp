// Distance between two balls: the building block of sphere/sphere, sphere/capsule and capsule/capsule.
#include <cmath>

#include "distance/distance.h"

namespace gq::detail {

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

template void ballsDistance<float>(const Vec3<float>&, float, const Vec3<float>&, float, const Vec3<float>&, DistanceResult<float>&);
template void ballsDistance<double>(const Vec3<double>&, double, const Vec3<double>&, double, const Vec3<double>&, DistanceResult<double>&);

}  // namespace gq::detail
