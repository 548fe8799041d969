// Sphere/box MTD (penetration/sphere_box.h).
#include "penetration/sphere_box.h"

#include "penetration/penetration.h"

namespace gq::detail {

template <class T>
bool penetrationSphereBox(const SphereGeometry<T>& g0, const Transform<T>& p0, const BoxGeometry<T>& g1, const Transform<T>& p1,
                          Vec3<T>& direction, T& depth) {
  return sphereBoxPenetration(g0, p0, g1, p1, direction, depth);
}

template bool penetrationSphereBox<float>(const SphereGeometry<float>&, const Transform<float>&, const BoxGeometry<float>&, const Transform<float>&,
                                         Vec3<float>&, float&);
template bool penetrationSphereBox<double>(const SphereGeometry<double>&, const Transform<double>&, const BoxGeometry<double>&, const Transform<double>&,
                                          Vec3<double>&, double&);

}  // namespace gq::detail
