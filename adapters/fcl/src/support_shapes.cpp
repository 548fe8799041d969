#include "support_shapes.h"

#include <cmath>

namespace gq::fcl::detail {

template <class T> Vec3<T> EllipsoidCallbacks<T>::support(const Vec3<T>& dir) const {
  const Vec3<T> scaled = radii_.cwiseProduct(dir);  // D d
  const T n = scaled.norm();
  if (!(n > T(0))) return Vec3<T>(radii_.x(), T(0), T(0));
  return radii_.cwiseProduct(scaled) / n;
}

// In the unit-sphere space u = x / radii the ray is o' + t d' (d' not unit, t unchanged): |o' + t d'|^2 = 1.
template <class T>
bool EllipsoidCallbacks<T>::raycast(const Vec3<T>& origin, const Vec3<T>& unitDir, T maxDist, HitFlags flags,
                                    RaycastHit<T>& hit) const {
  const Vec3<T> o = origin.cwiseQuotient(radii_), d = unitDir.cwiseQuotient(radii_);
  const T a = d.squaredNorm(), b = o.dot(d), c = o.squaredNorm() - T(1);
  T t = T(0);
  if (c > T(0)) {
    const T disc = b * b - a * c;
    if (b >= T(0) || disc < T(0)) return false;
    t = (-b - std::sqrt(disc)) / a;
    if (t > maxDist) return false;
  }
  hit = RaycastHit<T>();
  hit.distance = t;
  hit.position = origin + t * unitDir;
  // Gradient of the implicit function: x / radii^2; an origin inside reports -dir (the solid-shape rule).
  hit.normal = c > T(0) ? Vec3<T>(hit.position.cwiseQuotient(radii_.cwiseProduct(radii_)).normalized())
                        : Vec3<T>(-unitDir);
  hit.flags = flags & (HitFlag::Position | HitFlag::Normal);
  return true;
}

template <class T> Bounds3<T> TriangleCallbacks<T>::localBounds() const {
  Bounds3<T> b;
  for (const Vec3<T>& v : v_) b.include(v);
  return b;
}

template <class T> Vec3<T> TriangleCallbacks<T>::support(const Vec3<T>& dir) const {
  const T d0 = v_[0].dot(dir), d1 = v_[1].dot(dir), d2 = v_[2].dot(dir);
  if (d0 >= d1 && d0 >= d2) return v_[0];
  return d1 >= d2 ? v_[1] : v_[2];
}

// Moeller-Trumbore, both sides.
template <class T>
bool TriangleCallbacks<T>::raycast(const Vec3<T>& origin, const Vec3<T>& unitDir, T maxDist, HitFlags flags,
                                   RaycastHit<T>& hit) const {
  const Vec3<T> e1 = v_[1] - v_[0], e2 = v_[2] - v_[0];
  const Vec3<T> p = unitDir.cross(e2);
  const T det = e1.dot(p);
  if (det == T(0)) return false;
  const T inv = T(1) / det;
  const Vec3<T> s = origin - v_[0];
  const T u = s.dot(p) * inv;
  if (u < T(0) || u > T(1)) return false;
  const Vec3<T> q = s.cross(e1);
  const T v = unitDir.dot(q) * inv;
  if (v < T(0) || u + v > T(1)) return false;
  const T t = e2.dot(q) * inv;
  if (t < T(0) || t > maxDist) return false;
  hit = RaycastHit<T>();
  hit.distance = t;
  hit.position = origin + t * unitDir;
  const Vec3<T> n = e1.cross(e2).normalized();
  hit.normal = n.dot(unitDir) > T(0) ? Vec3<T>(-n) : n;
  hit.u = u;
  hit.v = v;
  hit.flags = flags & (HitFlag::Position | HitFlag::Normal | HitFlag::UV);
  return true;
}

template class EllipsoidCallbacks<float>;
template class EllipsoidCallbacks<double>;
template class TriangleCallbacks<float>;
template class TriangleCallbacks<double>;

}  // namespace gq::fcl::detail
