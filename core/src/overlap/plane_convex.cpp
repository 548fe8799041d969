// Plane/convex overlap: some hull vertex lies in the half-space x <= 0.
#include "overlap/overlap.h"
#include "shapes/plane.h"
#include "overlap/polytope.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers

template <class T>
bool overlapPlaneConvex(const PlaneGeometry<T>& g0, const Transform<T>& p0, const ConvexMeshGeometry<T>& g1, const Transform<T>& p1) {
  (void)g0;
  const Vec3<T> n = planeNormal(p0);
  const Mat3<T> s = g1.scale.toMatrix();
  for (const Vec3<T>& v : g1.mesh->vertices)
    if (n.dot(p1.transform(s * v) - p0.p) <= T(0)) return true;
  return false;
}

template bool overlapPlaneConvex<float>(const PlaneGeometry<float>&, const Transform<float>&, const ConvexMeshGeometry<float>&, const Transform<float>&);
template bool overlapPlaneConvex<double>(const PlaneGeometry<double>&, const Transform<double>&, const ConvexMeshGeometry<double>&, const Transform<double>&);

}  // namespace gq::kernels
