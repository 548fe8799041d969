// Sphere vs sphere: two balls. Concentric spheres report normal +X (world).
#include "distance/distance.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers

template <class T>
void distanceSphereSphere(const SphereGeometry<T>& g0, const Transform<T>& pose0, const SphereGeometry<T>& g1,
                          const Transform<T>& pose1, DistanceResult<T>& out) {
  ballsDistance(pose0.p, g0.radius, pose1.p, g1.radius, out);
}

template void distanceSphereSphere<float>(const SphereGeometry<float>&, const Transform<float>&, const SphereGeometry<float>&, const Transform<float>&, DistanceResult<float>&);
template void distanceSphereSphere<double>(const SphereGeometry<double>&, const Transform<double>&, const SphereGeometry<double>&, const Transform<double>&, DistanceResult<double>&);

}  // namespace gq::kernels
