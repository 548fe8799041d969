// Capsule/box overlap: exact segment-box test (SAT) then segment-box distance <= r.
#include "overlap/overlap.h"
#include "overlap/polytope.h"

namespace gq::detail {

template <class T>
bool overlapCapsuleBox(const CapsuleGeometry<T>& g0, const Transform<T>& p0, const BoxGeometry<T>& g1, const Transform<T>& p1) {
  Polytope<T>& box = scratchPolytope<T>(0);
  buildBoxPolytope(g1, p1, box);
  return overlapRoundedPolytope(capsuleCore(g0, p0), box);
}

template bool overlapCapsuleBox<float>(const CapsuleGeometry<float>&, const Transform<float>&, const BoxGeometry<float>&, const Transform<float>&);
template bool overlapCapsuleBox<double>(const CapsuleGeometry<double>&, const Transform<double>&, const BoxGeometry<double>&, const Transform<double>&);

}  // namespace gq::detail
