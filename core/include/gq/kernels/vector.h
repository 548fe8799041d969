#pragma once
// d / |d| for differences and cross products whose length may lie at the ends of the floating-point range.
// d / sqrt(|d|^2) is wrong there: a float offset of ~1e-20 has a subnormal square that keeps a few bits (a normal
// 2% long, then 10% short, were found by fuzz_pair_queries), and |d|^2 overflows above sqrt(max). Those cases are
// rescaled by the largest component first; the common case costs two comparisons more than d / |d|.
#include <cmath>
#include <limits>

#include "gq/transform.h"

namespace gq::kernels {

// True and `unit` = d / |d| when d is non-zero and finite; false (unit untouched) otherwise.
template <class T> inline bool tryUnit(const Vec3<T>& d, Vec3<T>& unit) {
  const T len2 = d.squaredNorm();
  if (len2 >= std::numeric_limits<T>::min() && len2 <= std::numeric_limits<T>::max()) {
    unit = d / std::sqrt(len2);
    return true;
  }
  const T scale = d.cwiseAbs().maxCoeff();
  if (!(scale > T(0)) || !std::isfinite(scale)) return false;
  const Vec3<T> scaled = d / scale;
  unit = scaled / scaled.norm();
  return true;
}

// |d| where |d|^2 may over- or underflow (then by the largest component first); 0, inf or NaN as d has them.
template <class T> inline T rangeSafeNorm(const Vec3<T>& d) {
  const T len2 = d.squaredNorm();
  if (len2 >= std::numeric_limits<T>::min() && len2 <= std::numeric_limits<T>::max()) return std::sqrt(len2);
  const T scale = d.cwiseAbs().maxCoeff();
  if (!(scale > T(0)) || !std::isfinite(scale)) return scale;
  return scale * (d / scale).norm();
}

// |d| <= r: the squares compared while r^2 is in T's normal range, rangeSafeNorm(d) <= r where it is not (a radius
// whose square under- or overflows: |d|^2 would then round with it, 0 <= 0 for spheres 1e20 radii apart).
template <class T> inline bool normWithin(const Vec3<T>& d, T r) {
  const T rr = r * r;
  if (rr >= std::numeric_limits<T>::min() && rr <= std::numeric_limits<T>::max()) [[likely]]
    return d.squaredNorm() <= rr;
  return rangeSafeNorm(d) <= r;
}

// |d| given len2 = |d|^2: its square root, or rangeSafeNorm(d) where len2 over- or underflowed.
template <class T> inline T normFromSquared(const Vec3<T>& d, T len2) {
  if (len2 >= std::numeric_limits<T>::min() && len2 <= std::numeric_limits<T>::max()) [[likely]]
    return std::sqrt(len2);
  return rangeSafeNorm(d);
}

// d / |d|, or `fallback` for d = 0 (or non-finite d).
template <class T> inline Vec3<T> unitOr(const Vec3<T>& d, const Vec3<T>& fallback) {
  Vec3<T> unit;
  return tryUnit(d, unit) ? unit : fallback;
}

// A unit vector perpendicular to v: v crossed with the coordinate axis least aligned with it (well conditioned);
// +X for v = 0.
template <class T> inline Vec3<T> anyPerpendicular(const Vec3<T>& v) {
  if (!(v.squaredNorm() > T(0))) return Vec3<T>::UnitX();
  Eigen::Index i;
  v.cwiseAbs().minCoeff(&i);
  return v.cross(Vec3<T>::Unit(i)).normalized();
}

}  // namespace gq::kernels
