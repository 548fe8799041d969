// Plane bounds. A plane is infinite, so its box covers the whole representable space (+-max, never inf), except
// when its normal is exactly a coordinate axis: then the solid half-space x_local <= 0 ends at the plane along that
// axis (as PhysX's plane bounds). "Exactly" means the other two normal components are exactly zero: any tilt makes
// the plane cross every finite bound on that axis, so a tolerance would give a box that misses part of the plane.
#include <limits>

#include "bounds/bounds.h"

namespace gq::detail {

template <class T> Bounds3<T> boundsPlane(const PlaneGeometry<T>&, const Transform<T>& pose) {
  constexpr T big = std::numeric_limits<T>::max();
  Bounds3<T> b = Bounds3<T>::fromMinMax(Vec3<T>::Constant(-big), Vec3<T>::Constant(big));
  const Vec3<T> n = pose.rotate(Vec3<T>::UnitX());
  for (int axis = 0; axis < 3; ++axis) {
    const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
    if (n[a1] != T(0) || n[a2] != T(0)) continue;
    if (n[axis] > T(0)) b.max[axis] = pose.p[axis];
    else b.min[axis] = pose.p[axis];
  }
  return b;
}

template Bounds3<float> boundsPlane<float>(const PlaneGeometry<float>&, const Transform<float>&);
template Bounds3<double> boundsPlane<double>(const PlaneGeometry<double>&, const Transform<double>&);

}  // namespace gq::detail
