#pragma once
// GJK distance, GJK boolean overlap and EPA penetration on two support-mapped convex shapes, in world space.
//
// A shape is a "core" (point, segment, box, scaled convex hull or custom convex) swept by a ball of radius
// `margin`: spheres are points + radius and capsules are segments + radius, so GJK stays exact on curved shapes
// (it only ever runs on the polytope-like cores; the margins are subtracted in closed form afterwards).
//
// Sign conventions (shared with gq::distance):
//  - normal is unit and points from shape a towards shape b;
//  - point0 lies on a's surface, point1 on b's surface, and point1 = point0 + distance * normal;
//  - for penetration (distance < 0), translating b by depth * normal (or a by -depth * normal) separates them.
#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <memory>

#include "gq/kernels/vector.h"
#include "gq/cooking.h"
#include "gq/custom.h"
#include "gq/geometry.h"
#include "gq/query.h"
#include "gq/status.h"
#include "gq/tolerances.h"
#include "gq/transform.h"

namespace gq::kernels {

// Convex hulls with more vertices than this use hill-climbing over the hull's edge adjacency (warm-started from the
// previous support vertex); smaller ones are searched exhaustively. Measured (docs/performance.md): the climb is
// faster in time from 12 vertices up (the exhaustive scan's data-dependent branches mispredict), and a SIMD scan
// over a per-query structure-of-arrays copy (SSE2) was slower than the climb at 30 vertices.
inline constexpr std::uint32_t kHillClimbMinVertices = 8;
// GJK/EPA stopping tolerance = max(Rel<T>::kGjkTolerance, kGjkRoundoffUlps * machine epsilon) * length scale:
// the floor keeps float from chasing an error bound below its own rounding of the support points.
inline constexpr double kGjkRoundoffUlps = 16.0;
inline constexpr std::uint32_t kGjkMaxIterations = 128;
inline constexpr std::uint32_t kEpaMaxIterations = 128;
// GJK steps without a strict decrease of |v| tolerated before stopping (rounding stalls near the origin).
inline constexpr std::uint32_t kGjkMaxStalls = 4;
// A hull's support start table: a cube map of start vertices for the hill climb (opaque here; core keeps its layout).
template <class T> class SupportStartTable;
// The shared table of a cooked hull, built on first use and valid while the mesh lives; nullptr for hulls of at
// most 8 vertices (they are scanned). Set ConvexShape::startTable to it: the support calls then start their climb
// one step or none from the answer.
template <class T> const SupportStartTable<T>* supportStartTable(const std::shared_ptr<const ConvexMesh<T>>& mesh);

// A support mapping for one convex Geometry<T> at a pose. Holds raw pointers into the geometry's cooked data or
// callbacks: it must not outlive the Geometry it was made from.
template <class T> struct ConvexShape {
  enum class Kind : std::uint8_t { Point, Segment, Box, Hull, Custom };

  Kind kind = Kind::Point;
  // Placement: world = position + rotation * local. A matrix, not a quaternion: every support call rotates twice,
  // and hosts that hold matrices (FCL, Bullet) place a shape without a round trip through a quaternion.
  Mat3<T> rotation = Mat3<T>::Identity();
  Vec3<T> position = Vec3<T>::Zero();
  T margin = T(0);                              // radius of the rounded shell (sphere, capsule), else 0
  Vec3<T> halfExtents = Vec3<T>::Zero();        // box half extents; segment: (halfHeight, 0, 0)
  const ConvexMesh<T>* hull = nullptr;          // Kind::Hull
  const SupportStartTable<T>* startTable = nullptr;  // Kind::Hull with a cooked start table (else climbs warm)
  Mat3<T> hullScale = Mat3<T>::Identity();      // symmetric MeshScale matrix (Kind::Hull)
  bool hullScaled = false;                      // false: hullScale is the identity
  const CustomGeometryCallbacks<T>* custom = nullptr;  // Kind::Custom
  T size = T(0);                                // length scale of the shape (bounding radius incl. margin)
  T localScale = T(1);                          // factor on the local core's points (a rescaled pair, pair_scale.h)
  mutable std::uint32_t climbStart = 0;         // hill-climbing warm start (last support vertex)

  // Point of the core farthest along `dir` (world, need not be unit), in world space.
  Vec3<T> support(const Vec3<T>& dir) const {
    return toWorld(Vec3<T>(localScale * supportLocal(Vec3<T>(rotation.transpose() * dir))));
  }
  Vec3<T> toWorld(const Vec3<T>& local) const { return position + rotation * local; }
  // Same in the shape's local frame, before localScale.
  Vec3<T> supportLocal(const Vec3<T>& dirLocal) const;
  // A point inside the core (world).
  Vec3<T> center() const;
};

// Sphere, capsule, box, convex mesh and convex custom geometry (check isConvexShapeType first; planes, meshes and
// heightfields have no bounded support mapping). The matrix form takes an orthonormal rotation (det +1) as given.
bool isConvexShapeType(GeometryType type);
template <class T> ConvexShape<T> makeConvexShape(const Geometry<T>& geom, const Transform<T>& pose);
template <class T>
ConvexShape<T> makeConvexShape(const Geometry<T>& geom, const Mat3<T>& rotation, const Vec3<T>& position);

// Support point of the Minkowski difference a - b, with the two points it came from (needed for witnesses).
// No default member initializers on purpose: EPA keeps ~130 of these in a stack array per query, and zeroing them
// cost more than EPA's own work on small hulls (a slot is always written before it is read).
template <class T> struct SupportPoint {
  Vec3<T> w;  // a - b
  Vec3<T> a;  // on a's core
  Vec3<T> b;  // on b's core
  Vec3<T> d;  // world search direction: a = s_A(d), b = s_B(-d)
};

template <class T> struct GjkSimplex {
  std::array<SupportPoint<T>, 4> points;
  std::uint32_t size = 0;
};

template <class T> struct GjkResult {
  Status status;               // Ok, or NotConverged when the final error bound exceeds the tolerance
  bool coresOverlap = false;   // the cores intersect (within tolerance): run EPA for depth and normal
  T distance = T(0);           // shapes' signed distance = core distance - margins (valid when !coresOverlap)
  Vec3<T> point0 = Vec3<T>::Zero();  // on a's surface (world)
  Vec3<T> point1 = Vec3<T>::Zero();  // on b's surface (world)
  Vec3<T> normal = Vec3<T>::UnitX(); // unit, from a to b
  T errorBound = T(0);         // upper bound on |core distance - exact| (from the duality gap)
  std::uint32_t iterations = 0;
  GjkSimplex<T> simplex;       // final simplex (handed to EPA when the cores overlap)
  // Stopped once the shapes' distance was certified above the caller's `farEnough`: `distance` is only that lower
  // bound, the witnesses and normal are not written.
  bool beyond = false;
};

// The distance result of cores that are apart (!g.coresOverlap): signed distance, normal and witnesses.
template <class T> void writeSeparated(const GjkResult<T>& g, DistanceResult<T>& out) {
  out.distance = g.distance;
  out.normal = g.normal;
  out.point0 = g.point0;
  out.point1 = g.point1;
}

// Distance between a and b. `cache` (optional): warm-start direction in a's local frame, updated on return.
// `stopTolerance` (optional, absolute): stop once the certified error bound (the duality gap) is below
// max(gjkTolerance(a, b), stopTolerance), for a caller that asked for less (FCL's DistanceRequest::distance_tolerance);
// whether the cores overlap is still decided at gjkTolerance. The default 0 leaves the stop rule as it is.
// `start` (optional, world): the first search direction when there is no cache, for a caller that has the shapes'
// centres at hand (a's minus b's); without it GJK places both shapes' centres itself.
// `farEnough` (optional): a caller that keeps only distances up to it (the nearest triangle so far of a mesh) lets
// GJK stop as soon as a support point's lower bound exceeds it (r.beyond).
template <class T>
GjkResult<T> gjkDistance(const ConvexShape<T>& a, const ConvexShape<T>& b, GjkCache<T>* cache = nullptr,
                         T stopTolerance = T(0), const Vec3<T>* start = nullptr,
                         T farEnough = std::numeric_limits<T>::infinity());

// What a positive gjkOverlap saw of the cores when it stopped: either a simplex enclosing the origin (cores
// overlap) or a point of the cores' Minkowski difference, whose norm bounds the core distance from above.
template <class T> struct GjkOverlapWitness {
  bool coresOverlap = false;
  GjkSimplex<T> simplex;              // valid when coresOverlap
  T coreDistanceUpper = T(0);         // >= the cores' distance (when !coresOverlap)
};

// Boolean overlap of the full shapes (margins included); returns as soon as a separating axis is found.
// Touching counts as overlapping. `witness` (optional) is written when the answer is true. `start` (optional, world):
// the first search direction, as gjkDistance's.
template <class T>
bool gjkOverlap(const ConvexShape<T>& a, const ConvexShape<T>& b, GjkOverlapWitness<T>* witness = nullptr,
                const Vec3<T>* start = nullptr);

template <class T> struct EpaResult {
  Status status;                     // Ok, or NotConverged (best face found is reported)
  T depth = T(0);                    // >= 0 penetration depth of the full shapes (margins included)
  Vec3<T> normal = Vec3<T>::UnitX(); // unit, from a to b: translate b by depth * normal to separate
  Vec3<T> point0 = Vec3<T>::Zero();  // deepest point of a inside b (world), on a's surface
  Vec3<T> point1 = Vec3<T>::Zero();  // deepest point of b inside a, on b's surface: point1 = point0 - depth*normal
  std::uint32_t iterations = 0;
};

// Penetration depth and normal of two overlapping shapes. Runs GJK first; if the cores are separated the answer
// is GJK's in closed form (depth = max(0, -distance): exact for rounded shells), else EPA on the cores. `start` (optional) is an enclosing simplex from gjkDistance.
template <class T>
EpaResult<T> epaPenetration(const ConvexShape<T>& a, const ConvexShape<T>& b, const GjkSimplex<T>* start = nullptr);

template <class T> constexpr T gjkRelativeTolerance() {
  const T floor = T(kGjkRoundoffUlps) * std::numeric_limits<T>::epsilon();
  return T(tol::Rel<T>::kGjkTolerance) > floor ? T(tol::Rel<T>::kGjkTolerance) : floor;
}
// A pair's length scale: the larger bounding radius, or the centres' distance (the rounding of world-space support
// points grows with their distance from the origin too), range-safe (an offset under 1e-154 in double has a square
// that underflows: the pair would look smaller than it is, and its rescaled copy larger).
template <class T> T gjkPairLength(const ConvexShape<T>& a, const ConvexShape<T>& b) {
  return std::max({a.size, b.size, rangeSafeNorm(Vec3<T>(a.position - b.position))});
}
// GJK/EPA stopping tolerance for a pair (see kGjkRoundoffUlps): gjkRelativeTolerance times the pair's length scale.
template <class T> T gjkToleranceFor(T length) {
  return gjkRelativeTolerance<T>() * std::max(length, std::numeric_limits<T>::min());
}
template <class T> T gjkTolerance(const ConvexShape<T>& a, const ConvexShape<T>& b) {
  return gjkToleranceFor(gjkPairLength(a, b));
}

}  // namespace gq::kernels
