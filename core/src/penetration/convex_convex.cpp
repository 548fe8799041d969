// Convex/convex MTD: the exact SAT over the facets of the Minkowski difference, the axes a certificate proves irrelevant
// skipped: by branch and bound over the hulls' Gauss-map trees in geom0's frame (penetration/hull_pair_mtd.h), else
// (a hull scaled non-uniformly, non-manifold input) over the posed hulls (penetration/polytope_mtd.h).
#include "penetration/penetration.h"
#include "penetration/hull_pair_mtd.h"
#include "penetration/polytope_mtd.h"

namespace gq::detail {

template <class T>
bool penetrationConvexConvex(const ConvexMeshGeometry<T>& g0, const Transform<T>& p0, const ConvexMeshGeometry<T>& g1, const Transform<T>& p1,
                             Vec3<T>& direction, T& depth) {
  bool penetrating = false;
  if (penetrationHullPairInFrame(g0, p0, g1, p1, penetrating, direction, depth)) return penetrating;
  Polytope<T>& a = scratchPolytope<T>(0);
  Polytope<T>& b = scratchPolytope<T>(1);
  buildConvexPolytope(g0, p0, a);
  buildConvexPolytope(g1, p1, b);
  return penetrationPolytopesCertified(a, hullInnerEllipsoid(g0, p0, a), b, hullInnerEllipsoid(g1, p1, b), direction, depth);
}

template bool penetrationConvexConvex<float>(const ConvexMeshGeometry<float>&, const Transform<float>&, const ConvexMeshGeometry<float>&, const Transform<float>&,
                                   Vec3<float>&, float&);
template bool penetrationConvexConvex<double>(const ConvexMeshGeometry<double>&, const Transform<double>&, const ConvexMeshGeometry<double>&, const Transform<double>&,
                                    Vec3<double>&, double&);

}  // namespace gq::detail
