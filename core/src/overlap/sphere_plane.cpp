// Sphere/plane overlap: the plane is the solid half-space x <= 0 of its frame, so the sphere overlaps
// when its centre lies no more than r in front of the plane.
#include "overlap/overlap.h"
#include "shapes/plane.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers

template <class T>
bool overlapSpherePlane(const SphereGeometry<T>& g0, const Transform<T>& p0, const PlaneGeometry<T>& g1, const Transform<T>& p1) {
  (void)g1;
  return planeNormal(p1).dot(p0.p - p1.p) <= g0.radius;
}

template bool overlapSpherePlane<float>(const SphereGeometry<float>&, const Transform<float>&, const PlaneGeometry<float>&, const Transform<float>&);
template bool overlapSpherePlane<double>(const SphereGeometry<double>&, const Transform<double>&, const PlaneGeometry<double>&, const Transform<double>&);

}  // namespace gq::kernels
