#pragma once
// The geometry queries (the spec's PxGeometryQuery). All functions:
//  - take every vector and pose in one (world) space and answer in it;
//  - validate their input and return a Status; on failure they write no output;
//  - never throw;
//  - are instantiated for float and double.
//
// Parameter order, one rule for every query here and in gq/mesh_query.h and gq/contacts.h:
//   inputs, then outputs, then optional arguments with defaults (flags, inflation, warm-start cache, tolerance,
//   iteration limit) or one settings struct (TriangleSweepSettings, TriangleContactSettings).
// Except where PhysX puts the result first, kept so PhysX users' code reads the same: the result struct of
// computePenetration, distance and distanceWithin (then beyond and maxDistance), computeTriangleMeshPenetration and
// computeHeightFieldPenetration (PxGeometryQuery::computePenetration(direction, depth, ...)), the bounds of
// computeGeomBounds (PxGeometryQuery::computeGeomBounds(bounds, ...)), and the report callback of
// findOverlapTriangleMeshPairs. A paged output (findOverlapTriangleMesh / findOverlapHeightField) is a
// TriangleOverlapPage (the caller's buffer, its capacity, the start) in and a TriangleOverlapPageResult out.
//
// Sign conventions (every pair, float and double; tests/core/sign_conventions_property_test.cpp checks the first
// four rows against each other on seeded poses):
//   DistanceResult::distance      > 0 apart, 0 touching, < 0 penetrating: minus the penetration depth (a triangle
//                                 mesh or heightfield is a surface, not a solid: 0 from touching on)
//   DistanceResult::normal        unit, from geom0 towards geom1; when penetrating, -PenetrationResult::direction
//                                 (where the MTD is not unique, both separate the pair)
//   PenetrationResult::direction  unit; translating geom0 by direction * depth separates (it points from geom1
//                                 towards geom0); depth >= 0 and equals -distance
//   overlap                       true exactly when distance <= 0 (touching overlaps)
//   ContactPoint (contacts.h)     normal unit, from the triangle towards the geometry; separation > 0 gap, < 0 depth
//   SweepHit::normal              against the motion (normal . unitDir <= 0), pushing the swept shape out of the
//                                 target; an initial overlap reports distance 0 and normal -unitDir, or with
//                                 HitFlag::Mtd distance = -depth and the normal out of the target
//   RaycastHit::normal            the outward surface normal at the hit (a double-sided mesh: the side the ray hit);
//                                 an origin inside a solid: distance 0, normal -unitDir
//   PointDistanceResult::distance >= 0; 0 inside a solid
//   plane                         x = 0 of its frame, normal +X; the solid half-space x <= 0 for overlaps, sweeps,
//                                 penetration and distance
#include <array>
#include <cstdint>

#include "gq/geometry.h"
#include "gq/hit.h"
#include "gq/math.h"
#include "gq/status.h"
#include "gq/tolerances.h"
#include "gq/transform.h"

namespace gq {

// Raycast against one geometry. maxDist in [0, inf); maxHits >= 1; `hits` holds maxHits entries.
// Solids (sphere, capsule, box, convex, custom) and planes report at most one hit; meshes and heightfields
// report up to maxHits with HitFlag::MeshMultiple. `hitCount` receives the number of hits written.
template <class T>
Status raycast(const Vec3<T>& origin, const Vec3<T>& unitDir, const Geometry<T>& geom, const Transform<T>& pose,
               T maxDist, HitFlags hitFlags, std::uint32_t maxHits, RaycastHit<T>* hits, std::uint32_t& hitCount) noexcept;

// World AABB of `geom` at `pose`: extents grow by `offset`, then scale about the centre by `inflation`.
template <class T>
Status computeGeomBounds(Bounds3<T>& bounds, const Geometry<T>& geom, const Transform<T>& pose, T offset = T(0),
                         T inflation = T(tol::kDefaultBoundsInflation)) noexcept;

template <class T> struct PointDistanceResult {
  T distance = T(0);                  // Euclidean (not squared); 0 inside a solid
  Vec3<T> closestPoint = Vec3<T>::Zero();
  std::uint32_t closestIndex = kInvalidFaceIndex;  // triangle index for meshes
};

// Distance from a point to a sphere, capsule, box, convex or triangle mesh (others: Unsupported).
template <class T>
Status pointDistance(const Vec3<T>& point, const Geometry<T>& geom, const Transform<T>& pose,
                     PointDistanceResult<T>& result) noexcept;

// Boolean overlap; touching counts as overlapping. Plane vs plane/mesh/heightfield: Unsupported.
template <class T>
Status overlap(const Geometry<T>& geom0, const Transform<T>& pose0, const Geometry<T>& geom1,
               const Transform<T>& pose1, bool& overlapping) noexcept;

template <class T> struct PenetrationResult {
  bool penetrating = false;
  Vec3<T> direction = Vec3<T>::Zero();  // unit; translate geom0 by direction * depth to separate
  T depth = T(0);                       // >= 0
};

// Minimum translational distance (MTD) for convex pairs (including plane and custom convex).
template <class T>
Status computePenetration(PenetrationResult<T>& result, const Geometry<T>& geom0, const Transform<T>& pose0,
                          const Geometry<T>& geom1, const Transform<T>& pose1) noexcept;

template <class T> struct DistanceResult {
  T distance = T(0);                 // signed: > 0 separation, < 0 penetration depth (convex pairs)
  Vec3<T> point0 = Vec3<T>::Zero();  // witness on geom0 (world)
  Vec3<T> point1 = Vec3<T>::Zero();  // witness on geom1 (world)
  Vec3<T> normal = Vec3<T>::Zero();  // unit, from geom0 towards geom1
};

// Warm-start state for distance(): pass the same cache for the same pair across frames.
template <class T> struct GjkCache {
  Vec3<T> direction = Vec3<T>::Zero();  // last separating direction, in geom0's local frame (0 = cold)
  std::uint32_t iterations = 0;         // iterations the last call took (diagnostic)
  // Search directions (geom0's local frame) whose support points formed the last GJK simplex. The next call
  // re-evaluates them to start from a simplex of valid support points (safe even if the shapes changed).
  std::array<Vec3<T>, 4> simplexDirections{};
  std::uint32_t simplexSize = 0;        // 0 = no simplex cached
};

// Signed separation distance with witness points and normal.
template <class T>
Status distance(DistanceResult<T>& result, const Geometry<T>& geom0, const Transform<T>& pose0,
                const Geometry<T>& geom1, const Transform<T>& pose1, GjkCache<T>* cache = nullptr) noexcept;

// Distance for a caller that keeps only distances below `maxDistance` (the nearest pair so far; MoveIt pre-seeds
// FCL's result with it): GJK and mesh or heightfield searches stop once the pair is proven farther. A pair closer than
// maxDistance gets distance()'s answer and beyond = false. A farther one may get beyond = true: result.distance is
// then only a lower bound of its distance (to rounding) above maxDistance, witnesses and normal are zero, and the
// cache holds a valid warm start. maxDistance may be any number but NaN (+inf: distance()).
template <class T>
Status distanceWithin(DistanceResult<T>& result, bool& beyond, T maxDistance, const Geometry<T>& geom0,
                      const Transform<T>& pose0, const Geometry<T>& geom1, const Transform<T>& pose1,
                      GjkCache<T>* cache = nullptr) noexcept;

// Sweeps geom0 from pose0 along unitDir up to maxDist against geom1 at pose1. `hasHit` says whether `hit` was
// written. `inflation` grows geom0 by a rounded shell.
template <class T>
Status sweep(const Vec3<T>& unitDir, T maxDist, const Geometry<T>& geom0, const Transform<T>& pose0,
             const Geometry<T>& geom1, const Transform<T>& pose1, SweepHit<T>& hit, bool& hasHit,
             HitFlags hitFlags = kDefaultHitFlags, T inflation = T(0)) noexcept;

}  // namespace gq
