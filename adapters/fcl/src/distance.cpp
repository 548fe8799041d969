// gq::fcl::distance: FCL's distance semantics answered by gq (see gq/fcl/collision.h).
//  - DistanceResult::update keeps the smaller distance (pre-seeded results stay when the pair is farther);
//  - a result already at min_distance <= 0 is satisfied: nothing is computed (as FCL's isSatisfied);
//  - shapes: the signed distance with enable_signed_distance. Without it (FCL: the penetrating value is
//    "implementation defined", mostly -1) closed-form pairs (sphere and capsule against sphere, capsule or box,
//    sphere-cylinder, and against a plane or half-space) still give the exact signed distance, which costs them
//    nothing more, and GJK pairs and two boxes answer FCL's -1 with nearest points at the origin when they overlap
//    (no EPA, no witness search); nearest points (world frame) are written when enable_nearest_points is set, and
//    always for BVHModel and plane pairs;
//  - BVHModel sides are thin surfaces: 0 when touching or crossing; with enable_signed_distance the deepest
//    triangle contact's depth is reported negated, with both nearest points at its position (FCL's workaround).
#include <algorithm>
#include <limits>
#include <vector>

#include "convert.h"
#include "fallback.h"
#include "fcl_tree.h"
#include "gq/fcl/collision.h"
#include "mesh_fitting.h"
#include "pair_kernels.h"
#include "solid_pairs.h"

namespace gq::fcl {
namespace {

// FCL's signed distance for pairs with a BVHModel: minus the deepest contact's depth, witnesses at its position.
template <class S>
Status deepestContact(const internal::Converted<S>& a, const Transform<S>& pa, const internal::Converted<S>& b,
                      const Transform<S>& pb, internal::PairDistance<S>& d) {
  thread_local std::vector<internal::PairContact<S>> contacts;
  contacts.clear();
  const Status s = internal::pairContacts(a, pa, b, pb, true, std::numeric_limits<std::size_t>::max(), contacts);
  if (!s.ok() || contacts.empty()) return s;
  const auto deepest = std::max_element(contacts.begin(), contacts.end(),
                                        [](const auto& x, const auto& y) { return x.depth < y.depth; });
  d.distance = -deepest->depth;
  d.point1 = d.point2 = deepest->position;
  d.b1 = deepest->b1;
  d.b2 = deepest->b2;
  return s;
}

// One side a BVHModel, the other a closed solid (not a plane, half-space or BVHModel).
template <class S> bool meshAgainstSolid(const internal::Converted<S>& a, const internal::Converted<S>& b) {
  const auto solid = [](const internal::Converted<S>& c) { return c.isSolid() && !c.isPlaneLike(); };
  return (a.isMesh() && solid(b)) || (solid(a) && b.isMesh());
}

// FCL's DistanceRequest::isSatisfied, on the result's public field as FCL 0.7 defines it (the library's out-of-line
// copy costs a call on the fast path).
template <class S> bool satisfied(const ::fcl::DistanceResult<S>& result) { return result.min_distance <= S(0); }

// Everything but two solids: meshes, planes and what gq does not model.
template <class S>
[[gnu::noinline]] S distanceOthers(const ::fcl::CollisionGeometry<S>* o1, const ::fcl::Transform3<S>& tf1,
                                   const ::fcl::CollisionGeometry<S>* o2, const ::fcl::Transform3<S>& tf2,
                                   const ::fcl::DistanceRequest<S>& request, ::fcl::DistanceResult<S>& result) {
  using internal::Conversion;
  constexpr S kNothing = std::numeric_limits<S>::max();
  if (!internal::isFiniteTransforms(tf1, tf2)) return kNothing;
  internal::Converted<S> a, b;
  Conversion ca = internal::convert(o1, a, internal::MeshUse::TreeAllowed);
  Conversion cb = internal::convert(o2, b, internal::MeshUse::TreeAllowed);
  if (ca == Conversion::Invalid || cb == Conversion::Invalid) return kNothing;
  if ((a.isTree() || b.isTree()) && !internal::treeAgainstSolid(a, b))
    ca = internal::convert(o1, a), cb = internal::convert(o2, b);
  if (!internal::rotationUsable(a, tf1) || !internal::rotationUsable(b, tf2)) return kNothing;
  const Transform<S> pa = internal::shapePose(a, tf1), pb = internal::shapePose(b, tf2);
  if (ca == Conversion::NotModelled || cb == Conversion::NotModelled)
    return internal::fclDistance(o1, tf1, o2, tf2, request, result);
  internal::PairDistance<S> d;
  // The result's min_distance as the bound: a pair proven farther changes nothing (FCL prunes its BVH traversal so).
  Status s = internal::pairDistance(a, pa, b, pb, d, internal::distanceToBeat(result.min_distance));
  if (s.ok() && (a.isMesh() || b.isMesh()) && d.distance <= S(0) && request.enable_signed_distance)
    s = deepestContact(a, pa, b, pb, d);
  if (s.code == StatusCode::InvalidArgument) return kNothing;
  // FCL 0.7 crashes on these (libccd's GJK calls a null support function for Halfspace/Plane): nothing written.
  if (!s.ok() && (a.isPlaneLike() || b.isPlaneLike())) return kNothing;
  if (!s.ok()) return internal::fclDistance(o1, tf1, o2, tf2, request, result);
  // A BVHModel reaching a solid shape without enable_signed_distance: FCL's -1 with its GJK's points at the origin
  // (FCL's mesh-shape traversal runs GJK per triangle), so the answer does not depend on which path gave it.
  if (!request.enable_signed_distance && d.distance <= S(0) && meshAgainstSolid(a, b)) {
    d.distance = S(-1);
    d.point1 = d.point2 = ::fcl::Vector3<S>::Zero();
  }
  internal::countGq();
  result.update(d.distance, o1, o2, d.b1, d.b2, d.point1, d.point2);
  return result.min_distance;
}

// Shapes classified by their node types (virtual calls): a pair that is not two common solids.
template <class S>
[[gnu::noinline]] S distanceClassified(const ::fcl::CollisionGeometry<S>* o1, const ::fcl::Transform3<S>& tf1,
                                       const ::fcl::CollisionGeometry<S>* o2, const ::fcl::Transform3<S>& tf2,
                                       const ::fcl::DistanceRequest<S>& request, ::fcl::DistanceResult<S>& result) {
  const internal::FclShape s1 = internal::shapeOf(o1), s2 = internal::shapeOf(o2);
  if (internal::isSolid(s1) && internal::isSolid(s2))
    return internal::solidFclDistance(s1, internal::Solid<S>{o1, &tf1}, s2, internal::Solid<S>{o2, &tf2}, request, result);
  return distanceOthers(o1, tf1, o2, tf2, request, result);
}

// The whole of distance; each public overload is this function. Bad input writes nothing and returns what FCL
// returns for a pair it cannot answer (docs/fcl.md). Two common solids jump to their pair's entry without a call.
template <class S>
[[gnu::always_inline]] inline S distancePair(const ::fcl::CollisionGeometry<S>* o1, const ::fcl::Transform3<S>& tf1,
                                             const ::fcl::CollisionGeometry<S>* o2, const ::fcl::Transform3<S>& tf2,
                                             const ::fcl::DistanceRequest<S>& request,
                                             ::fcl::DistanceResult<S>& result) {
  if (satisfied(result)) return result.min_distance;  // request.isSatisfied(result)
  if (o1 && o2) {
    const internal::FclShape s1 = internal::commonSolidOf<S>(typeid(*o1)), s2 = internal::commonSolidOf<S>(typeid(*o2));
    if (s1 != internal::FclShape::Unsupported && s2 != internal::FclShape::Unsupported)
      return internal::solidFclDistance(s1, internal::Solid<S>{o1, &tf1}, s2, internal::Solid<S>{o2, &tf2}, request, result);
  }
  return distanceClassified(o1, tf1, o2, tf2, request, result);
}

}  // namespace

template <typename S>
S distance(const ::fcl::CollisionGeometry<S>* o1, const ::fcl::Transform3<S>& tf1,
           const ::fcl::CollisionGeometry<S>* o2, const ::fcl::Transform3<S>& tf2,
           const ::fcl::DistanceRequest<S>& request, ::fcl::DistanceResult<S>& result) {
  return distancePair(o1, tf1, o2, tf2, request, result);
}

template <typename S>
S distance(const ::fcl::CollisionObject<S>* o1, const ::fcl::CollisionObject<S>* o2,
           const ::fcl::DistanceRequest<S>& request, ::fcl::DistanceResult<S>& result) {
  if (!o1 || !o2) return std::numeric_limits<S>::max();  // bad input: nothing written
  return distancePair(o1->collisionGeometry().get(), o1->getTransform(), o2->collisionGeometry().get(),
                      o2->getTransform(), request, result);
}

template <typename S>
S distance(const ::fcl::CollisionObject<S>* o1, const ::fcl::CollisionObject<S>* o2,
           const ::fcl::DistanceRequest<S>& request, ::fcl::DistanceResult<S>& result, const Options& options) {
  if (options.meshFitting && o1 && o2)
    return internal::distanceFitted(o1->collisionGeometry().get(), o1->getTransform(), o2->collisionGeometry().get(),
                                    o2->getTransform(), request, result, options);
  return distance(o1, o2, request, result);
}

template <typename S>
S distance(const ::fcl::CollisionGeometry<S>* o1, const ::fcl::Transform3<S>& tf1,
           const ::fcl::CollisionGeometry<S>* o2, const ::fcl::Transform3<S>& tf2,
           const ::fcl::DistanceRequest<S>& request, ::fcl::DistanceResult<S>& result, const Options& options) {
  if (options.meshFitting) return internal::distanceFitted(o1, tf1, o2, tf2, request, result, options);
  return distancePair(o1, tf1, o2, tf2, request, result);
}

template float distance<float>(const ::fcl::CollisionObject<float>*, const ::fcl::CollisionObject<float>*,
                               const ::fcl::DistanceRequest<float>&, ::fcl::DistanceResult<float>&, const Options&);
template double distance<double>(const ::fcl::CollisionObject<double>*, const ::fcl::CollisionObject<double>*,
                                 const ::fcl::DistanceRequest<double>&, ::fcl::DistanceResult<double>&,
                                 const Options&);
template float distance<float>(const ::fcl::CollisionGeometry<float>*, const ::fcl::Transform3<float>&,
                               const ::fcl::CollisionGeometry<float>*, const ::fcl::Transform3<float>&,
                               const ::fcl::DistanceRequest<float>&, ::fcl::DistanceResult<float>&, const Options&);
template double distance<double>(const ::fcl::CollisionGeometry<double>*, const ::fcl::Transform3<double>&,
                                 const ::fcl::CollisionGeometry<double>*, const ::fcl::Transform3<double>&,
                                 const ::fcl::DistanceRequest<double>&, ::fcl::DistanceResult<double>&,
                                 const Options&);
template float distance<float>(const ::fcl::CollisionObject<float>*, const ::fcl::CollisionObject<float>*,
                               const ::fcl::DistanceRequest<float>&, ::fcl::DistanceResult<float>&);
template double distance<double>(const ::fcl::CollisionObject<double>*, const ::fcl::CollisionObject<double>*,
                                 const ::fcl::DistanceRequest<double>&, ::fcl::DistanceResult<double>&);
template float distance<float>(const ::fcl::CollisionGeometry<float>*, const ::fcl::Transform3<float>&,
                               const ::fcl::CollisionGeometry<float>*, const ::fcl::Transform3<float>&,
                               const ::fcl::DistanceRequest<float>&, ::fcl::DistanceResult<float>&);
template double distance<double>(const ::fcl::CollisionGeometry<double>*, const ::fcl::Transform3<double>&,
                                 const ::fcl::CollisionGeometry<double>*, const ::fcl::Transform3<double>&,
                                 const ::fcl::DistanceRequest<double>&, ::fcl::DistanceResult<double>&);

}  // namespace gq::fcl
