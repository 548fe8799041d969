// Plane/capsule MTD: the plane (geom0) moves back along -n until the lower capsule end clears it.
#include "penetration/penetration.h"
#include "shapes/plane.h"

namespace gq::detail {

template <class T>
bool penetrationPlaneCapsule(const PlaneGeometry<T>& g0, const Transform<T>& p0, const CapsuleGeometry<T>& g1, const Transform<T>& p1,
                             Vec3<T>& direction, T& depth) {
  (void)g0;
  const Vec3<T> n = planeNormal(p0);
  const T reach = std::abs(n.dot(p1.rotate(Vec3<T>::UnitX()))) * g1.halfHeight;
  const T pen = g1.radius + reach - n.dot(p1.p - p0.p);
  if (!(pen >= T(0))) return false;
  direction = -n;
  depth = pen;
  return true;
}

template bool penetrationPlaneCapsule<float>(const PlaneGeometry<float>&, const Transform<float>&, const CapsuleGeometry<float>&, const Transform<float>&,
                                            Vec3<float>&, float&);
template bool penetrationPlaneCapsule<double>(const PlaneGeometry<double>&, const Transform<double>&, const CapsuleGeometry<double>&, const Transform<double>&,
                                             Vec3<double>&, double&);

}  // namespace gq::detail
