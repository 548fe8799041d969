// Capsule/capsule MTD: closest segment points; crossing segments push along the cross product of
// the axes (the Minkowski difference of two segments is flat, so its depth is 0 along that normal).
#include "penetration/penetration.h"
#include "shapes/segment.h"
#include "gq/tolerances.h"
#include "common/unit_vector.h"

namespace gq::detail {
namespace {

template <class T> Segment<T> capsuleSegment(const CapsuleGeometry<T>& g, const Transform<T>& pose) {
  const Vec3<T> axis = pose.rotate(Vec3<T>(g.halfHeight, T(0), T(0)));
  return {pose.p - axis, pose.p + axis};
}

// Direction when the segments touch: normal to both axes, or to the first one when they are parallel.
template <class T> Vec3<T> crossingDirection(const Transform<T>& p0, const Transform<T>& p1) {
  const Vec3<T> a0 = p0.rotate(Vec3<T>::UnitX()), a1 = p1.rotate(Vec3<T>::UnitX());
  const Vec3<T> c = a0.cross(a1);
  const T eps = T(tol::Rel<T>::kEpsilon);
  return c.squaredNorm() > eps * eps ? Vec3<T>(c.normalized()) : anyPerpendicular(a0);
}

}  // namespace

template <class T>
bool penetrationCapsuleCapsule(const CapsuleGeometry<T>& g0, const Transform<T>& p0, const CapsuleGeometry<T>& g1, const Transform<T>& p1,
                               Vec3<T>& direction, T& depth) {
  const Segment<T> s0 = capsuleSegment(g0, p0), s1 = capsuleSegment(g1, p1);
  const SegmentClosest<T> cp = closestSegmentSegment(s0.a, s0.b, s1.a, s1.b);
  const Vec3<T> d = cp.c0 - cp.c1;
  const T len2 = d.squaredNorm(), len = std::sqrt(len2);
  const T pen = g0.radius + g1.radius - len;
  if (!(pen >= T(0))) return false;
  if (!tryUnitWithNorm(d, len2, len, direction)) direction = crossingDirection(p0, p1);
  depth = pen;
  return true;
}

template bool penetrationCapsuleCapsule<float>(const CapsuleGeometry<float>&, const Transform<float>&, const CapsuleGeometry<float>&, const Transform<float>&,
                                              Vec3<float>&, float&);
template bool penetrationCapsuleCapsule<double>(const CapsuleGeometry<double>&, const Transform<double>&, const CapsuleGeometry<double>&, const Transform<double>&,
                                               Vec3<double>&, double&);

}  // namespace gq::detail
