// gq::fcl::collide: FCL's collide semantics answered by gq (see gq/fcl/collision.h).
#include <algorithm>
#include <vector>

#include <fcl/geometry/shape/plane.h>

#include "convert.h"
#include "fallback.h"
#include "fcl_tree.h"
#include "gq/fcl/collision.h"
#include "mesh_fitting.h"
#include "pair_kernels.h"
#include "solid_pairs.h"

namespace gq::fcl {
namespace {

// A solid against a two-sided Plane: the contact placed on the plane by FCL's rule for the solid, and on a
// symmetric tie FCL's side (gq's depth is exact and FCL's; the position and the side of a tie are FCL's choice).
template <class S>
void placeOnPlane(const ::fcl::CollisionGeometry<S>* o1, const ::fcl::Transform3<S>& tf1, internal::FclShape s1,
                  const ::fcl::CollisionGeometry<S>* o2, const ::fcl::Transform3<S>& tf2, internal::FclShape s2,
                  internal::PairContact<S>& contact) {
  const bool planeFirst = s1 == internal::FclShape::Plane;
  const auto* plane = static_cast<const ::fcl::Plane<S>*>(planeFirst ? o1 : o2);
  // The world plane as FCL forms it (renormalised), so that a tie is decided on FCL's rounded numbers.
  const ::fcl::Plane<S> world = ::fcl::transform(*plane, planeFirst ? tf1 : tf2);
  const Vec3<S> n = world.n;
  const S d = world.d;
  const internal::Solid<S> solid{planeFirst ? o2 : o1, planeFirst ? &tf2 : &tf1};
  Vec3<S> normal = planeFirst ? Vec3<S>(-contact.normal) : contact.normal;  // from the solid to the plane
  if (internal::fclPlaneContact(planeFirst ? s2 : s1, solid, n, d, contact.depth, contact.position, normal))
    contact.normal = planeFirst ? Vec3<S>(-normal) : normal;
}

// Meshes and two-sided planes: one contact per primitive (pair), gathered in a per-thread buffer.
template <class S>
bool collideGeneral(const ::fcl::CollisionGeometry<S>* o1, const ::fcl::Transform3<S>& tf1,
                    const internal::Converted<S>& a, const Transform<S>& pa, const ::fcl::CollisionGeometry<S>* o2,
                    const ::fcl::Transform3<S>& tf2, const internal::Converted<S>& b, const Transform<S>& pb,
                    const ::fcl::CollisionRequest<S>& request, ::fcl::CollisionResult<S>& result) {
  thread_local std::vector<internal::PairContact<S>> contacts;
  contacts.clear();
  const std::size_t room = request.num_max_contacts - std::min(request.num_max_contacts, result.numContacts());
  if (!internal::pairContacts(a, pa, b, pb, request.enable_contact, room, contacts).ok()) return false;
  const bool solidPlane = (a.shape == internal::FclShape::Plane && b.isSolid()) ||
                          (b.shape == internal::FclShape::Plane && a.isSolid());
  if (solidPlane && request.enable_contact)
    for (internal::PairContact<S>& c : contacts) placeOnPlane(o1, tf1, a.shape, o2, tf2, b.shape, c);
  for (const internal::PairContact<S>& c : contacts) {
    if (result.numContacts() >= request.num_max_contacts) break;
    if (request.enable_contact)
      result.addContact(::fcl::Contact<S>(o1, o2, c.b1, c.b2, c.position, c.normal, c.depth));
    else
      result.addContact(::fcl::Contact<S>(o1, o2, c.b1, c.b2));
  }
  return true;
}

// Shapes classified by their node types (virtual calls): a pair that is not two common solids. Out of line: the
// public entry stays a classification and a jump.
template <class S>
[[gnu::noinline]] std::size_t collideClassified(const ::fcl::CollisionGeometry<S>* o1, const ::fcl::Transform3<S>& tf1,
                                                const ::fcl::CollisionGeometry<S>* o2, const ::fcl::Transform3<S>& tf2,
                                                const ::fcl::CollisionRequest<S>& request,
                                                ::fcl::CollisionResult<S>& result, Options options) {
  const internal::FclShape s1 = internal::shapeOf(o1), s2 = internal::shapeOf(o2);
  if (internal::isSolid(s1) && internal::isSolid(s2))
    return internal::solidFclCollide(s1, internal::Solid<S>{o1, &tf1}, s2, internal::Solid<S>{o2, &tf2}, request, result,
                                   options);
  if (request.num_max_contacts == 0) return 0;  // FCL: "should stop early", nothing computed
  const std::size_t before = result.numContacts();
  if (internal::satisfiedBy(request, before)) return before;
  return internal::collideOthers(o1, tf1, o2, tf2, request, result,
                               request.enable_contact && internal::contactFromFcl(s1, s2, options));
}

// The whole of collide; each public overload is this function. Bad input (docs/fcl.md) writes nothing and returns
// 0, before anything reaches FCL (which crashes on it): the solid entries validate the numbers they read
// (solid_pairs.h), the others check the transforms (collideOthers). Two common solids jump to their pair's entry
// without a call of their own.
template <class S>
[[gnu::always_inline]] inline std::size_t collidePair(const ::fcl::CollisionGeometry<S>* o1,
                                                     const ::fcl::Transform3<S>& tf1,
                                                     const ::fcl::CollisionGeometry<S>* o2,
                                                     const ::fcl::Transform3<S>& tf2,
                                                     const ::fcl::CollisionRequest<S>& request,
                                                     ::fcl::CollisionResult<S>& result, Options options) {
  if (o1 && o2) {
    const internal::FclShape s1 = internal::commonSolidOf<S>(typeid(*o1)), s2 = internal::commonSolidOf<S>(typeid(*o2));
    if (s1 != internal::FclShape::Unsupported && s2 != internal::FclShape::Unsupported)
      return internal::solidFclCollide(s1, internal::Solid<S>{o1, &tf1}, s2, internal::Solid<S>{o2, &tf2}, request, result,
                                     options);
  }
  return collideClassified(o1, tf1, o2, tf2, request, result, options);
}

}  // namespace

namespace internal {

// Out of line (see solid_pairs.h): the fast path's frame stays small.
template <class S>
[[gnu::noinline]] std::size_t collideOthers(const ::fcl::CollisionGeometry<S>* o1, const ::fcl::Transform3<S>& tf1,
                                            const ::fcl::CollisionGeometry<S>* o2, const ::fcl::Transform3<S>& tf2,
                                            const ::fcl::CollisionRequest<S>& request,
                                            ::fcl::CollisionResult<S>& result, bool fclContact) {
  if (!isFiniteTransforms(tf1, tf2)) return 0;
  Converted<S> a, b;
  Conversion ca = convert(o1, a, MeshUse::TreeAllowed), cb = convert(o2, b, MeshUse::TreeAllowed);
  if (ca == Conversion::Invalid || cb == Conversion::Invalid) return 0;
  if ((a.isTree() || b.isTree()) && !treeAgainstSolid(a, b)) ca = convert(o1, a), cb = convert(o2, b);
  if (!rotationUsable(a, tf1) || !rotationUsable(b, tf2)) return 0;
  const Transform<S> pa = shapePose(a, tf1), pb = shapePose(b, tf2);
  if (ca == Conversion::NotModelled || cb == Conversion::NotModelled || request.enable_cost || fclContact ||
      (a.isSolid() && b.isSolid()))
    return fclCollide(o1, tf1, o2, tf2, request, result);
  if (!collideGeneral(o1, tf1, a, pa, o2, tf2, b, pb, request, result))
    return fclCollide(o1, tf1, o2, tf2, request, result);
  countGq();
  return result.numContacts();
}
template std::size_t collideOthers<float>(const ::fcl::CollisionGeometry<float>*, const ::fcl::Transform3<float>&,
                                          const ::fcl::CollisionGeometry<float>*, const ::fcl::Transform3<float>&,
                                          const ::fcl::CollisionRequest<float>&, ::fcl::CollisionResult<float>&, bool);
template std::size_t collideOthers<double>(const ::fcl::CollisionGeometry<double>*, const ::fcl::Transform3<double>&,
                                           const ::fcl::CollisionGeometry<double>*, const ::fcl::Transform3<double>&,
                                           const ::fcl::CollisionRequest<double>&, ::fcl::CollisionResult<double>&,
                                           bool);

}  // namespace internal

template <typename S>
std::size_t collide(const ::fcl::CollisionGeometry<S>* o1, const ::fcl::Transform3<S>& tf1,
                    const ::fcl::CollisionGeometry<S>* o2, const ::fcl::Transform3<S>& tf2,
                    const ::fcl::CollisionRequest<S>& request, ::fcl::CollisionResult<S>& result,
                    const Options& options) {
  if (options.meshFitting) return internal::collideFitted(o1, tf1, o2, tf2, request, result, options);
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

template <typename S>
std::size_t collide(const ::fcl::CollisionObject<S>* o1, const ::fcl::CollisionObject<S>* o2,
                    const ::fcl::CollisionRequest<S>& request, ::fcl::CollisionResult<S>& result,
                    const Options& options) {
  if (!o1 || !o2) return 0;  // bad input: nothing written
  if (options.meshFitting)
    return internal::collideFitted(o1->collisionGeometry().get(), o1->getTransform(), o2->collisionGeometry().get(),
                                   o2->getTransform(), request, result, options);
  return collidePair(o1->collisionGeometry().get(), o1->getTransform(), o2->collisionGeometry().get(),
                     o2->getTransform(), request, result, options);
}

template std::size_t collide<float>(const ::fcl::CollisionObject<float>*, const ::fcl::CollisionObject<float>*,
                                    const ::fcl::CollisionRequest<float>&, ::fcl::CollisionResult<float>&,
                                    const Options&);
template std::size_t collide<double>(const ::fcl::CollisionObject<double>*, const ::fcl::CollisionObject<double>*,
                                     const ::fcl::CollisionRequest<double>&, ::fcl::CollisionResult<double>&,
                                     const Options&);
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

template <typename S> void forgetGeometry(const ::fcl::CollisionGeometry<S>* geometry) {
  internal::forget(geometry);
  internal::forgetFits(geometry);
}
template void forgetGeometry<float>(const ::fcl::CollisionGeometry<float>*);
template void forgetGeometry<double>(const ::fcl::CollisionGeometry<double>*);
void clearGeometryCache() {
  internal::clearCache();
  internal::clearFits();
}

}  // namespace gq::fcl
