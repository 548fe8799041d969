// Sphere/sphere overlap: |c0 - c1| <= r0 + r1.
#include "overlap/overlap.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers

template <class T>
bool overlapSphereSphere(const SphereGeometry<T>& g0, const Transform<T>& p0, const SphereGeometry<T>& g1, const Transform<T>& p1) {
  return overlapSphereSphere<T>(p0.p, g0.radius, p1.p, g1.radius);
}

template bool overlapSphereSphere<float>(const SphereGeometry<float>&, const Transform<float>&, const SphereGeometry<float>&, const Transform<float>&);
template bool overlapSphereSphere<double>(const SphereGeometry<double>&, const Transform<double>&, const SphereGeometry<double>&, const Transform<double>&);

}  // namespace gq::kernels
