// Capsule vs capsule: balls at the closest points of the two segments. Intersecting segments have no
// centre-to-centre direction; the minimum translation is then along the common perpendicular d0 x d1 (the
// Minkowski difference of two segments is flat), or orthogonal to the axis when they are parallel.
#include "distance/distance.h"
#include "shapes/segment.h"

namespace gq::detail {
namespace {

template <class T> Vec3<T> intersectingAxesNormal(const Vec3<T>& d0, const Vec3<T>& d1, const Vec3<T>& towards) {
  const Vec3<T> c = d0.cross(d1);
  Vec3<T> n;
  if (!tryUnit(c, n)) n = anyPerpendicular<T>(d0.squaredNorm() > T(0) ? d0 : d1);
  return n.dot(towards) < T(0) ? Vec3<T>(-n) : n;
}

}  // namespace

template <class T>
void distanceCapsuleCapsule(const CapsuleAxis<T>& k0, const CapsuleAxis<T>& k1, DistanceResult<T>& out) {
  const Vec3<T> a0 = k0.halfHeight * k0.axis, a1 = k1.halfHeight * k1.axis;
  const SegmentClosest<T> c = closestSegmentSegment<T>(k0.centre - a0, k0.centre + a0, k1.centre - a1, k1.centre + a1);
  // The fallback normal is used only when the closest points coincide (ballsDistance's |c1 - c0| = 0).
  const bool coincide = !((c.c1 - c.c0).squaredNorm() > T(0));
  const Vec3<T> fallback = coincide ? intersectingAxesNormal<T>(k0.axis, k1.axis, k1.centre - k0.centre) : Vec3<T>(Vec3<T>::UnitX());
  ballsDistance(c.c0, k0.radius, c.c1, k1.radius, fallback, out);
}

template <class T>
void distanceCapsuleCapsule(const CapsuleGeometry<T>& g0, const Transform<T>& pose0, const CapsuleGeometry<T>& g1,
                            const Transform<T>& pose1, DistanceResult<T>& out) {
  const CapsuleAxis<T> k0{pose0.p, pose0.rotate(Vec3<T>(Vec3<T>::UnitX())), g0.halfHeight, g0.radius};
  const CapsuleAxis<T> k1{pose1.p, pose1.rotate(Vec3<T>(Vec3<T>::UnitX())), g1.halfHeight, g1.radius};
  distanceCapsuleCapsule(k0, k1, out);
}

template void distanceCapsuleCapsule<float>(const CapsuleGeometry<float>&, const Transform<float>&, const CapsuleGeometry<float>&, const Transform<float>&, DistanceResult<float>&);
template void distanceCapsuleCapsule<double>(const CapsuleGeometry<double>&, const Transform<double>&, const CapsuleGeometry<double>&, const Transform<double>&, DistanceResult<double>&);
template void distanceCapsuleCapsule<float>(const CapsuleAxis<float>&, const CapsuleAxis<float>&, DistanceResult<float>&);
template void distanceCapsuleCapsule<double>(const CapsuleAxis<double>&, const CapsuleAxis<double>&, DistanceResult<double>&);

}  // namespace gq::detail
