// Overlap of a convex custom geometry with any shape that has a support mapping (sphere, capsule, box, convex,
// custom): GJK on the support mappings (gjk/gjk.h), margins included; touching counts as overlapping.
#include "gjk/gjk.h"
#include "overlap/overlap.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers

template <class T>
bool overlapCustomAny(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1) {
  return gjkOverlap(makeConvexShape(g0, p0), makeConvexShape(g1, p1));
}

template bool overlapCustomAny<float>(const Geometry<float>&, const Transform<float>&, const Geometry<float>&, const Transform<float>&);
template bool overlapCustomAny<double>(const Geometry<double>&, const Transform<double>&, const Geometry<double>&, const Transform<double>&);

}  // namespace gq::kernels
