// Capsule bounds: the box of the two segment end points, grown by the radius (tight for any rotation).
#include "bounds/bounds.h"

namespace gq::detail {

template <class T> Bounds3<T> boundsCapsule(const CapsuleGeometry<T>& g, const Transform<T>& pose) {
  const Vec3<T> axis = pose.rotate(Vec3<T>(g.halfHeight, T(0), T(0)));
  const Vec3<T> extents = axis.cwiseAbs() + Vec3<T>::Constant(g.radius);
  return Bounds3<T>::fromCenterExtents(pose.p, extents);
}

template Bounds3<float> boundsCapsule<float>(const CapsuleGeometry<float>&, const Transform<float>&);
template Bounds3<double> boundsCapsule<double>(const CapsuleGeometry<double>&, const Transform<double>&);

}  // namespace gq::detail
