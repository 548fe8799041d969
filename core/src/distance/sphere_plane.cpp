// Sphere vs plane: signed height of the centre above the plane minus the radius. The normal from the sphere
// towards the plane is the plane's -normal.
#include "distance/distance.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers

template <class T>
void distanceSpherePlane(const SphereGeometry<T>& g0, const Transform<T>& pose0, const PlaneGeometry<T>&,
                         const Transform<T>& pose1, DistanceResult<T>& out) {
  const Vec3<T> n = pose1.rotate(Vec3<T>(Vec3<T>::UnitX()));
  const T height = n.dot(pose0.p - pose1.p);
  out.normal = -n;
  out.distance = height - g0.radius;
  out.point0 = pose0.p - g0.radius * n;
  out.point1 = pose0.p - height * n;
}

template void distanceSpherePlane<float>(const SphereGeometry<float>&, const Transform<float>&, const PlaneGeometry<float>&, const Transform<float>&, DistanceResult<float>&);
template void distanceSpherePlane<double>(const SphereGeometry<double>&, const Transform<double>&, const PlaneGeometry<double>&, const Transform<double>&, DistanceResult<double>&);

}  // namespace gq::kernels
