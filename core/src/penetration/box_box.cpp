// Box/box MTD: exact SAT, minimum push-out over the 6 + 6 face planes and the crossing edge pairs.
#include "penetration/penetration.h"
#include "overlap/polytope.h"

namespace gq::detail {

template <class T>
bool penetrationBoxBox(const BoxGeometry<T>& g0, const Transform<T>& p0, const BoxGeometry<T>& g1, const Transform<T>& p1,
                       Vec3<T>& direction, T& depth) {
  Polytope<T>& a = scratchPolytope<T>(0);
  Polytope<T>& b = scratchPolytope<T>(1);
  buildBoxPolytope(g0, p0, a);
  buildBoxPolytope(g1, p1, b);
  return penetrationPolytopes(a, b, direction, depth);
}

template bool penetrationBoxBox<float>(const BoxGeometry<float>&, const Transform<float>&, const BoxGeometry<float>&, const Transform<float>&,
                             Vec3<float>&, float&);
template bool penetrationBoxBox<double>(const BoxGeometry<double>&, const Transform<double>&, const BoxGeometry<double>&, const Transform<double>&,
                              Vec3<double>&, double&);

}  // namespace gq::detail
