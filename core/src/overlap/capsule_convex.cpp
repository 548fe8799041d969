// Capsule/convex overlap: the shapes' balls when they decide, else GJK, with the exact segment-hull test (SAT, then
// distance <= r) within the band of touching.
#include "overlap/overlap.h"
#include "overlap/polytope.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers

template <class T>
bool overlapCapsuleConvex(const CapsuleGeometry<T>& g0, const Transform<T>& p0, const ConvexMeshGeometry<T>& g1, const Transform<T>& p1) {
  switch (hullBallsCertificate(hullBalls(g0, p0), hullBalls(g1, p1))) {  // as hull pairs (convex_convex.cpp)
    case OverlapCertificate::Apart: return false;
    case OverlapCertificate::Overlapping: return true;
    case OverlapCertificate::Unknown: break;
  }
  return overlapConvexShapes(Geometry<T>(g0), p0, Geometry<T>(g1), p1);
}

template bool overlapCapsuleConvex<float>(const CapsuleGeometry<float>&, const Transform<float>&, const ConvexMeshGeometry<float>&, const Transform<float>&);
template bool overlapCapsuleConvex<double>(const CapsuleGeometry<double>&, const Transform<double>&, const ConvexMeshGeometry<double>&, const Transform<double>&);

}  // namespace gq::kernels
