// Capsule/box MTD: exact (segment core + radius against the box: SAT when the segment enters the box,
// segment-box distance otherwise, see polytope.h).
#include "penetration/penetration.h"
#include "overlap/polytope.h"

namespace gq::detail {

template <class T>
bool penetrationCapsuleBox(const CapsuleGeometry<T>& g0, const Transform<T>& p0, const BoxGeometry<T>& g1, const Transform<T>& p1,
                           Vec3<T>& direction, T& depth) {
  Polytope<T>& poly = scratchPolytope<T>(0);
  buildBoxPolytope(g1, p1, poly);
  return penetrationRoundedPolytope(capsuleCore(g0, p0), poly, direction, depth);
}

template bool penetrationCapsuleBox<float>(const CapsuleGeometry<float>&, const Transform<float>&, const BoxGeometry<float>&, const Transform<float>&,
                                 Vec3<float>&, float&);
template bool penetrationCapsuleBox<double>(const CapsuleGeometry<double>&, const Transform<double>&, const BoxGeometry<double>&, const Transform<double>&,
                                  Vec3<double>&, double&);

}  // namespace gq::detail
