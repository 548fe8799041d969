#pragma once
// Sphere/capsule MTD, inline: the façade's cell (dispatch/penetration.cpp) runs it without a call or the poses'
// copies, and penetrationSphereCapsule (sphere_capsule.cpp) is this code.
// The sphere against the closest segment point; a centre on the segment pushes perpendicular to it (every
// perpendicular gives the same depth r0 + r1).
#include <cmath>

#include "common/rotated_axis.h"
#include "common/unit_vector.h"
#include "gq/geometry.h"
#include "shapes/segment.h"

namespace gq::detail {

template <class T>
[[gnu::always_inline]] inline bool sphereCapsulePenetration(const SphereGeometry<T>& g0, const Transform<T>& p0,
                                                            const CapsuleGeometry<T>& g1, const Transform<T>& p1,
                                                            Vec3<T>& direction, T& depth) {
  const Vec3<T> axis = rotatedX(p1.q, g1.halfHeight);
  const Vec3<T> q = closestPointOnSegment(Vec3<T>(p1.p - axis), Vec3<T>(p1.p + axis), p0.p);
  const Vec3<T> d = p0.p - q;
  const T len2 = d.squaredNorm(), len = normFromSquared(d, len2);
  const T pen = g0.radius + g1.radius - len;
  if (!(pen >= T(0))) return false;
  if (!tryUnitWithNorm(d, len2, len, direction)) [[unlikely]]
    direction = anyPerpendicular(p1.rotate(Vec3<T>::UnitX()));
  depth = pen;
  return true;
}

}  // namespace gq::detail
