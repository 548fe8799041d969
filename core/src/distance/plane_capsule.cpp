// Plane vs capsule: the lower of the segment's end points (height above the plane) minus the radius.
#include "distance/distance.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers

template <class T>
void distancePlaneCapsule(const PlaneGeometry<T>&, const Transform<T>& pose0, const CapsuleGeometry<T>& g1,
                          const Transform<T>& pose1, DistanceResult<T>& out) {
  const Vec3<T> n = pose0.rotate(Vec3<T>(Vec3<T>::UnitX()));
  const Vec3<T> axis = pose1.rotate(Vec3<T>(g1.halfHeight, T(0), T(0)));
  const Vec3<T> end = n.dot(axis) > T(0) ? Vec3<T>(pose1.p - axis) : Vec3<T>(pose1.p + axis);
  const T height = n.dot(end - pose0.p);
  out.normal = n;
  out.distance = height - g1.radius;
  out.point0 = end - height * n;
  out.point1 = end - g1.radius * n;
}

template void distancePlaneCapsule<float>(const PlaneGeometry<float>&, const Transform<float>&, const CapsuleGeometry<float>&, const Transform<float>&, DistanceResult<float>&);
template void distancePlaneCapsule<double>(const PlaneGeometry<double>&, const Transform<double>&, const CapsuleGeometry<double>&, const Transform<double>&, DistanceResult<double>&);

}  // namespace gq::kernels
