#pragma once
// Custom geometry: a user shape that takes part in every query through callbacks (the spec's
// PxCustomGeometry::Callbacks). Everything is in the shape's local frame. A convex custom shape needs only
// localBounds, support and raycast: overlap, penetration, distance and sweeps then go through GJK/EPA.
#include <cstdint>

#include "gq/hit.h"
#include "gq/math.h"

namespace gq {

template <class T> class CustomGeometryCallbacks {
 public:
  virtual ~CustomGeometryCallbacks() = default;

  virtual const char* name() const = 0;
  // Tight local bounds.
  virtual Bounds3<T> localBounds() const = 0;
  // Support mapping: the point of the shape farthest along `dir` (dir need not be unit).
  virtual Vec3<T> support(const Vec3<T>& dir) const = 0;
  // Local-frame raycast with the solid-shape rules (origin inside -> distance 0). Returns true on hit and fills
  // `hit` (fields as requested by flags; set hit.flags accordingly).
  virtual bool raycast(const Vec3<T>& origin, const Vec3<T>& unitDir, T maxDist, HitFlags flags,
                       RaycastHit<T>& hit) const = 0;
  // Whether the shape is convex (support mapping describes it exactly). Non-convex custom shapes answer only
  // raycast and bounds; other queries report Unsupported.
  virtual bool isConvex() const { return true; }
};

}  // namespace gq
