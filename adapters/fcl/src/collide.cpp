// gq::fcl::collide: FCL's collide semantics answered by gq (see gq/fcl/collision.h).
#include <algorithm>
#include <vector>

#include "convert.h"
#include "fallback.h"
#include "gq/fcl/collision.h"
#include "pair_kernels.h"
#include "solid_pairs.h"

namespace gq::fcl {
namespace {

using detail::FclShape;

bool either(FclShape a, FclShape b, FclShape x) { return a == x || b == x; }
bool pairIs(FclShape a, FclShape b, FclShape x, FclShape y) { return (a == x && b == y) || (a == y && b == x); }

// Whether FCL 0.7 (GJKSolver_libccd) computes this pair's contact with a closed form, where gq's exact answer is
// the same: sphere against sphere/capsule/box/cylinder/BVHModel triangles, and the shapes it has a half-space or
// plane formula for. Every other pair goes through libccd's MPR (or, box-box, FCL's box routine).
bool fclContactIsClosedForm(FclShape a, FclShape b) {
  const FclShape other = a == FclShape::Sphere ? b : a;
  if (either(a, b, FclShape::Sphere))
    return other == FclShape::Sphere || other == FclShape::Capsule || other == FclShape::Box ||
           other == FclShape::Cylinder || other == FclShape::Mesh || other == FclShape::Halfspace ||
           other == FclShape::Plane;
  const bool halfspace = either(a, b, FclShape::Halfspace), plane = either(a, b, FclShape::Plane);
  if (!halfspace && !plane) return false;
  const FclShape shape = (a == FclShape::Halfspace || a == FclShape::Plane) ? b : a;
  return shape == FclShape::Ellipsoid || shape == FclShape::Box || shape == FclShape::Capsule ||
         shape == FclShape::Cylinder || shape == FclShape::Cone || shape == FclShape::Mesh ||
         (halfspace && shape == FclShape::Convex);
}

// Contacts that stay FCL's own unless a correction is opted into (see Options).
bool contactFromFcl(FclShape a, FclShape b, Options options) {
  if (options.minimumTranslation) return false;
  if (pairIs(a, b, FclShape::Box, FclShape::Box)) return !options.exactContainedBoxDepth;
  return !fclContactIsClosedForm(a, b);
}

// Two closed solids, the fast path (solid_pairs.h): at most one contact, no buffer; contact geometry only when
// asked for. With `resultHeldContacts` a miss returns their count and bad input 0: the table must tell them apart.
template <class S>
[[gnu::always_inline]] inline detail::Answer collideSolids(detail::FclShape sa, detail::Solid<S> a, detail::FclShape sb,
                                                          detail::Solid<S> b, bool withContact,
                                                          bool resultHeldContacts, bool& added,
                                                          ::fcl::CollisionResult<S>& result) {
  if (!withContact) {
    const detail::Answer answer = detail::solidOverlap(sa, a, sb, b, resultHeldContacts, added);
    if (answer == detail::Answer::Done && added)
      result.addContact(::fcl::Contact<S>(a.geometry, b.geometry, detail::kNoPrimitive, detail::kNoPrimitive));
    return answer;
  }
  DistanceResult<S> d;
  const detail::Answer answer = detail::solidDistance(sa, a, sb, b, detail::DistanceAsk{true, true}, d);
  added = answer == detail::Answer::Done && d.distance <= S(0);
  if (added)
    result.addContact(::fcl::Contact<S>(a.geometry, b.geometry, detail::kNoPrimitive, detail::kNoPrimitive,
                                        (d.point0 + d.point1) * S(0.5), d.normal, -d.distance));
  return answer;
}

// Meshes and two-sided planes: one contact per primitive (pair), gathered in a per-thread buffer.
template <class S>
bool collideGeneral(const ::fcl::CollisionGeometry<S>* o1, const detail::Converted<S>& a, const Transform<S>& pa,
                    const ::fcl::CollisionGeometry<S>* o2, const detail::Converted<S>& b, const Transform<S>& pb,
                    const ::fcl::CollisionRequest<S>& request, ::fcl::CollisionResult<S>& result) {
  thread_local std::vector<detail::PairContact<S>> contacts;
  contacts.clear();
  const std::size_t room = request.num_max_contacts - std::min(request.num_max_contacts, result.numContacts());
  if (!detail::pairContacts(a, pa, b, pb, request.enable_contact, room, contacts).ok()) return false;
  for (const detail::PairContact<S>& c : contacts) {
    if (result.numContacts() >= request.num_max_contacts) break;
    if (request.enable_contact)
      result.addContact(::fcl::Contact<S>(o1, o2, c.b1, c.b2, c.position, c.normal, c.depth));
    else
      result.addContact(::fcl::Contact<S>(o1, o2, c.b1, c.b2));
  }
  return true;
}

// Everything off the solid fast path: meshes and two-sided planes (gq), FCL's own contacts, cost sources and what gq
// does not model (FCL). Out of line: the fast path's frame stays small (inline, its saved registers cost every call).
template <class S>
[[gnu::noinline]] std::size_t collideOthers(const ::fcl::CollisionGeometry<S>* o1, const ::fcl::Transform3<S>& tf1,
                                            const ::fcl::CollisionGeometry<S>* o2, const ::fcl::Transform3<S>& tf2,
                                            const ::fcl::CollisionRequest<S>& request,
                                            ::fcl::CollisionResult<S>& result, bool fclContact) {
  using detail::Conversion;
  if (!detail::isFiniteTransforms(tf1, tf2)) return 0;
  detail::Converted<S> a, b;
  const Conversion ca = detail::convert(o1, a), cb = detail::convert(o2, b);
  if (ca == Conversion::Invalid || cb == Conversion::Invalid) return 0;
  if (!detail::rotationUsable(a, tf1) || !detail::rotationUsable(b, tf2)) return 0;
  const Transform<S> pa = detail::shapePose(a, tf1), pb = detail::shapePose(b, tf2);
  if (ca == Conversion::NotModelled || cb == Conversion::NotModelled || request.enable_cost || fclContact ||
      (a.isSolid() && b.isSolid()))
    return detail::fclCollide(o1, tf1, o2, tf2, request, result);
  if (!collideGeneral(o1, a, pa, o2, b, pb, request, result))
    return detail::fclCollide(o1, tf1, o2, tf2, request, result);
  detail::countGq();
  return result.numContacts();
}

// The whole of collide; each public overload is this function (forced inline: GCC otherwise splits it in two calls).
template <class S>
[[gnu::always_inline]] inline std::size_t collidePair(const ::fcl::CollisionGeometry<S>* o1,
                                                     const ::fcl::Transform3<S>& tf1,
                                                     const ::fcl::CollisionGeometry<S>* o2,
                                                     const ::fcl::Transform3<S>& tf2,
                                                     const ::fcl::CollisionRequest<S>& request,
                                                     ::fcl::CollisionResult<S>& result, Options options) {
  if (request.num_max_contacts == 0) return 0;  // FCL: "should stop early", nothing computed
  // FCL's CollisionRequest::isSatisfied (no cost sources, a collision, num_max_contacts reached) on one count.
  const std::size_t before = result.numContacts();
  if (!request.enable_cost && before > 0 && request.num_max_contacts <= before) return before;
  // Bad input (docs/fcl.md) writes nothing and returns 0, before anything reaches FCL (which crashes on it); the
  // solid path validates the numbers it reads (solid_pairs.h), the others check the transforms (collideOthers).
  const detail::FclShape s1 = detail::shapeOf(o1), s2 = detail::shapeOf(o2);
  const bool fclContact = request.enable_contact && contactFromFcl(s1, s2, options);
  if (detail::isSolid(s1) && detail::isSolid(s2) && !request.enable_cost && !fclContact) {
    bool added = false;
    switch (collideSolids(s1, detail::Solid<S>{o1, &tf1}, s2, detail::Solid<S>{o2, &tf2}, request.enable_contact,
                          before > 0, added, result)) {
      case detail::Answer::Done: detail::countGq(); return before + added;
      case detail::Answer::Invalid: return 0;
      case detail::Answer::Unanswered: break;
    }
  }
  return collideOthers(o1, tf1, o2, tf2, request, result, fclContact);
}

}  // namespace

template <typename S>
std::size_t collide(const ::fcl::CollisionGeometry<S>* o1, const ::fcl::Transform3<S>& tf1,
                    const ::fcl::CollisionGeometry<S>* o2, const ::fcl::Transform3<S>& tf2,
                    const ::fcl::CollisionRequest<S>& request, ::fcl::CollisionResult<S>& result,
                    const Options& options) {
  return collidePair(o1, tf1, o2, tf2, request, result, options);
}

template <typename S>
std::size_t collide(const ::fcl::CollisionGeometry<S>* o1, const ::fcl::Transform3<S>& tf1,
                    const ::fcl::CollisionGeometry<S>* o2, const ::fcl::Transform3<S>& tf2,
                    const ::fcl::CollisionRequest<S>& request, ::fcl::CollisionResult<S>& result) {
  return collidePair(o1, tf1, o2, tf2, request, result, Options());
}

template <typename S>
std::size_t collide(const ::fcl::CollisionObject<S>* o1, const ::fcl::CollisionObject<S>* o2,
                    const ::fcl::CollisionRequest<S>& request, ::fcl::CollisionResult<S>& result) {
  if (!o1 || !o2) return 0;  // bad input: nothing written
  return collidePair(o1->collisionGeometry().get(), o1->getTransform(), o2->collisionGeometry().get(),
                     o2->getTransform(), request, result, Options());
}

template std::size_t collide<float>(const ::fcl::CollisionObject<float>*, const ::fcl::CollisionObject<float>*,
                                    const ::fcl::CollisionRequest<float>&, ::fcl::CollisionResult<float>&);
template std::size_t collide<double>(const ::fcl::CollisionObject<double>*, const ::fcl::CollisionObject<double>*,
                                     const ::fcl::CollisionRequest<double>&, ::fcl::CollisionResult<double>&);
template std::size_t collide<float>(const ::fcl::CollisionGeometry<float>*, const ::fcl::Transform3<float>&,
                                    const ::fcl::CollisionGeometry<float>*, const ::fcl::Transform3<float>&,
                                    const ::fcl::CollisionRequest<float>&, ::fcl::CollisionResult<float>&);
template std::size_t collide<double>(const ::fcl::CollisionGeometry<double>*, const ::fcl::Transform3<double>&,
                                     const ::fcl::CollisionGeometry<double>*, const ::fcl::Transform3<double>&,
                                     const ::fcl::CollisionRequest<double>&, ::fcl::CollisionResult<double>&);
template std::size_t collide<float>(const ::fcl::CollisionGeometry<float>*, const ::fcl::Transform3<float>&,
                                    const ::fcl::CollisionGeometry<float>*, const ::fcl::Transform3<float>&,
                                    const ::fcl::CollisionRequest<float>&, ::fcl::CollisionResult<float>&,
                                    const Options&);
template std::size_t collide<double>(const ::fcl::CollisionGeometry<double>*, const ::fcl::Transform3<double>&,
                                     const ::fcl::CollisionGeometry<double>*, const ::fcl::Transform3<double>&,
                                     const ::fcl::CollisionRequest<double>&, ::fcl::CollisionResult<double>&,
                                     const Options&);

template <typename S> void forgetGeometry(const ::fcl::CollisionGeometry<S>* geometry) { detail::forget(geometry); }
template void forgetGeometry<float>(const ::fcl::CollisionGeometry<float>*);
template void forgetGeometry<double>(const ::fcl::CollisionGeometry<double>*);
void clearGeometryCache() { detail::clearCache(); }

}  // namespace gq::fcl
