#pragma once
// Closest point on a segment, used by capsule kernels.
#include "gq/math.h"

namespace gq::detail {

// Parameter s in [0, 1] of the point of segment a + s * (b - a) closest to p.
template <class T> T closestParameterOnSegment(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& p) {
  const Vec3<T> ab = b - a;
  const T len2 = ab.squaredNorm();
  if (!(len2 > T(0))) return T(0);
  return std::clamp((p - a).dot(ab) / len2, T(0), T(1));
}

template <class T> Vec3<T> closestPointOnSegment(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& p) {
  return a + closestParameterOnSegment(a, b, p) * (b - a);
}

// The capsule's core segment (local X axis) clamped: the closest point of it to a local point is (clamp(x), 0, 0).
template <class T> Vec3<T> closestPointOnCapsuleAxis(T halfHeight, const Vec3<T>& localPoint) {
  return Vec3<T>(std::clamp(localPoint.x(), -halfHeight, halfHeight), T(0), T(0));
}

}  // namespace gq::detail
