// Convex/convex overlap: SAT over the face normals of both and all edge cross products.
#include "overlap/overlap.h"
#include "overlap/polytope.h"

namespace gq::detail {

template <class T>
bool overlapConvexConvex(const ConvexMeshGeometry<T>& g0, const Transform<T>& p0, const ConvexMeshGeometry<T>& g1, const Transform<T>& p1) {
  return overlapPolytopes(makeConvexPolytope(g0, p0), makeConvexPolytope(g1, p1));
}

template bool overlapConvexConvex<float>(const ConvexMeshGeometry<float>&, const Transform<float>&, const ConvexMeshGeometry<float>&, const Transform<float>&);
template bool overlapConvexConvex<double>(const ConvexMeshGeometry<double>&, const Transform<double>&, const ConvexMeshGeometry<double>&, const Transform<double>&);

}  // namespace gq::detail
