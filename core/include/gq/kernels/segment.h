#pragma once
// Closest points on segments, written once: the exact kernels behind the sphere/capsule pairs, the rounded cores of
// the polytope tests, box-box touch points and the segment-triangle tests. Either segment may have zero length.
#include <algorithm>
#include <limits>

#include "gq/math.h"

namespace gq::kernels {

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

// The same for segments given by centre and half axis, c + u a with u in [-1, 1] (capsule cores), without forming
// endpoints: with w = c1 - c0, minimise |u a0 - v a1 - w|^2, whose normal equations are a u - b v = c and
// b u - e v = f (a = a0.a0, b = a0.a1, e = a1.a1, c = a0.w, f = a1.w); the line-line u = w.(a1 x n) / |n|^2 with
// n = a0 x a1, for the reason above. Parallel segments: u = 0 (the first centre) before the clamping.
// The parameters are products with reciprocals taken as soon as a, e and |n|^2 are known, so no division waits on
// a numerator (each sat on the kernel's dependency chain: capsule-capsule distance's time is mostly that chain). A
// half axis with |a|^2 below the smallest normal number counts as a point, and |n|^2 below it as parallel (their
// reciprocals would overflow); either moves the closest points by less than sqrt of that number (1e-154 in double,
// 1e-19 in float). The clamps are by value (std::clamp's reference made GCC select spilled constants in memory).
template <class T>
[[gnu::always_inline]] inline SegmentClosest<T> closestCentredSegments(const Vec3<T>& c0, const Vec3<T>& a0,
                                                                       const Vec3<T>& c1, const Vec3<T>& a1) {
  constexpr T kTiny = std::numeric_limits<T>::min();
  const auto clampUnit = [](T x) { return x < T(-1) ? T(-1) : (x > T(1) ? T(1) : x); };
  const T wx = c1.x() - c0.x(), wy = c1.y() - c0.y(), wz = c1.z() - c0.z();
  const T a = a0.squaredNorm(), e = a1.squaredNorm(), f = a1.x() * wx + a1.y() * wy + a1.z() * wz;
  T u = T(0), v = T(0);
  if (!(a >= kTiny) && !(e >= kTiny)) return {c0, c1};
  if (!(a >= kTiny)) {
    v = clampUnit(-f / e);
  } else {
    const T c = a0.x() * wx + a0.y() * wy + a0.z() * wz, ia = T(1) / a;
    if (!(e >= kTiny)) {
      u = clampUnit(c * ia);
    } else {
      const T b = a0.dot(a1), ie = T(1) / e;
      // n = a0 x a1 and m = a1 x n in scalars (see closestSegmentSegment).
      const T nx = a0.y() * a1.z() - a0.z() * a1.y(), ny = a0.z() * a1.x() - a0.x() * a1.z(),
              nz = a0.x() * a1.y() - a0.y() * a1.x();
      const T nn = nx * nx + ny * ny + nz * nz;
      const T mx = a1.y() * nz - a1.z() * ny, my = a1.z() * nx - a1.x() * nz, mz = a1.x() * ny - a1.y() * nx;
      u = nn >= kTiny ? clampUnit((wx * mx + wy * my + wz * mz) * (T(1) / nn)) : T(0);
      v = (b * u - f) * ie;
      if (v < T(-1)) {
        v = T(-1);
        u = clampUnit((c - b) * ia);
      } else if (v > T(1)) {
        v = T(1);
        u = clampUnit((c + b) * ia);
      }
    }
  }
  return {Vec3<T>(c0.x() + u * a0.x(), c0.y() + u * a0.y(), c0.z() + u * a0.z()),
          Vec3<T>(c1.x() + v * a1.x(), c1.y() + v * a1.y(), c1.z() + v * a1.z())};
}

}  // namespace gq::kernels
