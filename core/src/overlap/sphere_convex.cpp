// Sphere/convex overlap: the shapes' balls when they decide, else GJK, with the exact point-to-hull distance within the
// band of touching.
#include "overlap/overlap.h"
#include "overlap/polytope.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers

template <class T>
bool overlapSphereConvex(const SphereGeometry<T>& g0, const Transform<T>& p0, const ConvexMeshGeometry<T>& g1, const Transform<T>& p1) {
  switch (hullBallsCertificate(hullBalls(g0, p0), hullBalls(g1, p1))) {  // as hull pairs (convex_convex.cpp)
    case OverlapCertificate::Apart: return false;
    case OverlapCertificate::Overlapping: return true;
    case OverlapCertificate::Unknown: break;
  }
  return overlapConvexShapes(Geometry<T>(g0), p0, Geometry<T>(g1), p1);
}

template bool overlapSphereConvex<float>(const SphereGeometry<float>&, const Transform<float>&, const ConvexMeshGeometry<float>&, const Transform<float>&);
template bool overlapSphereConvex<double>(const SphereGeometry<double>&, const Transform<double>&, const ConvexMeshGeometry<double>&, const Transform<double>&);

}  // namespace gq::kernels
