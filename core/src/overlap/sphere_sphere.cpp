// Sphere/sphere overlap: |c0 - c1| <= r0 + r1.
#include "overlap/overlap.h"

namespace gq::detail {

template <class T>
bool overlapSphereSphere(const SphereGeometry<T>& g0, const Transform<T>& p0, const SphereGeometry<T>& g1, const Transform<T>& p1) {
  const T r = g0.radius + g1.radius;
  return (p0.p - p1.p).squaredNorm() <= r * r;
}

template bool overlapSphereSphere<float>(const SphereGeometry<float>&, const Transform<float>&, const SphereGeometry<float>&, const Transform<float>&);
template bool overlapSphereSphere<double>(const SphereGeometry<double>&, const Transform<double>&, const SphereGeometry<double>&, const Transform<double>&);

}  // namespace gq::detail
