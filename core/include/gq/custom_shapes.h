#pragma once
// Ready-made custom shapes: the spec's PxCustomGeometryExt::CylinderCallbacks and ConeCallbacks, and an ellipsoid
// and a solid triangle. Each has an exact raycast (closed form) and exact bounds, and a support mapping through which
// overlap, penetration, distance and sweeps run GJK/EPA (the cylinder answers overlap with a sphere itself, and with
// a box when a separating axis or a common point is cheap to find).
//  - Cylinder (axis local X, like the capsule): |x| <= halfHeight, y^2 + z^2 <= radius^2;
//  - Cone (axis local X): base disk of `radius` at x = -halfHeight, apex at x = +halfHeight;
//  - Ellipsoid: x^2/a^2 + y^2/b^2 + z^2/c^2 <= 1 for radii (a, b, c);
//  - Triangle: the flat solid triangle abc (both faces; a ray in its plane enters through an edge).
// Use: CustomGeometry<T>(std::make_shared<CylinderCallbacks<T>>(radius, halfHeight)), or the validating factories
// below, which return a Status instead of building a shape the queries would reject or misanswer.
#include <memory>

#include "gq/custom.h"
#include "gq/geometry.h"
#include "gq/status.h"

namespace gq {

template <class T> class CylinderCallbacks final : public CustomGeometryCallbacks<T> {
 public:
  CylinderCallbacks(T radius, T halfHeight) : radius_(radius), halfHeight_(halfHeight) {}
  const char* name() const override { return "cylinder"; }
  Bounds3<T> localBounds() const override;
  Vec3<T> support(const Vec3<T>& dir) const override;
  bool raycast(const Vec3<T>& origin, const Vec3<T>& unitDir, T maxDist, HitFlags flags,
               RaycastHit<T>& hit) const override;
  // Against a sphere: closed form. Against a box: a separating axis or a common point when one is cheap to find,
  // else GJK (false).
  bool overlap(const Geometry<T>& other, const Transform<T>& otherPose, bool& overlapping) const override;
  // Against a separated box: the certified closest pair of distance/box_cylinder.cpp; else GJK/EPA (false).
  bool distance(const Geometry<T>& other, const Transform<T>& otherPose, DistanceResult<T>& result) const override;
  T radius() const { return radius_; }
  T halfHeight() const { return halfHeight_; }

 private:
  T radius_, halfHeight_;
};

template <class T> class ConeCallbacks final : public CustomGeometryCallbacks<T> {
 public:
  ConeCallbacks(T radius, T halfHeight) : radius_(radius), halfHeight_(halfHeight) {}
  const char* name() const override { return "cone"; }
  Bounds3<T> localBounds() const override;
  Vec3<T> support(const Vec3<T>& dir) const override;
  bool raycast(const Vec3<T>& origin, const Vec3<T>& unitDir, T maxDist, HitFlags flags,
               RaycastHit<T>& hit) const override;
  T radius() const { return radius_; }
  T halfHeight() const { return halfHeight_; }

 private:
  T radius_, halfHeight_;
};

// x^2/a^2 + y^2/b^2 + z^2/c^2 <= 1, radii = (a, b, c). Support along d: D^2 d / |D d| with D = diag(a, b, c).
// Raycast: the ray scaled into the unit sphere's space (t unchanged), a quadratic solved without cancellation.
template <class T> class EllipsoidCallbacks final : public CustomGeometryCallbacks<T> {
 public:
  explicit EllipsoidCallbacks(const Vec3<T>& radii) : radii_(radii), shape_(radii / radii.maxCoeff()) {}
  const char* name() const override { return "ellipsoid"; }
  Bounds3<T> localBounds() const override { return Bounds3<T>::fromCenterExtents(Vec3<T>::Zero(), radii_); }
  Vec3<T> support(const Vec3<T>& dir) const override;
  bool raycast(const Vec3<T>& origin, const Vec3<T>& unitDir, T maxDist, HitFlags flags,
               RaycastHit<T>& hit) const override;
  const Vec3<T>& radii() const { return radii_; }

 private:
  Vec3<T> radii_;
  Vec3<T> shape_;  // radii / max radius: the support's products stay within range for any size
};

// The solid triangle abc, a flat convex set: support = the vertex farthest along d (the first of equals);
// raycast from either side (normal against the ray, u/v the barycentric weights of b and c), a ray in the
// triangle's plane entering through an edge (normal: that edge's outward normal in the plane).
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

// Validating factories (`out` untouched on failure):
//  - makeCylinder, makeCone, makeEllipsoid: InvalidArgument for a non-finite or non-positive size;
//  - makeTriangle: InvalidArgument for a non-finite vertex, DegenerateMesh for a triangle without area, by the rule
//    mesh cooking drops triangles with (|(b - a) x (c - a)| <= tol::kDegenerateTriangleArea * longest edge^2):
//    its raycast normal and face are undefined.
template <class T> Status makeCylinder(T radius, T halfHeight, CustomGeometry<T>& out);
template <class T> Status makeCone(T radius, T halfHeight, CustomGeometry<T>& out);
template <class T> Status makeEllipsoid(const Vec3<T>& radii, CustomGeometry<T>& out);
template <class T> Status makeTriangle(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c, CustomGeometry<T>& out);

}  // namespace gq
