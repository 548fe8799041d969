// Plane vs box: the corner deepest along -normal, i.e. the box centre's height minus sum_i h_i |n . axis_i|.
#include "distance/distance.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers

template <class T>
void distancePlaneBox(const PlaneGeometry<T>&, const Transform<T>& pose0, const BoxGeometry<T>& g1,
                      const Transform<T>& pose1, DistanceResult<T>& out) {
  const Vec3<T> n = pose0.rotate(Vec3<T>(Vec3<T>::UnitX()));
  const Vec3<T> nLocal = pose1.rotateInv(n);
  const Vec3<T>& h = g1.halfExtents;
  const Vec3<T> cornerLocal(nLocal.x() > T(0) ? -h.x() : h.x(), nLocal.y() > T(0) ? -h.y() : h.y(),
                            nLocal.z() > T(0) ? -h.z() : h.z());
  const Vec3<T> corner = pose1.transform(cornerLocal);
  const T height = n.dot(corner - pose0.p);
  out.normal = n;
  out.distance = height;
  out.point0 = corner - height * n;
  out.point1 = corner;
}

template void distancePlaneBox<float>(const PlaneGeometry<float>&, const Transform<float>&, const BoxGeometry<float>&, const Transform<float>&, DistanceResult<float>&);
template void distancePlaneBox<double>(const PlaneGeometry<double>&, const Transform<double>&, const BoxGeometry<double>&, const Transform<double>&, DistanceResult<double>&);

}  // namespace gq::kernels
