#pragma once
// Prepared shapes: validate a geometry once, query it many times.
//
// A Shape<T> is a Geometry<T> that was checked by Shape<T>::make (the rules of validateGeometry) together with what
// the queries derive from it: its feature radius (the radius about its origin that holds its features, which picks
// the frame a pair query runs in), its local bounds, and whether it is too large for a pair query. The query
// overloads below take prepared shapes and validate only what changes per call: poses, directions, distances.
// They run the same code as the Geometry<T> overloads of gq/query.h after those have validated the geometry, so both
// give bit-identical answers and the same Status on the same bad pose.
//
// Cost (callgrind, double, bench_primitives): a prepared sphere-sphere overlap is a few tens of instructions above its
// kernel; a Geometry<T> call adds the geometry checks and the feature radius on every call (docs/core.md, "Prepared
// shapes", lists the measured counts).
//
// Heavier derived data (a convex hull's scaled inner and outer balls and its support start table) is built on the
// first call that asks for it (Shape::hullBalls) and published once: concurrent first use from several threads builds
// it exactly once (std::call_once), later reads take no lock.
//
// Thread-safety: a Shape is immutable after make(). Any number of threads may query the same Shape (or copies of it)
// at once. Copies are cheap: the geometry's cooked data and the derived data are shared (std::shared_ptr), not
// copied. Assigning to a Shape while another thread queries it is a data race, as for any C++ value.
#include <cstdint>
#include <memory>

#include "gq/geometry.h"
#include "gq/hit.h"
#include "gq/math.h"
#include "gq/query.h"
#include "gq/status.h"
#include "gq/tolerances.h"
#include "gq/transform.h"

namespace gq {

namespace detail {
template <class T> struct ShapeDerived;
template <class T> struct ShapeAccess;
}  // namespace detail

// A convex hull's balls in the shape's frame (scale applied): the hull contains the inner ball and lies in the
// outer one. Non-hull shapes and hulls not made by cookConvexMesh report inner 0 and outer infinity.
template <class T> struct ShapeBalls {
  Vec3<T> center = Vec3<T>::Zero();
  T inner = T(0);
  T outer = T(0);
};

template <class T> class Shape {
 public:
  // An empty shape: every query rejects it with InvalidArgument.
  Shape() = default;

  // Validates `geometry` (the rules of validateGeometry, same Status on failure) and derives its data. On failure
  // `out` is left unchanged.
  static Status make(const Geometry<T>& geometry, Shape& out) noexcept;

  const Geometry<T>& geometry() const noexcept { return geometry_; }
  GeometryType type() const noexcept { return geometry_.type(); }
  bool empty() const noexcept { return !made_; }
  // Radius about the shape's origin that holds its features; infinite for planes, meshes and heightfields.
  T featureRadius() const noexcept { return featureRadius_; }
  // The tight box in the shape's frame (a plane's reaches +-max on its unbounded sides).
  const Bounds3<T>& localBounds() const noexcept { return localBounds_; }
  // The hull's balls, built on the first call (thread-safe, once per shape and its copies).
  ShapeBalls<T> hullBalls() const noexcept;

 private:
  friend struct detail::ShapeAccess<T>;

  Geometry<T> geometry_;
  T featureRadius_ = T(0);
  Bounds3<T> localBounds_{Vec3<T>::Zero(), Vec3<T>::Zero()};
  // Why a pair query (overlap, penetration, distance, sweep) rejects this shape: sizes beyond the range those
  // queries square safely; nullptr when it accepts it.
  StatusCode pairCode_ = StatusCode::InvalidArgument;
  const char* pairProblem_ = "the shape is empty (not made by Shape::make)";
  bool made_ = false;
  bool nonConvexCustom_ = false;
  bool pairReady_ = false;  // made, pairProblem_ null and not a non-convex custom shape: pair queries check only poses
  // A triangle mesh: raycast calls the mesh kernel directly (no dispatch table); with an identity scale the kernel
  // skips the mesh-space products without testing the scale per ray.
  bool rayMesh_ = false;
  bool rayMeshUnscaled_ = false;
  std::shared_ptr<detail::ShapeDerived<T>> derived_;
};

template <class T> Status makeShape(const Geometry<T>& geometry, Shape<T>& out) noexcept {
  return Shape<T>::make(geometry, out);
}

// ---- Queries on prepared shapes: the same contracts as the Geometry<T> overloads in gq/query.h ----------------

template <class T>
Status overlap(const Shape<T>& shape0, const Transform<T>& pose0, const Shape<T>& shape1, const Transform<T>& pose1,
               bool& overlapping) noexcept;

template <class T>
Status computePenetration(PenetrationResult<T>& result, const Shape<T>& shape0, const Transform<T>& pose0,
                          const Shape<T>& shape1, const Transform<T>& pose1) noexcept;

template <class T>
Status distance(DistanceResult<T>& result, const Shape<T>& shape0, const Transform<T>& pose0, const Shape<T>& shape1,
                const Transform<T>& pose1, GjkCache<T>* cache = nullptr) noexcept;

template <class T>
Status distanceWithin(DistanceResult<T>& result, bool& beyond, T maxDistance, const Shape<T>& shape0,
                      const Transform<T>& pose0, const Shape<T>& shape1, const Transform<T>& pose1,
                      GjkCache<T>* cache = nullptr) noexcept;

template <class T>
Status sweep(const Vec3<T>& unitDir, T maxDist, const Shape<T>& shape0, const Transform<T>& pose0,
             const Shape<T>& shape1, const Transform<T>& pose1, SweepHit<T>& hit, bool& hasHit,
             HitFlags hitFlags = kDefaultHitFlags, T inflation = T(0)) noexcept;

template <class T>
Status raycast(const Vec3<T>& origin, const Vec3<T>& unitDir, const Shape<T>& shape, const Transform<T>& pose,
               T maxDist, HitFlags hitFlags, std::uint32_t maxHits, RaycastHit<T>* hits,
               std::uint32_t& hitCount) noexcept;

template <class T>
Status pointDistance(const Vec3<T>& point, const Shape<T>& shape, const Transform<T>& pose,
                     PointDistanceResult<T>& result) noexcept;

template <class T>
Status computeGeomBounds(Bounds3<T>& bounds, const Shape<T>& shape, const Transform<T>& pose, T offset = T(0),
                         T inflation = T(tol::kDefaultBoundsInflation)) noexcept;

}  // namespace gq
