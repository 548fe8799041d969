// Sphere/box overlap: clamp the centre into the box (its frame) for the closest point.
#include "overlap/overlap.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers

template <class T>
bool overlapSphereBox(const SphereGeometry<T>& g0, const Transform<T>& p0, const BoxGeometry<T>& g1, const Transform<T>& p1) {
  return overlapSphereBox<T>(p1.transformInv(p0.p), g0.radius, g1.halfExtents);
}

template bool overlapSphereBox<float>(const SphereGeometry<float>&, const Transform<float>&, const BoxGeometry<float>&, const Transform<float>&);
template bool overlapSphereBox<double>(const SphereGeometry<double>&, const Transform<double>&, const BoxGeometry<double>&, const Transform<double>&);

}  // namespace gq::kernels
