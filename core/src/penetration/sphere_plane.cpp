// Sphere/plane MTD: depth r - n.(c - p) along the plane normal n (half-space x <= 0 is solid).
#include "penetration/penetration.h"
#include "shapes/plane.h"

namespace gq::detail {

template <class T>
bool penetrationSpherePlane(const SphereGeometry<T>& g0, const Transform<T>& p0, const PlaneGeometry<T>& g1, const Transform<T>& p1,
                            Vec3<T>& direction, T& depth) {
  (void)g1;
  const Vec3<T> n = planeNormal(p1);
  const T pen = g0.radius - n.dot(p0.p - p1.p);
  if (!(pen >= T(0))) return false;
  direction = n;
  depth = pen;
  return true;
}

template bool penetrationSpherePlane<float>(const SphereGeometry<float>&, const Transform<float>&, const PlaneGeometry<float>&, const Transform<float>&,
                                           Vec3<float>&, float&);
template bool penetrationSpherePlane<double>(const SphereGeometry<double>&, const Transform<double>&, const PlaneGeometry<double>&, const Transform<double>&,
                                            Vec3<double>&, double&);

}  // namespace gq::detail
