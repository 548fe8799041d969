// Custom bounds: the callbacks' local box, transformed (centre by the pose, extents by |R|).
#include "bounds/bounds.h"

namespace gq::detail {

template <class T> Bounds3<T> boundsCustom(const CustomGeometry<T>& g, const Transform<T>& pose) {
  const Bounds3<T> local = g.callbacks->localBounds();
  if (local.isEmpty()) return local;
  const Mat3<T> absR = pose.q.toRotationMatrix().cwiseAbs();
  return Bounds3<T>::fromCenterExtents(pose.transform(local.center()), absR * local.extents());
}

template Bounds3<float> boundsCustom<float>(const CustomGeometry<float>&, const Transform<float>&);
template Bounds3<double> boundsCustom<double>(const CustomGeometry<double>&, const Transform<double>&);

}  // namespace gq::detail
