// Box/box overlap: the 15-axis separating-axis test (overlap/box_box_sat.h); touching counts as overlapping.
#include "overlap/box_box_sat.h"
#include "overlap/overlap.h"

namespace gq::detail {

template <class T>
bool overlapBoxBox(const BoxGeometry<T>& g0, const Transform<T>& p0, const BoxGeometry<T>& g1, const Transform<T>& p1) {
  bool separated = false;
  forEachBoxAxis(boxPair(g0, p0, g1, p1), [&](const BoxAxis<T>& axis) { return separated = axis.overlap < T(0); });
  return !separated;
}

template bool overlapBoxBox<float>(const BoxGeometry<float>&, const Transform<float>&, const BoxGeometry<float>&, const Transform<float>&);
template bool overlapBoxBox<double>(const BoxGeometry<double>&, const Transform<double>&, const BoxGeometry<double>&, const Transform<double>&);

}  // namespace gq::detail
