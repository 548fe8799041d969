// Plane/custom overlap: the custom shape's support point along -n lies in the half-space x <= 0.
#include "gq/custom.h"
#include "shapes/plane.h"
#include "overlap/overlap.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers

template <class T>
bool overlapPlaneCustom(const PlaneGeometry<T>&, const Transform<T>& p0, const CustomGeometry<T>& g1, const Transform<T>& p1) {
  const Vec3<T> n = planeNormal(p0);
  const Vec3<T> lowest = p1.transform(g1.callbacks->support(p1.rotateInv(Vec3<T>(-n))));
  return n.dot(lowest - p0.p) <= T(0);
}

template bool overlapPlaneCustom<float>(const PlaneGeometry<float>&, const Transform<float>&, const CustomGeometry<float>&, const Transform<float>&);
template bool overlapPlaneCustom<double>(const PlaneGeometry<double>&, const Transform<double>&, const CustomGeometry<double>&, const Transform<double>&);

}  // namespace gq::kernels
