// Box/box overlap: SAT over the 3 + 3 face axes and the 9 edge cross products.
#include "overlap/overlap.h"
#include "overlap/polytope.h"

namespace gq::detail {

template <class T>
bool overlapBoxBox(const BoxGeometry<T>& g0, const Transform<T>& p0, const BoxGeometry<T>& g1, const Transform<T>& p1) {
  return overlapPolytopes(makeBoxPolytope(g0, p0), makeBoxPolytope(g1, p1));
}

template bool overlapBoxBox<float>(const BoxGeometry<float>&, const Transform<float>&, const BoxGeometry<float>&, const Transform<float>&);
template bool overlapBoxBox<double>(const BoxGeometry<double>&, const Transform<double>&, const BoxGeometry<double>&, const Transform<double>&);

}  // namespace gq::detail
