// Capsule/capsule overlap: segment-segment distance <= r0 + r1.
#include "overlap/overlap.h"
#include "overlap/closest_points.h"

namespace gq::detail {
namespace {

template <class T> Segment<T> capsuleSegment(const CapsuleGeometry<T>& g, const Transform<T>& pose) {
  const Vec3<T> axis = pose.rotate(Vec3<T>(g.halfHeight, T(0), T(0)));
  return {pose.p - axis, pose.p + axis};
}

}  // namespace

template <class T>
bool overlapCapsuleCapsule(const CapsuleGeometry<T>& g0, const Transform<T>& p0, const CapsuleGeometry<T>& g1, const Transform<T>& p1) {
  const SegmentPair<T> cp = closestPointsSegmentSegment(capsuleSegment(g0, p0), capsuleSegment(g1, p1));
  const T r = g0.radius + g1.radius;
  return (cp.p0 - cp.p1).squaredNorm() <= r * r;
}

template bool overlapCapsuleCapsule<float>(const CapsuleGeometry<float>&, const Transform<float>&, const CapsuleGeometry<float>&, const Transform<float>&);
template bool overlapCapsuleCapsule<double>(const CapsuleGeometry<double>&, const Transform<double>&, const CapsuleGeometry<double>&, const Transform<double>&);

}  // namespace gq::detail
