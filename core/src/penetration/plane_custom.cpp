// Plane/custom MTD: the plane (geom0) moves back along -n by the depth of the custom shape's support point.
#include "gq/custom.h"
#include "shapes/plane.h"
#include "penetration/penetration.h"

namespace gq::detail {

template <class T>
bool penetrationPlaneCustom(const PlaneGeometry<T>&, const Transform<T>& p0, const CustomGeometry<T>& g1, const Transform<T>& p1,
                            Vec3<T>& direction, T& depth) {
  const Vec3<T> n = planeNormal(p0);
  const Vec3<T> lowest = p1.transform(g1.callbacks->support(p1.rotateInv(Vec3<T>(-n))));
  const T height = n.dot(lowest - p0.p);
  if (!(height <= T(0))) return false;
  direction = -n;
  depth = -height;
  return true;
}

template bool penetrationPlaneCustom<float>(const PlaneGeometry<float>&, const Transform<float>&, const CustomGeometry<float>&, const Transform<float>&,
                                            Vec3<float>&, float&);
template bool penetrationPlaneCustom<double>(const PlaneGeometry<double>&, const Transform<double>&, const CustomGeometry<double>&, const Transform<double>&,
                                             Vec3<double>&, double&);

}  // namespace gq::detail
