// Box/box MTD: the smallest normalised projection overlap over the 15 separating axes (overlap/box_box_sat.h),
// exact; face axes win ties. Box 0 moves against the centre gap: direction = -sign(t.L) L / |L|.
#include "overlap/box_box_sat.h"
#include "penetration/penetration.h"

namespace gq::detail {

template <class T>
bool penetrationBoxBox(const BoxGeometry<T>& g0, const Transform<T>& p0, const BoxGeometry<T>& g1, const Transform<T>& p1,
                       Vec3<T>& direction, T& depth) {
  T best;
  Vec3<T> towardsBox1;
  if (!leastOverlapAxis(boxPair(g0, p0, g1, p1), best, towardsBox1)) return false;
  direction = p0.rotate(Vec3<T>(-towardsBox1));
  depth = best;
  return true;
}

template bool penetrationBoxBox<float>(const BoxGeometry<float>&, const Transform<float>&, const BoxGeometry<float>&, const Transform<float>&,
                             Vec3<float>&, float&);
template bool penetrationBoxBox<double>(const BoxGeometry<double>&, const Transform<double>&, const BoxGeometry<double>&, const Transform<double>&,
                              Vec3<double>&, double&);

}  // namespace gq::detail
