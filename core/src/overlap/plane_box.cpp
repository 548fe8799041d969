// Plane/box overlap: the box support point along -n lies in the half-space x <= 0.
#include "overlap/overlap.h"
#include "shapes/plane.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers

template <class T>
bool overlapPlaneBox(const PlaneGeometry<T>& g0, const Transform<T>& p0, const BoxGeometry<T>& g1, const Transform<T>& p1) {
  (void)g0;
  const Vec3<T> n = planeNormal(p0);
  const T reach = p1.rotateInv(n).cwiseAbs().dot(g1.halfExtents);  // support of the box along -n
  return n.dot(p1.p - p0.p) - reach <= T(0);
}

template bool overlapPlaneBox<float>(const PlaneGeometry<float>&, const Transform<float>&, const BoxGeometry<float>&, const Transform<float>&);
template bool overlapPlaneBox<double>(const PlaneGeometry<double>&, const Transform<double>&, const BoxGeometry<double>&, const Transform<double>&);

}  // namespace gq::kernels
