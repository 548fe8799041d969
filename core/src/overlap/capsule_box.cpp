// Capsule/box overlap: the capsule's segment against the box in the box's frame (overlap/segment_box.h). A
// separating axis with a gap beyond the radius proves them apart; a segment meeting the box on every axis
// overlaps; otherwise the exact segment-box distance decides. Touching counts as overlapping.
#include "overlap/overlap.h"
#include "overlap/segment_box.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers

template <class T> bool overlapCapsuleBox(const Vec3<T>& c, const Vec3<T>& d, T r0, const Vec3<T>& h) {
  const SegmentBoxSat<T> sat = satSegmentBox(c, d, h);
  if (sat.overlap >= T(0)) return true;
  if (-sat.overlap > r0) return false;  // a separating gap bounds the distance from below
  return closestSegmentBox(c, d, h).distSq <= r0 * r0;
}

template <class T>
bool overlapCapsuleBox(const CapsuleGeometry<T>& g0, const Transform<T>& p0, const BoxGeometry<T>& g1, const Transform<T>& p1) {
  const Vec3<T> c = p1.transformInv(p0.p);
  const Vec3<T> d = p1.rotateInv(p0.rotate(Vec3<T>(g0.halfHeight, T(0), T(0))));
  return overlapCapsuleBox<T>(c, d, g0.radius, g1.halfExtents);
}

template bool overlapCapsuleBox<float>(const CapsuleGeometry<float>&, const Transform<float>&, const BoxGeometry<float>&, const Transform<float>&);
template bool overlapCapsuleBox<double>(const CapsuleGeometry<double>&, const Transform<double>&, const BoxGeometry<double>&, const Transform<double>&);
template bool overlapCapsuleBox<float>(const Vec3<float>&, const Vec3<float>&, float, const Vec3<float>&);
template bool overlapCapsuleBox<double>(const Vec3<double>&, const Vec3<double>&, double, const Vec3<double>&);

}  // namespace gq::kernels
