#pragma once
// Support-mapped custom shapes for the FCL types gq has no geometry for: Ellipsoid and TriangleP (also used for
// the per-triangle contacts of BVHModel pairs). Local frame = FCL's local frame.
#include "gq/custom.h"

namespace gq::fcl::detail {

// x^2/a^2 + y^2/b^2 + z^2/c^2 <= 1. Support along d: D^2 d / |D d| with D = diag(a, b, c).
template <class T> class EllipsoidCallbacks final : public CustomGeometryCallbacks<T> {
 public:
  explicit EllipsoidCallbacks(const Vec3<T>& radii) : radii_(radii) {}
  const char* name() const override { return "ellipsoid"; }
  Bounds3<T> localBounds() const override { return Bounds3<T>::fromCenterExtents(Vec3<T>::Zero(), radii_); }
  Vec3<T> support(const Vec3<T>& dir) const override;
  bool raycast(const Vec3<T>& origin, const Vec3<T>& unitDir, T maxDist, HitFlags flags,
               RaycastHit<T>& hit) const override;
  const Vec3<T>& radii() const { return radii_; }

 private:
  Vec3<T> radii_;
};

// A solid triangle (a flat convex set): support = the vertex farthest along d; two-sided raycast.
template <class T> class TriangleCallbacks final : public CustomGeometryCallbacks<T> {
 public:
  TriangleCallbacks(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) : v_{a, b, c} {}
  const char* name() const override { return "triangle"; }
  Bounds3<T> localBounds() const override;
  Vec3<T> support(const Vec3<T>& dir) const override;
  bool raycast(const Vec3<T>& origin, const Vec3<T>& unitDir, T maxDist, HitFlags flags,
               RaycastHit<T>& hit) const override;
  const Vec3<T>& vertex(int i) const { return v_[i]; }

 private:
  Vec3<T> v_[3];
};

}  // namespace gq::fcl::detail
