#pragma once
// Scalar-templated math types shared by every query (Eigen underneath).
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace gq {

template <class T> using Vec3 = Eigen::Matrix<T, 3, 1>;
template <class T> using Mat3 = Eigen::Matrix<T, 3, 3>;
template <class T> using Quat = Eigen::Quaternion<T>;

template <class T> inline bool isFinite(const Vec3<T>& v) {
  return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}
template <class T> inline bool isFinite(const Quat<T>& q) { return isFinite(Vec3<T>(q.vec())) && std::isfinite(q.w()); }

// Axis-aligned bounds; an empty box has min > max.
template <class T> struct Bounds3 {
  Vec3<T> min = Vec3<T>::Constant(std::numeric_limits<T>::max());
  Vec3<T> max = Vec3<T>::Constant(-std::numeric_limits<T>::max());

  static Bounds3 fromMinMax(const Vec3<T>& lo, const Vec3<T>& hi) { return Bounds3{lo, hi}; }
  static Bounds3 fromCenterExtents(const Vec3<T>& c, const Vec3<T>& e) { return Bounds3{c - e, c + e}; }
  bool isEmpty() const { return (min.array() > max.array()).any(); }
  void include(const Vec3<T>& p) { min = min.cwiseMin(p); max = max.cwiseMax(p); }
  void include(const Bounds3& b) { min = min.cwiseMin(b.min); max = max.cwiseMax(b.max); }
  Vec3<T> center() const { return (min + max) * T(0.5); }
  Vec3<T> extents() const { return (max - min) * T(0.5); }
  bool overlaps(const Bounds3& b) const { return (min.array() <= b.max.array()).all() && (b.min.array() <= max.array()).all(); }
  bool contains(const Vec3<T>& p) const { return (min.array() <= p.array()).all() && (p.array() <= max.array()).all(); }
};

}  // namespace gq
