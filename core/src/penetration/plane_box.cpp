// Plane/box MTD: the plane (geom0) moves back along -n by the depth of the box support point.
#include "penetration/penetration.h"
#include "shapes/plane.h"

namespace gq::detail {

template <class T>
bool penetrationPlaneBox(const PlaneGeometry<T>& g0, const Transform<T>& p0, const BoxGeometry<T>& g1, const Transform<T>& p1,
                         Vec3<T>& direction, T& depth) {
  (void)g0;
  const Vec3<T> n = planeNormal(p0);
  const T reach = p1.rotateInv(n).cwiseAbs().dot(g1.halfExtents);
  const T pen = reach - n.dot(p1.p - p0.p);
  if (!(pen >= T(0))) return false;
  direction = -n;
  depth = pen;
  return true;
}

template bool penetrationPlaneBox<float>(const PlaneGeometry<float>&, const Transform<float>&, const BoxGeometry<float>&, const Transform<float>&,
                                        Vec3<float>&, float&);
template bool penetrationPlaneBox<double>(const PlaneGeometry<double>&, const Transform<double>&, const BoxGeometry<double>&, const Transform<double>&,
                                         Vec3<double>&, double&);

}  // namespace gq::detail
