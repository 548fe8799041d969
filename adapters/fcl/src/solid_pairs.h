#pragma once
// The adapter's fast path for two closed convex solids: FCL Sphere, Box, Capsule, Cylinder, Cone, Ellipsoid, Convex,
// TriangleP and Halfspace. One table keyed on the two FCL shapes (solid_pairs.cpp) picks, per ordered pair, a
// function calling core's kernel for that pair directly, without the public façade's re-validation and dispatch:
//  - sphere, box and capsule pairs read the FCL parameters and the Transform3 matrices as they are (no gq::Geometry,
//    no quaternion, no cache): the second shape is expressed in the first's frame (R_a^T R_b, R_a^T (t_b - t_a)), or
//    in the box's frame, or relative to the first translation, and core's frame-form kernels answer; so do a
//    sphere/cylinder overlap and distance (closed forms), a box/cylinder overlap and a box/cylinder distance
//    without a requested depth when core's certificates prove the overlap (FCL's -1), else GJK;
//  - pairs with another solid convert both sides (convert.h; a Convex comes from the cache) and call core's kernel
//    for their gq geometry types, chosen at compile time.
// Semantics are the façade's: touching overlaps; distance is signed with the normal from a to b, in world space
// (without a requested depth, GJK pairs answer FCL's -1 when overlapping: solidFclDistance).
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <typeinfo>

#include <fcl/geometry/collision_geometry.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/capsule.h>
#include <fcl/geometry/shape/convex.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/collision_request.h>
#include <fcl/narrowphase/collision_result.h>
#include <fcl/narrowphase/distance_request.h>
#include <fcl/narrowphase/distance_result.h>

#include "convert.h"
#include "gq/fcl/collision.h"
#include "gq/query.h"

namespace gq::fcl::internal {

template <class S> using Isometry = Eigen::Transform<S, 3, Eigen::Isometry>;

// Done: answered. Invalid: bad input (a size or a linear part that is not a rotation): the call writes nothing.
// Unanswered: gq has no usable answer (half-space against half-space, GJK/EPA not converged): FCL answers.
enum class Answer : std::uint8_t { Done, Invalid, Unanswered };

// The FclShape of a geometry whose dynamic type is exactly one of FCL's common solid classes, from its type_info
// alone (no virtual call: a caller that needs none keeps no frame), else Unsupported (ask shapeOf). Equal type_info
// addresses prove the type; a host whose objects refer to another copy of a class's type_info only takes shapeOf.
// Convex first: its pairs run the longest chain of work after classification and are the closest to their speed
// target; a primitive pays one compare more.
template <class S> FclShape commonSolidOf(const std::type_info& type) {
  if (&type == &typeid(::fcl::Convex<S>)) return FclShape::Convex;
  if (&type == &typeid(::fcl::Sphere<S>)) return FclShape::Sphere;
  if (&type == &typeid(::fcl::Box<S>)) return FclShape::Box;
  if (&type == &typeid(::fcl::Capsule<S>)) return FclShape::Capsule;
  if (&type == &typeid(::fcl::Cylinder<S>)) return FclShape::Cylinder;
  return FclShape::Unsupported;
}

// The FclShape of an FCL geometry (null: Unsupported): a common solid from its type_info, the rest from its node type
// (a virtual call). Inline: every call asks it twice.
template <class S> FclShape shapeOf(const ::fcl::CollisionGeometry<S>* geometry) {
  using FS = FclShape;
  // Indexed by FCL's NODE_TYPE: BV_UNKNOWN, the eight BVHModel bounding volumes, then the shapes in FCL's order.
  static constexpr FS kShapeOf[::fcl::NODE_COUNT] = {
      FS::Unsupported, FS::Mesh,      FS::Mesh,   FS::Mesh,     FS::Mesh,  FS::Mesh,     FS::Mesh,
      FS::Mesh,        FS::Mesh,      FS::Box,    FS::Sphere,   FS::Ellipsoid, FS::Capsule, FS::Cone,
      FS::Cylinder,    FS::Convex,    FS::Plane,  FS::Halfspace, FS::TriangleP, FS::Unsupported};
  static_assert(::fcl::GEOM_BOX == 9 && ::fcl::GEOM_TRIANGLE == 18 && ::fcl::NODE_COUNT == 20, "FCL 0.7's NODE_TYPE");
  if (!geometry) return FS::Unsupported;
  if (const FS common = commonSolidOf<S>(typeid(*geometry)); common != FS::Unsupported) return common;
  const int type = geometry->getNodeType();
  return type >= 0 && type < ::fcl::NODE_COUNT ? kShapeOf[type] : FS::Unsupported;
}
inline bool isSolid(FclShape s) { return s <= FclShape::Halfspace && s != FclShape::Unsupported; }

// One side of a query: an FCL geometry and its pose (two pointers: passed by value, in registers). The table is
// indexed by the two sides' shapeOf; each entry knows its shapes.
template <class S> struct Solid {
  const ::fcl::CollisionGeometry<S>* geometry;
  const Isometry<S>* tf;
};

// What a distance request asks for: the world witnesses (enable_nearest_points), the penetration depth
// (enable_signed_distance) and GJK's stop tolerance (DistanceRequest::distance_tolerance as the host set it; only
// the pairs that run GJK read it, and a non-positive or non-finite one means gq's own), and the distance to beat
// (the result's min_distance: a GJK pair proven farther may stop with a lower bound above it, which FCL's update
// then ignores; the closed forms answer exactly anyway).
struct DistanceAsk {
  bool points;
  bool depth;
  double tolerance = 0;
  double farEnough = std::numeric_limits<double>::infinity();  // the result's min_distance, exact in S
};

// The distance a pair must beat to change an FCL result of this min_distance: itself, or +inf for FCL's unseeded
// max() (as a finite bound it made GJK test its lower bounds for nothing: convex30 distance +1.6 % instructions).
template <class S> S distanceToBeat(S minDistance) {
  return minDistance < std::numeric_limits<S>::max() ? minDistance : std::numeric_limits<S>::infinity();
}

// Whether FCL 0.7 (GJKSolver_libccd) computes this pair's contact with a closed form, where gq's exact answer is
// the same: sphere against sphere/capsule/box/cylinder/BVHModel triangles, and the shapes it has a half-space or
// plane formula for. Every other pair goes through libccd's MPR (or, box-box, FCL's box routine).
constexpr bool fclContactIsClosedForm(FclShape a, FclShape b) {
  const auto either = [a, b](FclShape x) { return a == x || b == x; };
  const FclShape other = a == FclShape::Sphere ? b : a;
  if (either(FclShape::Sphere))
    return other == FclShape::Sphere || other == FclShape::Capsule || other == FclShape::Box ||
           other == FclShape::Cylinder || other == FclShape::Mesh || other == FclShape::Halfspace ||
           other == FclShape::Plane;
  const bool halfspace = either(FclShape::Halfspace), plane = either(FclShape::Plane);
  if (!halfspace && !plane) return false;
  const FclShape shape = (a == FclShape::Halfspace || a == FclShape::Plane) ? b : a;
  return shape == FclShape::Ellipsoid || shape == FclShape::Box || shape == FclShape::Capsule ||
         shape == FclShape::Cylinder || shape == FclShape::Cone || shape == FclShape::Mesh ||
         (halfspace && shape == FclShape::Convex);
}

// Contacts that stay FCL's own unless a correction is opted into (see Options).
constexpr bool contactFromFcl(FclShape a, FclShape b, Options options) {
  if (options.minimumTranslation) return false;
  if (a == FclShape::Box && b == FclShape::Box) return !options.exactContainedBoxDepth;
  return !fclContactIsClosedForm(a, b);
}

// FCL's CollisionRequest::isSatisfied on the result's count `before`: no cost sources, a collision, and
// num_max_contacts reached (collide then computes nothing and returns the count).
template <class S> bool satisfiedBy(const ::fcl::CollisionRequest<S>& request, std::size_t before) {
  return !request.enable_cost && before > 0 && request.num_max_contacts <= before;
}

// Everything of gq::fcl::collide off the solid fast path (collide.cpp): meshes and two-sided planes (gq), FCL's own
// contacts (`fclContact`), cost sources and what gq does not model (FCL).
template <class S>
std::size_t collideOthers(const ::fcl::CollisionGeometry<S>* o1, const ::fcl::Transform3<S>& tf1,
                          const ::fcl::CollisionGeometry<S>* o2, const ::fcl::Transform3<S>& tf2,
                          const ::fcl::CollisionRequest<S>& request, ::fcl::CollisionResult<S>& result,
                          bool fclContact);

// The table of solid pairs (solid_pairs.cpp): per ordered pair, the whole of gq::fcl::collide and of
// gq::fcl::distance for it (FCL's request and result semantics; FCL itself answers what gq leaves unanswered). The
// public calls jump here once they know both shapes: the pair's kernel is inline in its entry (no second call, no
// result copied in between). Declared here so that both calls index it inline (an out-of-line lookup cost each
// call ~5 instructions).
// The entries take each side as its two pointers: given two Solid values, GCC stored their register halves on the
// stack and copied them on as 16-byte loads for the kernels' calls, a failed store forward each (collide
// sphere-sphere 15 -> 24 ns, sphere-box 22 -> 33 ns).
template <class S> using FclGeometry = ::fcl::CollisionGeometry<S>;
template <class S> struct PairEntry {
  std::size_t (*fclCollide)(const FclGeometry<S>*, const Isometry<S>*, const FclGeometry<S>*, const Isometry<S>*,
                            const ::fcl::CollisionRequest<S>&, ::fcl::CollisionResult<S>&, Options);
  S (*fclDistance)(const FclGeometry<S>*, const Isometry<S>*, const FclGeometry<S>*, const Isometry<S>*,
                   const ::fcl::DistanceRequest<S>&, ::fcl::DistanceResult<S>&);
};
inline constexpr std::size_t kSolids = std::size_t(FclShape::Halfspace) + 1;
template <class S> struct SolidPairs {
  static const std::array<PairEntry<S>, kSolids * kSolids> table;
};
extern template struct SolidPairs<float>;
extern template struct SolidPairs<double>;

template <class S> const PairEntry<S>& solidPair(FclShape a, FclShape b) {
  return SolidPairs<S>::table[std::size_t(a) * kSolids + std::size_t(b)];
}

// gq::fcl::collide on two solids (isSolid both). The transforms are validated in the entry (bad input: nothing
// written, 0 returned); a miss writes nothing, as bad input must not: the closed-form pairs validate only before
// reporting a hit, or on a miss too when the result already holds contacts (their count is returned then).
template <class S>
inline std::size_t solidFclCollide(FclShape sa, Solid<S> a, FclShape sb, Solid<S> b,
                                   const ::fcl::CollisionRequest<S>& request, ::fcl::CollisionResult<S>& result,
                                   Options options) {
  return solidPair<S>(sa, sb).fclCollide(a.geometry, a.tf, b.geometry, b.tf, request, result, options);
}

// FCL 0.7's contact of a sphere, box, capsule, cylinder or cone crossing a two-sided Plane n.x = d (world normal and
// offset; solid_pairs.cpp): `position` on the plane by FCL's per-shape rule; `normal` (from the solid to the plane,
// gq's exact one on entry, `depth` deep) turned to FCL's side where both sides are equally deep to rounding (a
// symmetric tie). False for another shape (nothing changed).
template <class S>
bool fclPlaneContact(FclShape shape, Solid<S> solid, const Vec3<S>& n, S d, S depth, Vec3<S>& position,
                     Vec3<S>& normal);

// gq::fcl::distance on two solids. Signed distance, normal from a to b. Without enable_signed_distance, a pair whose
// depth needs EPA (a converted side other than a plane) or a witness search (two boxes) answers FCL's -1 when the
// shapes overlap; other closed-form pairs keep their exact signed distance, which costs nothing more.
template <class S>
inline S solidFclDistance(FclShape sa, Solid<S> a, FclShape sb, Solid<S> b, const ::fcl::DistanceRequest<S>& request,
                          ::fcl::DistanceResult<S>& result) {
  return solidPair<S>(sa, sb).fclDistance(a.geometry, a.tf, b.geometry, b.tf, request, result);
}

}  // namespace gq::fcl::internal
