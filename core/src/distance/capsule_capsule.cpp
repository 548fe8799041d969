// Capsule vs capsule: balls at the closest points of the two segments. Intersecting segments have no
// centre-to-centre direction; the minimum translation is then along the common perpendicular d0 x d1 (the
// Minkowski difference of two segments is flat), or orthogonal to the axis when they are parallel.
#include "distance/distance.h"

namespace gq::detail {
namespace {

template <class T> Vec3<T> intersectingAxesNormal(const Vec3<T>& d0, const Vec3<T>& d1, const Vec3<T>& towards) {
  const Vec3<T> c = d0.cross(d1);
  Vec3<T> n = c.squaredNorm() > T(0) ? Vec3<T>(c.normalized()) : anyOrthogonal<T>(d0.squaredNorm() > T(0) ? d0 : d1);
  return n.dot(towards) < T(0) ? Vec3<T>(-n) : n;
}

}  // namespace

template <class T>
void distanceCapsuleCapsule(const CapsuleGeometry<T>& g0, const Transform<T>& pose0, const CapsuleGeometry<T>& g1,
                            const Transform<T>& pose1, DistanceResult<T>& out) {
  const Vec3<T> a0 = pose0.rotate(Vec3<T>(g0.halfHeight, T(0), T(0)));
  const Vec3<T> a1 = pose1.rotate(Vec3<T>(g1.halfHeight, T(0), T(0)));
  const SegmentClosest<T> c = closestSegmentSegment<T>(pose0.p - a0, pose0.p + a0, pose1.p - a1, pose1.p + a1);
  const Vec3<T> fallback = intersectingAxesNormal<T>(pose0.rotate(Vec3<T>(Vec3<T>::UnitX())),
                                                     pose1.rotate(Vec3<T>(Vec3<T>::UnitX())), pose1.p - pose0.p);
  ballsDistance(c.c0, g0.radius, c.c1, g1.radius, fallback, out);
}

template void distanceCapsuleCapsule<float>(const CapsuleGeometry<float>&, const Transform<float>&, const CapsuleGeometry<float>&, const Transform<float>&, DistanceResult<float>&);
template void distanceCapsuleCapsule<double>(const CapsuleGeometry<double>&, const Transform<double>&, const CapsuleGeometry<double>&, const Transform<double>&, DistanceResult<double>&);

}  // namespace gq::detail
