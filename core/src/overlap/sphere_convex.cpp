// Sphere/convex overlap: GJK, with the exact point-to-hull distance within the band of touching.
#include "overlap/overlap.h"
#include "overlap/polytope.h"

namespace gq::detail {

template <class T>
bool overlapSphereConvex(const SphereGeometry<T>& g0, const Transform<T>& p0, const ConvexMeshGeometry<T>& g1, const Transform<T>& p1) {
  return overlapConvexShapes(Geometry<T>(g0), p0, Geometry<T>(g1), p1);
}

template bool overlapSphereConvex<float>(const SphereGeometry<float>&, const Transform<float>&, const ConvexMeshGeometry<float>&, const Transform<float>&);
template bool overlapSphereConvex<double>(const SphereGeometry<double>&, const Transform<double>&, const ConvexMeshGeometry<double>&, const Transform<double>&);

}  // namespace gq::detail
