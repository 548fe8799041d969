// Sphere bounds: centre +- radius (rotation-invariant).
#include "bounds/bounds.h"

namespace gq::detail {

template <class T> Bounds3<T> boundsSphere(const SphereGeometry<T>& g, const Transform<T>& pose) {
  return Bounds3<T>::fromCenterExtents(pose.p, Vec3<T>::Constant(g.radius));
}

template Bounds3<float> boundsSphere<float>(const SphereGeometry<float>&, const Transform<float>&);
template Bounds3<double> boundsSphere<double>(const SphereGeometry<double>&, const Transform<double>&);

}  // namespace gq::detail
