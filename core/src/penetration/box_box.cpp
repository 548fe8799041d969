// Box/box MTD: exact SAT, minimum overlap over the 3 + 3 face axes and 9 edge cross products.
#include "penetration/penetration.h"
#include "overlap/polytope.h"

namespace gq::detail {

template <class T>
bool penetrationBoxBox(const BoxGeometry<T>& g0, const Transform<T>& p0, const BoxGeometry<T>& g1, const Transform<T>& p1,
                       Vec3<T>& direction, T& depth) {
  return penetrationPolytopes(makeBoxPolytope(g0, p0), makeBoxPolytope(g1, p1), direction, depth);
}

template bool penetrationBoxBox<float>(const BoxGeometry<float>&, const Transform<float>&, const BoxGeometry<float>&, const Transform<float>&,
                                      Vec3<float>&, float&);
template bool penetrationBoxBox<double>(const BoxGeometry<double>&, const Transform<double>&, const BoxGeometry<double>&, const Transform<double>&,
                                       Vec3<double>&, double&);

}  // namespace gq::detail
