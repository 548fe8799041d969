#pragma once
// Hulls scaled flat or thin past T's precision: MeshScale factors spanning more than 1/eps (a cube scaled
// (0.125, 1e-266, 7.9) is a sheet, (9e-36, 3e-12, 7.6) a needle). Their face normals S^-1 n are decided by the
// rounding of the scale's rotation rather than by the shape, so SAT and the closest-point search over their faces
// can use a face that is not there (a sphere centred on such a sheet was pushed out through its rim, 1.94 deep for
// 2.06; a sphere 4.5 beside such a needle was 2.0 deep). Their support points S v are exact: GJK and EPA answer
// them, as distance does.
#include <limits>

#include "penetration/gjk_epa.h"

namespace gq::detail {

template <class T> bool scaledPastPrecision(const MeshScale<T>& scale) {
  const Vec3<T> s = scale.scale.cwiseAbs();
  return !(s.maxCoeff() * std::numeric_limits<T>::epsilon() <= s.minCoeff());
}

// The MTD by GJK and EPA (geom0 separates along -normal) into `penetrating`. GJK's separating axis is a proof at any
// resolution. Overlapping is trusted only when GJK's resolution for the pair (gjkTolerance, relative to the pair's
// size) is fine against the round shape's radius: false, untouched, when it is not (a float sheet 7e8 wide resolves
// to ~1e3, which calls a sphere 1.6 off it touching; SAT answers those). (A sphere 2e39 from a 1e-266 sheet failed
// that test by the pair's size and went to SAT, whose face normals claimed a depth of 1: found by fuzzing.) EPA out
// of iterations still reports an upper bound that separates.
template <class T, class G0>
bool penetrationBySupport(const G0& g0, const Transform<T>& p0, const ConvexMeshGeometry<T>& g1, const Transform<T>& p1,
                          bool& penetrating, Vec3<T>& direction, T& depth) {
  const Geometry<T> a(g0), b(g1);  // the shapes below point into these
  const ConvexShape<T> sa = makeConvexShape(a, p0), sb = makeConvexShape(b, p1);
  if (!gjkOverlap(sa, sb)) return penetrating = false, true;
  if (!(gjkTolerance(sa, sb) <= T(1e-3) * g0.radius)) return false;
  penetrating = true;
  (void)mtdByEpa(sa, sb, direction, depth);  // its status: see above
  return true;
}

}  // namespace gq::detail
