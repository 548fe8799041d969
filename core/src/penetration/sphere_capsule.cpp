// Sphere/capsule MTD (penetration/sphere_capsule.h).
#include "penetration/sphere_capsule.h"

#include "penetration/penetration.h"

namespace gq::detail {

template <class T>
bool penetrationSphereCapsule(const SphereGeometry<T>& g0, const Transform<T>& p0, const CapsuleGeometry<T>& g1, const Transform<T>& p1,
                              Vec3<T>& direction, T& depth) {
  return sphereCapsulePenetration(g0, p0, g1, p1, direction, depth);
}

template bool penetrationSphereCapsule<float>(const SphereGeometry<float>&, const Transform<float>&, const CapsuleGeometry<float>&, const Transform<float>&,
                                             Vec3<float>&, float&);
template bool penetrationSphereCapsule<double>(const SphereGeometry<double>&, const Transform<double>&, const CapsuleGeometry<double>&, const Transform<double>&,
                                              Vec3<double>&, double&);

}  // namespace gq::detail
