#pragma once
// Sphere/capsule overlap, inline: the façade's cell (dispatch/overlap.cpp) runs it without a call or the poses'
// copies, and the public kernels (sphere_capsule.cpp) are this code.
#include "common/rotated_axis.h"
#include "common/unit_vector.h"
#include "gq/geometry.h"
#include "shapes/segment.h"

namespace gq::detail {

// Distance from the centre c0 to the capsule segment [c1 - a1, c1 + a1] <= r0 + r1.
template <class T>
[[gnu::always_inline]] inline bool sphereCapsuleOverlaps(const Vec3<T>& c0, T r0, const Vec3<T>& c1, const Vec3<T>& a1,
                                                         T r1) {
  const Vec3<T> q = closestPointOnSegment(Vec3<T>(c1 - a1), Vec3<T>(c1 + a1), c0);
  return normWithin(Vec3<T>(c0 - q), r0 + r1);
}

// The capsule's half axis is its rotation's X column times the half height (rotatedX).
template <class T>
[[gnu::always_inline]] inline bool sphereCapsuleOverlaps(const SphereGeometry<T>& g0, const Transform<T>& p0,
                                                         const CapsuleGeometry<T>& g1, const Transform<T>& p1) {
  return sphereCapsuleOverlaps<T>(p0.p, g0.radius, p1.p, rotatedX(p1.q, g1.halfHeight), g1.radius);
}

}  // namespace gq::detail
