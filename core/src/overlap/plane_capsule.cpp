// Plane/capsule overlap: the lower capsule end is within r of the half-space x <= 0.
#include "overlap/overlap.h"
#include "shapes/plane.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers

template <class T>
bool overlapPlaneCapsule(const PlaneGeometry<T>& g0, const Transform<T>& p0, const CapsuleGeometry<T>& g1, const Transform<T>& p1) {
  (void)g0;
  const Vec3<T> n = planeNormal(p0);
  const T centre = n.dot(p1.p - p0.p);
  const T reach = std::abs(n.dot(p1.rotate(Vec3<T>::UnitX()))) * g1.halfHeight;  // support of the segment along -n
  return centre - reach <= g1.radius;
}

template bool overlapPlaneCapsule<float>(const PlaneGeometry<float>&, const Transform<float>&, const CapsuleGeometry<float>&, const Transform<float>&);
template bool overlapPlaneCapsule<double>(const PlaneGeometry<double>&, const Transform<double>&, const CapsuleGeometry<double>&, const Transform<double>&);

}  // namespace gq::kernels
