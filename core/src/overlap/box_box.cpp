// Box/box overlap: SAT over the 6 + 6 face planes and the crossing edge pairs (exact; cheap at 8 vertices).
#include "overlap/overlap.h"
#include "overlap/polytope.h"

namespace gq::detail {

template <class T>
bool overlapBoxBox(const BoxGeometry<T>& g0, const Transform<T>& p0, const BoxGeometry<T>& g1, const Transform<T>& p1) {
  Polytope<T>& a = scratchPolytope<T>(0);
  Polytope<T>& b = scratchPolytope<T>(1);
  buildBoxPolytope(g0, p0, a);
  buildBoxPolytope(g1, p1, b);
  return overlapPolytopes(a, b);
}

template bool overlapBoxBox<float>(const BoxGeometry<float>&, const Transform<float>&, const BoxGeometry<float>&, const Transform<float>&);
template bool overlapBoxBox<double>(const BoxGeometry<double>&, const Transform<double>&, const BoxGeometry<double>&, const Transform<double>&);

}  // namespace gq::detail
