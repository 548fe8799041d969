// Box/convex overlap: SAT over the face normals of both and all edge cross products.
#include "overlap/overlap.h"
#include "overlap/polytope.h"

namespace gq::detail {

template <class T>
bool overlapBoxConvex(const BoxGeometry<T>& g0, const Transform<T>& p0, const ConvexMeshGeometry<T>& g1, const Transform<T>& p1) {
  return overlapPolytopes(makeBoxPolytope(g0, p0), makeConvexPolytope(g1, p1));
}

template bool overlapBoxConvex<float>(const BoxGeometry<float>&, const Transform<float>&, const ConvexMeshGeometry<float>&, const Transform<float>&);
template bool overlapBoxConvex<double>(const BoxGeometry<double>&, const Transform<double>&, const ConvexMeshGeometry<double>&, const Transform<double>&);

}  // namespace gq::detail
