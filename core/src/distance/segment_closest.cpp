// Closest points between segments (Ericson, Real-Time Collision Detection, 5.1.9), robust for parallel and
// zero-length segments: the parameters are clamped one after the other, never divided by a vanishing quantity.
#include <cmath>

#include "distance/distance.h"
#include "gq/tolerances.h"

namespace gq::detail {
namespace {
template <class T> T clamp01(T x) { return std::min(T(1), std::max(T(0), x)); }
}  // namespace

template <class T> Vec3<T> closestOnSegment(const Vec3<T>& p, const Vec3<T>& q, const Vec3<T>& x) {
  const Vec3<T> d = q - p;
  const T dd = d.squaredNorm();
  if (!(dd > T(0))) return p;
  return p + clamp01((x - p).dot(d) / dd) * d;
}

// Minimises |(p0 + s d0) - (p1 + t d1)|^2 over [0,1]^2: the unconstrained s from the 2x2 normal equations,
// clamped, then t = best for that s, clamped, then s recomputed for the clamped t.
template <class T>
SegmentClosest<T> closestSegmentSegment(const Vec3<T>& p0, const Vec3<T>& q0, const Vec3<T>& p1, const Vec3<T>& q1) {
  const Vec3<T> d0 = q0 - p0, d1 = q1 - p1, r = p0 - p1;
  const T a = d0.squaredNorm(), e = d1.squaredNorm(), f = d1.dot(r);
  T s = T(0), t = T(0);
  if (!(a > T(0)) && !(e > T(0))) {
    // both points
  } else if (!(a > T(0))) {
    t = clamp01(f / e);
  } else {
    const T c = d0.dot(r);
    if (!(e > T(0))) {
      s = clamp01(-c / a);
    } else {
      const T b = d0.dot(d1);
      const T denom = a * e - b * b;  // = |d0 x d1|^2 >= 0; ~0 when parallel: any s works, take 0
      s = denom > T(tol::Rel<T>::kEpsilon) * a * e ? clamp01((b * f - c * e) / denom) : T(0);
      t = (b * s + f) / e;
      if (t < T(0)) {
        t = T(0);
        s = clamp01(-c / a);
      } else if (t > T(1)) {
        t = T(1);
        s = clamp01((b - c) / a);
      }
    }
  }
  return SegmentClosest<T>{p0 + s * d0, p1 + t * d1, s, t};
}

template Vec3<float> closestOnSegment<float>(const Vec3<float>&, const Vec3<float>&, const Vec3<float>&);
template Vec3<double> closestOnSegment<double>(const Vec3<double>&, const Vec3<double>&, const Vec3<double>&);
template SegmentClosest<float> closestSegmentSegment<float>(const Vec3<float>&, const Vec3<float>&, const Vec3<float>&, const Vec3<float>&);
template SegmentClosest<double> closestSegmentSegment<double>(const Vec3<double>&, const Vec3<double>&, const Vec3<double>&, const Vec3<double>&);

}  // namespace gq::detail
