// Plane/convex MTD: the plane (geom0) moves back along -n by the depth of the deepest hull vertex.
#include "gq/cooking.h"
#include "penetration/penetration.h"
#include "shapes/plane.h"

namespace gq::detail {

template <class T>
bool penetrationPlaneConvex(const PlaneGeometry<T>& g0, const Transform<T>& p0, const ConvexMeshGeometry<T>& g1, const Transform<T>& p1,
                            Vec3<T>& direction, T& depth) {
  (void)g0;
  const Vec3<T> n = planeNormal(p0);
  const Mat3<T> s = g1.scale.toMatrix();
  T lowest = std::numeric_limits<T>::max();
  for (const Vec3<T>& v : g1.mesh->vertices) lowest = std::min(lowest, n.dot(p1.transform(s * v) - p0.p));
  if (!(lowest <= T(0))) return false;
  direction = -n;
  depth = -lowest;
  return true;
}

template bool penetrationPlaneConvex<float>(const PlaneGeometry<float>&, const Transform<float>&, const ConvexMeshGeometry<float>&, const Transform<float>&,
                                           Vec3<float>&, float&);
template bool penetrationPlaneConvex<double>(const PlaneGeometry<double>&, const Transform<double>&, const ConvexMeshGeometry<double>&, const Transform<double>&,
                                            Vec3<double>&, double&);

}  // namespace gq::detail
