#pragma once
// Closest points on segments, written once: the exact kernels behind the sphere/capsule pairs, the rounded cores of
// the polytope tests, box-box touch points and the segment-triangle tests. Either segment may have zero length.
#include <algorithm>

#include "gq/math.h"

namespace gq::detail {

template <class T> struct Segment {
  Vec3<T> a, b;
};

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

template <class T> struct SegmentClosest {
  Vec3<T> c0, c1;  // closest point on the first and on the second segment
};

// Minimise |p0 + s d0 - p1 - t d1|^2 over [0,1]^2: take the unconstrained line-line solution, clamp s, re-solve t
// for that s, clamp t, then re-solve s for the clamped t (the standard procedure for convex quadratics on a box).
// The line-line parameter is s = (p1 - p0).(d1 x n) / |n|^2 with n = d0 x d1, not (bf - ce) / (ae - b^2): the
// Gram determinant ae - b^2 = |n|^2 cancels catastrophically for nearly parallel segments (relative error
// eps / sin^2 of the angle instead of eps / sin), which in float moved closest points by ~1e-3 along the segments.
// Parallel segments (n = 0): any s on the common range is a minimiser; s = 0 is taken before the clamping.
template <class T>
[[gnu::always_inline]] inline SegmentClosest<T> closestSegmentSegment(const Vec3<T>& p0, const Vec3<T>& q0,
                                                                      const Vec3<T>& p1, const Vec3<T>& q1) {
  const Vec3<T> d0 = q0 - p0, d1 = q1 - p1, r = p0 - p1;
  const T a = d0.squaredNorm(), e = d1.squaredNorm(), f = d1.dot(r);
  T s = T(0), t = T(0);
  if (!(a > T(0)) && !(e > T(0))) return {p0, p1};
  if (!(a > T(0))) {
    t = std::clamp(f / e, T(0), T(1));
  } else {
    const T c = d0.dot(r);
    if (!(e > T(0))) {
      s = std::clamp(-c / a, T(0), T(1));
    } else {
      const T b = d0.dot(d1);
      // n = d0 x d1 and r . (d1 x n) in scalars: Eigen's cross products were read back as packed pairs just after
      // being written one component at a time (failed store forwarding, ~25 % of capsule-capsule distance's time).
      // Written out rather than through gjk/simplex.cpp's tripleProduct on a vector n: that took capsule-capsule
      // collide ~5 % longer.
      const T nx = d0.y() * d1.z() - d0.z() * d1.y(), ny = d0.z() * d1.x() - d0.x() * d1.z(),
              nz = d0.x() * d1.y() - d0.y() * d1.x();
      const T nn = nx * nx + ny * ny + nz * nz;
      const T mx = d1.y() * nz - d1.z() * ny, my = d1.z() * nx - d1.x() * nz, mz = d1.x() * ny - d1.y() * nx;
      s = nn > T(0) ? std::clamp(-(r.x() * mx + r.y() * my + r.z() * mz) / nn, T(0), T(1)) : T(0);
      t = (b * s + f) / e;
      if (t < T(0)) {
        t = T(0);
        s = std::clamp(-c / a, T(0), T(1));
      } else if (t > T(1)) {
        t = T(1);
        s = std::clamp((b - c) / a, T(0), T(1));
      }
    }
  }
  return {p0 + d0 * s, p1 + d1 * t};
}

}  // namespace gq::detail
