// Sphere/sphere MTD: depth r0 + r1 - |c0 - c1| along c0 - c1; coincident centres push along +X.
#include "common/unit_vector.h"
#include "penetration/penetration.h"

namespace gq::detail {

template <class T>
bool penetrationSphereSphere(const SphereGeometry<T>& g0, const Transform<T>& p0, const SphereGeometry<T>& g1, const Transform<T>& p1,
                             Vec3<T>& direction, T& depth) {
  const Vec3<T> d = p0.p - p1.p;
  const T len2 = d.squaredNorm(), len = normFromSquared(d, len2);
  const T pen = g0.radius + g1.radius - len;
  if (!(pen >= T(0))) return false;
  if (!tryUnitWithNorm(d, len2, len, direction)) direction = Vec3<T>::UnitX();
  depth = pen;
  return true;
}

template bool penetrationSphereSphere<float>(const SphereGeometry<float>&, const Transform<float>&, const SphereGeometry<float>&, const Transform<float>&,
                                            Vec3<float>&, float&);
template bool penetrationSphereSphere<double>(const SphereGeometry<double>&, const Transform<double>&, const SphereGeometry<double>&, const Transform<double>&,
                                             Vec3<double>&, double&);

}  // namespace gq::detail
