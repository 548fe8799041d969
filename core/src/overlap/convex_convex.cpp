// Convex/convex overlap: the hulls' cooked balls when they decide, else GJK, with exact SAT (face normals and
// crossing edge pairs) within the band of touching. hullBallsCertificate is the one ball prefilter of hull pairs:
// the FCL adapter's Convex entry runs it too (on FCL's matrices), so both decide a pair the same way, and so do the
// sphere, capsule and box pairs with a hull (sphere_convex.cpp, capsule_convex.cpp, box_convex.cpp).
#include <algorithm>

#include "overlap/overlap.h"
#include "overlap/polytope.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers

// Scale R diag(s) R^T maps a ball of radius r to an ellipsoid with semi-axes |s_k| r: it contains the ball of
// radius min |s_k| r and lies in the one of radius max |s_k| r.
template <class T> HullBalls<T> hullBalls(const ConvexMeshGeometry<T>& g, const Transform<T>& pose) {
  const ConvexMesh<T>& m = *g.mesh;
  if (g.scale.isIdentity()) return {pose.transform(m.center), m.innerRadius, m.outerRadius};
  const Vec3<T> s = g.scale.scale.cwiseAbs();
  return {pose.transform(g.scale.toMatrix() * m.center), s.minCoeff() * m.innerRadius, s.maxCoeff() * m.outerRadius};
}

// The band scales with the balls and with the centres' coordinates (their rounding, for a hull cooked far from its
// local origin).
template <class T> OverlapCertificate hullBallsCertificate(const HullBalls<T>& a, const HullBalls<T>& b) {
  const T scale = std::max({a.outer, b.outer, a.center.cwiseAbs().maxCoeff(), b.center.cwiseAbs().maxCoeff()});
  const T d = (b.center - a.center).norm(), band = kGjkOverlapBand<T> * scale;
  if (d > a.outer + b.outer + band) return OverlapCertificate::Apart;
  if (d < a.inner + b.inner - band) return OverlapCertificate::Overlapping;
  return OverlapCertificate::Unknown;  // also for a NaN centre
}

template <class T>
bool overlapConvexConvex(const ConvexMeshGeometry<T>& g0, const Transform<T>& p0, const ConvexMeshGeometry<T>& g1, const Transform<T>& p1) {
  switch (hullBallsCertificate(hullBalls(g0, p0), hullBalls(g1, p1))) {
    case OverlapCertificate::Apart: return false;
    case OverlapCertificate::Overlapping: return true;
    case OverlapCertificate::Unknown: break;
  }
  return overlapConvexShapes(Geometry<T>(g0), p0, Geometry<T>(g1), p1);
}

template HullBalls<float> hullBalls<float>(const ConvexMeshGeometry<float>&, const Transform<float>&);
template HullBalls<double> hullBalls<double>(const ConvexMeshGeometry<double>&, const Transform<double>&);
template OverlapCertificate hullBallsCertificate<float>(const HullBalls<float>&, const HullBalls<float>&);
template OverlapCertificate hullBallsCertificate<double>(const HullBalls<double>&, const HullBalls<double>&);
template bool overlapConvexConvex<float>(const ConvexMeshGeometry<float>&, const Transform<float>&, const ConvexMeshGeometry<float>&, const Transform<float>&);
template bool overlapConvexConvex<double>(const ConvexMeshGeometry<double>&, const Transform<double>&, const ConvexMeshGeometry<double>&, const Transform<double>&);

}  // namespace gq::kernels
