#pragma once
// Raycast kernels, one per target shape (raycast/<shape>.cpp). Inputs are validated by the façade
// (dispatch/raycast.cpp): finite origin, unit dir, maxDist >= 0, maxHits >= 1, valid geometry and pose.
// A kernel writes at most ray.maxHits hits and returns how many; it fills only the fields ray.flags ask for and
// sets each hit's flags to what it filled.
#include <cstdint>

#include <algorithm>
#include <limits>

#include "common/validate.h"
#include "gq/custom.h"
#include "gq/geometry.h"
#include "gq/hit.h"
#include "gq/transform.h"
#include "mesh/triangle.h"

namespace gq {
template <class T> class Shape;
}  // namespace gq

namespace gq::detail {

template <class T> struct RayQuery {
  Vec3<T> origin;  // world
  Vec3<T> dir;     // world, unit
  T maxDist;
  HitFlags flags;
  std::uint32_t maxHits;
};

// The query a kernel receives for valid inputs. Several hits only with MeshMultiple (the spec); solids cap
// themselves at one. A hit has a finite distance: an entry parameter that overflows T (a far ray all but parallel to
// a box face or a plane, found by fuzz_raycast) lies beyond every representable distance, so maxDist = inf means the
// largest finite T and every kernel's "t > maxDist" test rejects it.
template <class T> [[gnu::always_inline]] inline T finiteMaxDist(T maxDist) {
  return std::min(maxDist, std::numeric_limits<T>::max());
}
template <class T>
[[gnu::always_inline]] inline RayQuery<T> rayQuery(const Vec3<T>& origin, const Vec3<T>& unitDir, T maxDist,
                                                   HitFlags flags, std::uint32_t maxHits) {
  const std::uint32_t cap = flags.has(HitFlag::MeshMultiple) ? maxHits : 1u;
  return RayQuery<T>{origin, unitDir, finiteMaxDist(maxDist), flags, cap};
}

// The façade's checks on its success path as predicates of a few compares; a failing input takes the full checks,
// which name the problem. What does not depend on the ray (checked once for a batch): maxDist >= 0 admits +inf and
// rejects NaN and -inf, as checkMaxDist does; the flags are raycast flags; the pose rotation is a unit quaternion
// (the identity, the common case, by one compare).
template <class T>
[[gnu::always_inline]] inline bool raySettingsAreValid(const Transform<T>& pose, T maxDist, HitFlags flags,
                                                       std::uint32_t maxHits, const RaycastHit<T>* hits) {
  const HitFlags sweepOnly = HitFlag::Mtd | HitFlag::PreciseSweep | HitFlag::AssumeNoInitialOverlap;
  return (maxDist >= T(0)) & (maxHits != 0) & (hits != nullptr) & ((flags & sweepOnly).bits() == 0) &
         (isIdentityRotation(pose.q) || isUnitQuaternion(pose.q));
}

// The ray's own checks: a finite origin - p proves both finite (an infinite or NaN coordinate on either side makes
// the difference infinite or NaN); a NaN or infinite direction fails the squared-norm bounds.
template <class T>
[[gnu::always_inline]] inline bool rayIsValid(const Vec3<T>& origin, const Vec3<T>& dir, const Vec3<T>& poseP) {
  const Vec3<T> offset = origin - poseP;
  return (T(0) * offset.x() + T(0) * offset.y() + T(0) * offset.z() == T(0)) &
         squaredNormIsUnit(double(dir.squaredNorm()), tol::kUnitDirection);
}

template <class T>
std::uint32_t raycastSphere(const SphereGeometry<T>& g, const Transform<T>& pose, const RayQuery<T>& ray, RaycastHit<T>* hits);
template <class T>
std::uint32_t raycastPlane(const PlaneGeometry<T>& g, const Transform<T>& pose, const RayQuery<T>& ray, RaycastHit<T>* hits);
template <class T>
std::uint32_t raycastCapsule(const CapsuleGeometry<T>& g, const Transform<T>& pose, const RayQuery<T>& ray, RaycastHit<T>* hits);
template <class T>
std::uint32_t raycastBox(const BoxGeometry<T>& g, const Transform<T>& pose, const RayQuery<T>& ray, RaycastHit<T>* hits);
template <class T>
std::uint32_t raycastConvex(const ConvexMeshGeometry<T>& g, const Transform<T>& pose, const RayQuery<T>& ray, RaycastHit<T>* hits);
template <class T>
std::uint32_t raycastTriangleMesh(const TriangleMeshGeometry<T>& g, const Transform<T>& pose, const RayQuery<T>& ray, RaycastHit<T>* hits);
// The Shape<T> raycast on a triangle-mesh shape (gq/shape.h's contract): inputs passing the success-path predicate
// (rayIsValid, raySettingsAreValid) take the mesh kernel of raycastTriangleMesh without the dispatch table, with the
// shape's identity scale known from Shape::make (one hit on an unscaled mesh with an identity pose rotation:
// TriangleMeshRays::castOneCooked); others take raycastShapeChecked, whose Status names the problem.
template <class T>
Status raycastMeshShape(const Vec3<T>& origin, const Vec3<T>& unitDir, const Shape<T>& shape,
                        const Transform<T>& pose, T maxDist, HitFlags hitFlags, std::uint32_t maxHits,
                        RaycastHit<T>* hits, std::uint32_t& hitCount) noexcept;

// The Shape<T> raycast through the dispatch table after the full checks (dispatch/raycast.cpp).
template <class T>
Status raycastShapeChecked(const Vec3<T>& origin, const Vec3<T>& unitDir, const Shape<T>& shape,
                           const Transform<T>& pose, T maxDist, HitFlags hitFlags, std::uint32_t maxHits,
                           RaycastHit<T>* hits, std::uint32_t& hitCount) noexcept;

// A mesh raycast's hit without its position (which its caller computes from the ray as the raycast does, origin +
// dir * distance): the fields a batch keeps per ray, one 64-byte cache line in double. flags is 0 for no hit.
template <class T> struct MeshRayHit {
  Vec3<T> normal;
  T distance;
  T u, v;
  std::uint32_t faceIndex;
  HitFlags flags;
};

// A triangle the mesh walk hit: its cooked index, the exact test's hit, and where its values are (TriangleMesh::
// triangleValues: vertex k's axis a at values[(3 k + a) stride], its input index at values[9 stride]), so the hit fill
// looks nothing up.
template <class T> struct MeshTriangleHit {
  std::uint32_t cooked;
  std::uint32_t stride;
  const T* values;
  TriangleRayHit<T> tri;
};

// Raycasts against one mesh at one pose (a single raycast, or a batch's rays): the mesh frame and the node test the
// CPU runs are found once; cast() is raycastTriangleMesh's kernel for one ray. Holds references to g and pose.
template <class T> class TriangleMeshRays {
 public:
  TriangleMeshRays(const TriangleMeshGeometry<T>& g, const Transform<T>& pose)
      : TriangleMeshRays(g, pose, !g.scale.isIdentity()) {}
  // `scaled`: !g.scale.isIdentity(), as a prepared shape keeps it.
  TriangleMeshRays(const TriangleMeshGeometry<T>& g, const Transform<T>& pose, bool scaled);
  std::uint32_t cast(const RayQuery<T>& ray, RaycastHit<T>* hits) const;
  // cast() for one hit (ray.maxHits 1) written as a MeshRayHit: its fields are cast()'s bit for bit but the position,
  // whose flag it keeps when asked; flags 0 when nothing is hit. Returns the hit count.
  std::uint32_t castOne(const RayQuery<T>& ray, MeshRayHit<T>& hit) const;
  // One hit (closest or any) of a ray passing the success-path checks (rayIsValid, raySettingsAreValid) on an
  // unscaled mesh whose pose rotation is the identity (a mesh placed as cooked): cast() without the instance frame.
  static std::uint32_t castOneCooked(const TriangleMeshGeometry<T>& g, const Transform<T>& pose,
                                     const Vec3<T>& origin, const Vec3<T>& dir, T maxDist, HitFlags flags,
                                     RaycastHit<T>& hit);

 private:
  [[gnu::always_inline]] Vec3<T> toMesh(const Vec3<T>& v) const {
    if (!scaled_) return v;
    // The diagonal product in scalars (GCC leaves Eigen's cwiseProduct assignment an out-of-line call per hit normal).
    const Vec3<T>& d = invScaleDiagonal_;
    if (diagonal_) return Vec3<T>(v.x() * d.x(), v.y() * d.y(), v.z() * d.z());
    return invScale_ * v;
  }
  // Hit: RaycastHit or MeshRayHit (no position). frame: the instance frame, unused with kCooked (see castOneCooked).
  template <bool kCooked, class Hit>
  static void writeHitIn(const TriangleMeshRays* frame, const TriangleMeshGeometry<T>& g, const Vec3<T>& origin,
                         const Vec3<T>& dir, HitFlags asked, const MeshTriangleHit<T>& found, Hit& hit);
  template <class Hit> std::uint32_t castInto(const RayQuery<T>& ray, Hit* hits) const;
  template <bool kCooked>
  static void writeNormalIn(const TriangleMeshRays* frame, const TriangleMeshGeometry<T>& g,
                            const MeshTriangleHit<T>& found, const Vec3<T>& rayDir, Vec3<T>& normal);

  const TriangleMeshGeometry<T>& g_;
  const Transform<T>& pose_;
  bool scaled_;
  bool rotated_;
  bool flips_;
  bool diagonal_ = true;  // S^-1 is diag(invScaleDiagonal_)
  int walk_;
  Vec3<T> invScaleDiagonal_;
  Mat3<T> invScale_;
};

// Mesh raycasts walk 8-wide nodes with AVX2 where the CPU has it; true makes them use the SSE4.2 baseline (two 4-lane
// halves per node) on any CPU, so tests can compare both walks on one machine. Not for use while rays are cast.
void setMeshRaycastBaselineOnly(bool baselineOnly);
template <class T>
std::uint32_t raycastHeightField(const HeightFieldGeometry<T>& g, const Transform<T>& pose, const RayQuery<T>& ray, RaycastHit<T>* hits);
template <class T>
std::uint32_t raycastCustom(const CustomGeometry<T>& g, const Transform<T>& pose, const RayQuery<T>& ray, RaycastHit<T>* hits);

}  // namespace gq::detail
