// Box bounds: world extents = |R| * halfExtents (tight for rotated boxes).
#include "bounds/bounds.h"

namespace gq::detail {

template <class T> Bounds3<T> boundsBox(const BoxGeometry<T>& g, const Transform<T>& pose) {
  const Mat3<T> absR = pose.q.toRotationMatrix().cwiseAbs();
  return Bounds3<T>::fromCenterExtents(pose.p, absR * g.halfExtents);
}

template Bounds3<float> boundsBox<float>(const BoxGeometry<float>&, const Transform<float>&);
template Bounds3<double> boundsBox<double>(const BoxGeometry<double>&, const Transform<double>&);

}  // namespace gq::detail
