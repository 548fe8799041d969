#pragma once
// Custom geometry: a user shape that takes part in every query through callbacks (the spec's
// PxCustomGeometry::Callbacks). Everything is in the shape's local frame. A convex custom shape needs only
// localBounds, support and raycast: overlap, penetration, distance and sweeps then go through GJK/EPA. It may also
// answer overlap, penetration, distance and sweeps itself (exactly, or faster) by overriding the optional query
// callbacks.
#include <cstdint>

#include "gq/geometry.h"
#include "gq/hit.h"
#include "gq/math.h"
#include "gq/query.h"
#include "gq/transform.h"

namespace gq {

template <class T> class CustomGeometryCallbacks {
 public:
  virtual ~CustomGeometryCallbacks() = default;

  // A string literal (static storage): a Status about the shape keeps the pointer and prints the name in toString().
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

  // Optional queries against another geometry (the spec's Callbacks::overlap, computePenetration and sweep, and
  // distance). The other geometry's pose and every vector are in this shape's local frame. Return true when answered
  // (outputs written), false to let gq run its generic algorithm: GJK for overlap, GJK + EPA for penetration and
  // distance, conservative advancement for sweeps. Only convex custom shapes are asked; when both shapes are custom,
  // geom0's callbacks are asked first. Answers must be finite (a non-finite answer makes the query return
  // InternalError).
  //
  // overlap: touching counts as overlapping.
  virtual bool overlap(const Geometry<T>& /*other*/, const Transform<T>& /*otherPose*/, bool& /*overlapping*/) const {
    return false;
  }
  // When `penetrating`: translating THIS shape by direction * depth separates the two (direction unit, depth >= 0).
  virtual bool computePenetration(const Geometry<T>& /*other*/, const Transform<T>& /*otherPose*/, bool& /*penetrating*/,
                                  Vec3<T>& /*direction*/, T& /*depth*/) const {
    return false;
  }
  // distance: as gq::distance with this shape as geom0 (signed; normal unit from this shape towards the other,
  // point0 on this shape, point1 on the other, all in this shape's frame). gq's generic path is GJK/EPA.
  virtual bool distance(const Geometry<T>& /*other*/, const Transform<T>& /*otherPose*/,
                        DistanceResult<T>& /*result*/) const {
    return false;
  }
  // `swept` (sphere, capsule, box or convex mesh, grown by the rounded shell `inflation`) moves from sweptPose along
  // unitDir for at most maxDist against this shape. On a hit set hasHit and hit.distance, hit.normal (unit, out of
  // this shape: dot(normal, unitDir) <= 0) and hit.position (the touching point); an initial overlap (touching
  // counts) is hit.initialOverlap = true with distance 0. Other hit fields are ignored; gq applies the flag rules.
  virtual bool sweep(const Vec3<T>& /*unitDir*/, T /*maxDist*/, const Geometry<T>& /*swept*/,
                     const Transform<T>& /*sweptPose*/, T /*inflation*/, SweepHit<T>& /*hit*/, bool& /*hasHit*/) const {
    return false;
  }
};

}  // namespace gq
