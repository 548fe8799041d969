#pragma once
// Ready-made custom shapes (the spec's PxCustomGeometryExt::CylinderCallbacks and ConeCallbacks): exact raycasts
// and bounds, and a support mapping through which overlap, penetration, distance and sweeps run GJK/EPA (the
// cylinder answers overlap with a sphere itself, and with a box when a separating axis or a common point is cheap
// to find).
// Both have their axis along local X (like the capsule):
//  - Cylinder: |x| <= halfHeight, y^2 + z^2 <= radius^2;
//  - Cone: base disk of `radius` at x = -halfHeight, apex at x = +halfHeight.
// Use: CustomGeometry<T>(std::make_shared<CylinderCallbacks<T>>(radius, halfHeight)).
// Sizes must be finite and > 0 (makeCylinder/makeCone check it and return a Status).
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

// Validating factories: InvalidArgument for non-finite or non-positive sizes (`out` untouched then).
template <class T> Status makeCylinder(T radius, T halfHeight, CustomGeometry<T>& out);
template <class T> Status makeCone(T radius, T halfHeight, CustomGeometry<T>& out);

}  // namespace gq
