// MTD of a convex custom geometry with any support-mapped shape: GJK, then EPA when they overlap
// (penetration/gjk_epa.h); EPA out of iterations answers with its best upper bound under a Warning.
#include "penetration/gjk_epa.h"
#include "penetration/penetration.h"

namespace gq::detail {

template <class T>
Status penetrationCustomAny(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1,
                            bool& penetrating, Vec3<T>& direction, T& depth) {
  return penetrationGjkEpa(makeConvexShape(g0, p0), makeConvexShape(g1, p1), penetrating, direction, depth);
}

template Status penetrationCustomAny<float>(const Geometry<float>&, const Transform<float>&, const Geometry<float>&, const Transform<float>&,
                                            bool&, Vec3<float>&, float&);
template Status penetrationCustomAny<double>(const Geometry<double>&, const Transform<double>&, const Geometry<double>&, const Transform<double>&,
                                             bool&, Vec3<double>&, double&);

}  // namespace gq::detail
