// Closest points between segments (the clamped least-squares solution of |s0(s) - s1(t)|^2).
#include "overlap/closest_points.h"

#include <algorithm>

namespace gq::detail {

template <class T> T closestParameterOnSegment(const Segment<T>& s, const Vec3<T>& p) {
  const Vec3<T> d = s.b - s.a;
  const T dd = d.squaredNorm();
  if (!(dd > T(0))) return T(0);
  return std::clamp((p - s.a).dot(d) / dd, T(0), T(1));
}

template <class T> Vec3<T> closestPointOnSegment(const Segment<T>& s, const Vec3<T>& p) {
  return s.a + (s.b - s.a) * closestParameterOnSegment(s, p);
}

// Minimise |a0 + s d0 - a1 - t d1|^2 over [0,1]^2: take the unconstrained line-line solution, clamp s, re-solve t
// for that s, clamp t, then re-solve s for the clamped t (the standard procedure for convex quadratics on a box).
// The line-line parameter is s = (a1 - a0).(d1 x n) / |n|^2 with n = d0 x d1, not (bf - ce) / (ae - b^2): the
// Gram determinant ae - b^2 = |n|^2 cancels catastrophically for nearly parallel segments (relative error
// eps / sin^2 of the angle instead of eps / sin), which in float moved closest points by ~1e-3 along the segments.
template <class T> SegmentPair<T> closestPointsSegmentSegment(const Segment<T>& s0, const Segment<T>& s1) {
  const Vec3<T> d0 = s0.b - s0.a, d1 = s1.b - s1.a, r = s0.a - s1.a;
  const T a = d0.squaredNorm(), e = d1.squaredNorm(), f = d1.dot(r);
  T s = T(0), t = T(0);
  if (!(a > T(0)) && !(e > T(0))) return {s0.a, s1.a};
  if (!(a > T(0))) {
    t = std::clamp(f / e, T(0), T(1));
  } else {
    const T c = d0.dot(r);
    if (!(e > T(0))) {
      s = std::clamp(-c / a, T(0), T(1));
    } else {
      const T b = d0.dot(d1);
      const Vec3<T> n = d0.cross(d1);
      const T nn = n.squaredNorm();  // = ae - b^2, zero for parallel segments
      s = nn > T(0) ? std::clamp(-r.dot(d1.cross(n)) / nn, T(0), T(1)) : T(0);
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
  return {s0.a + d0 * s, s1.a + d1 * t};
}

template <class T> Vec3<T> anyPerpendicular(const Vec3<T>& v) {
  if (!(v.squaredNorm() > T(0))) return Vec3<T>::UnitY();
  // Cross with the coordinate axis least aligned with v: well conditioned.
  Vec3<T> axis = Vec3<T>::Zero();
  Eigen::Index i;
  v.cwiseAbs().minCoeff(&i);
  axis[i] = T(1);
  return v.cross(axis).normalized();
}

template float closestParameterOnSegment<float>(const Segment<float>&, const Vec3<float>&);
template double closestParameterOnSegment<double>(const Segment<double>&, const Vec3<double>&);
template Vec3<float> closestPointOnSegment<float>(const Segment<float>&, const Vec3<float>&);
template Vec3<double> closestPointOnSegment<double>(const Segment<double>&, const Vec3<double>&);
template SegmentPair<float> closestPointsSegmentSegment<float>(const Segment<float>&, const Segment<float>&);
template SegmentPair<double> closestPointsSegmentSegment<double>(const Segment<double>&, const Segment<double>&);
template Vec3<float> anyPerpendicular<float>(const Vec3<float>&);
template Vec3<double> anyPerpendicular<double>(const Vec3<double>&);

}  // namespace gq::detail
