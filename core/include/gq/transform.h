#pragma once
// Rigid transform = rotation quaternion + translation (like PxTransform): x_world = q * x_local + p.
#include "gq/math.h"

namespace gq {

template <class T> struct Transform {
  Quat<T> q = Quat<T>::Identity();
  Vec3<T> p = Vec3<T>::Zero();

  Transform() = default;
  explicit Transform(const Vec3<T>& position) : p(position) {}
  Transform(const Vec3<T>& position, const Quat<T>& rotation) : q(rotation), p(position) {}
  explicit Transform(const Eigen::Transform<T, 3, Eigen::Isometry>& iso) : q(iso.rotation()), p(iso.translation()) {}

  static Transform identity() { return Transform(); }

  Vec3<T> transform(const Vec3<T>& v) const { return q * v + p; }
  Vec3<T> transformInv(const Vec3<T>& v) const { return q.conjugate() * (v - p); }
  Vec3<T> rotate(const Vec3<T>& v) const { return q * v; }
  Vec3<T> rotateInv(const Vec3<T>& v) const { return q.conjugate() * v; }

  // (a * b).transform(x) == a.transform(b.transform(x))
  Transform operator*(const Transform& b) const { return Transform(q * b.p + p, q * b.q); }
  Transform getInverse() const {
    const Quat<T> qi = q.conjugate();
    return Transform(-(qi * p), qi);
  }
  // Re-express this transform relative to `frame`: frame.getInverse() * this, with the translations subtracted
  // before rotating (one rotation, and no cancellation between two rotated far-away positions).
  Transform relativeTo(const Transform& frame) const {
    const Quat<T> qi = frame.q.conjugate();
    return Transform(qi * (p - frame.p), qi * q);
  }

  Eigen::Transform<T, 3, Eigen::Isometry> toIsometry() const {
    Eigen::Transform<T, 3, Eigen::Isometry> iso = Eigen::Transform<T, 3, Eigen::Isometry>::Identity();
    iso.linear() = q.toRotationMatrix();
    iso.translation() = p;
    return iso;
  }

  template <class U> Transform<U> cast() const { return Transform<U>(p.template cast<U>(), q.template cast<U>()); }

  bool isFinite() const { return gq::isFinite(p) && gq::isFinite(q); }
  // Finite with a unit quaternion (|q| within 1e-3 of 1, as PhysX's PxTransform::isValid()).
  bool isValid() const { return isFinite() && std::abs(q.norm() - T(1)) < T(1e-3); }
};

}  // namespace gq
