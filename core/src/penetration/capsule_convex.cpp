// Capsule/convex MTD, exact: the segment core plus the radius against the hull, in an unscaled hull's own frame
// (rounded_hull.h), else against the posed hull (polytope.h); hulls scaled past T's precision by GJK/EPA
// (degenerate_hull.h).
#include "penetration/penetration.h"
#include "overlap/polytope.h"
#include "penetration/degenerate_hull.h"
#include "penetration/rounded_hull.h"

namespace gq::detail {

template <class T>
bool penetrationCapsuleConvex(const CapsuleGeometry<T>& g0, const Transform<T>& p0, const ConvexMeshGeometry<T>& g1, const Transform<T>& p1,
                              Vec3<T>& direction, T& depth) {
  bool penetrating = false;
  if (scaledPastPrecision(g1.scale) && penetrationBySupport(g0, p0, g1, p1, penetrating, direction, depth))
    return penetrating;
  const RoundedCore<T> core = capsuleCore(g0, p0);
  if (penetrationRoundedHull(core, g1, p1, penetrating, direction, depth)) return penetrating;
  Polytope<T>& poly = scratchPolytope<T>(0);
  buildConvexPolytope(g1, p1, poly);
  return penetrationRoundedPolytope(core, poly, direction, depth);
}

template bool penetrationCapsuleConvex<float>(const CapsuleGeometry<float>&, const Transform<float>&, const ConvexMeshGeometry<float>&, const Transform<float>&,
                                    Vec3<float>&, float&);
template bool penetrationCapsuleConvex<double>(const CapsuleGeometry<double>&, const Transform<double>&, const ConvexMeshGeometry<double>&, const Transform<double>&,
                                     Vec3<double>&, double&);

}  // namespace gq::detail
