#include "fallback.h"

#include <algorithm>
#include <exception>
#include <vector>

#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>

#include "gq/fcl/collision.h"

namespace gq::fcl {

AdapterCounters adapterCounters() { return internal::tCounters; }
void resetAdapterCounters() { internal::tCounters = AdapterCounters(); }

namespace internal {
namespace {

// FCL 0.7 answers a shape (o1) against a BVHModel (o2) as the BVHModel against the shape and reports that order:
// Contact::o1/b1 name the model, the normal points from the model to the shape, nearest_points[0] lies on the model.
// gq keeps the caller's order on every path, so such a pair is asked in FCL's order and its answer turned back.
template <class S> bool answersSwapped(const ::fcl::CollisionGeometry<S>* o1, const ::fcl::CollisionGeometry<S>* o2) {
  return o1->getObjectType() == ::fcl::OT_GEOM && o2->getObjectType() == ::fcl::OT_BVH;
}

}  // namespace

// FCL reports its own errors on std::cerr and returns; an exception (rare: Eigen or allocation) must not cross the
// adapter's API, so it is swallowed and the result left as FCL left it.
template <class S>
std::size_t fclCollide(const ::fcl::CollisionGeometry<S>* o1, const ::fcl::Transform3<S>& tf1,
                       const ::fcl::CollisionGeometry<S>* o2, const ::fcl::Transform3<S>& tf2,
                       const ::fcl::CollisionRequest<S>& request, ::fcl::CollisionResult<S>& result) {
  countFallback();
  try {
    if (!answersSwapped(o1, o2)) return ::fcl::collide(o1, tf1, o2, tf2, request, result);
    ::fcl::CollisionRequest<S> room = request;
    room.num_max_contacts = request.num_max_contacts - std::min(request.num_max_contacts, result.numContacts());
    ::fcl::CollisionResult<S> swapped;
    if (room.num_max_contacts > 0) ::fcl::collide(o2, tf2, o1, tf1, room, swapped);
    for (std::size_t i = 0; i < swapped.numContacts(); ++i) {
      const ::fcl::Contact<S>& c = swapped.getContact(i);
      result.addContact(::fcl::Contact<S>(c.o2, c.o1, c.b2, c.b1, c.pos, -c.normal, c.penetration_depth));
    }
    if (request.enable_cost) {  // a cost source is a world box: the same whichever side comes first
      std::vector<::fcl::CostSource<S>> sources;
      swapped.getCostSources(sources);
      for (const ::fcl::CostSource<S>& c : sources) result.addCostSource(c, request.num_max_cost_sources);
    }
    return result.numContacts();
  } catch (const std::exception&) {
    return result.numContacts();
  }
}

template <class S>
S fclDistance(const ::fcl::CollisionGeometry<S>* o1, const ::fcl::Transform3<S>& tf1,
              const ::fcl::CollisionGeometry<S>* o2, const ::fcl::Transform3<S>& tf2,
              const ::fcl::DistanceRequest<S>& request, ::fcl::DistanceResult<S>& result) {
  countFallback();
  try {
    if (!answersSwapped(o1, o2)) return ::fcl::distance(o1, tf1, o2, tf2, request, result);
    ::fcl::DistanceResult<S> swapped;
    swapped.min_distance = result.min_distance;
    ::fcl::distance(o2, tf2, o1, tf1, request, swapped);
    if (swapped.min_distance < result.min_distance)
      result.update(swapped.min_distance, swapped.o2, swapped.o1, swapped.b2, swapped.b1, swapped.nearest_points[1],
                    swapped.nearest_points[0]);
    return result.min_distance;
  } catch (const std::exception&) {
    return result.min_distance;
  }
}

template std::size_t fclCollide<float>(const ::fcl::CollisionGeometry<float>*, const ::fcl::Transform3<float>&,
                                       const ::fcl::CollisionGeometry<float>*, const ::fcl::Transform3<float>&,
                                       const ::fcl::CollisionRequest<float>&, ::fcl::CollisionResult<float>&);
template std::size_t fclCollide<double>(const ::fcl::CollisionGeometry<double>*, const ::fcl::Transform3<double>&,
                                        const ::fcl::CollisionGeometry<double>*, const ::fcl::Transform3<double>&,
                                        const ::fcl::CollisionRequest<double>&, ::fcl::CollisionResult<double>&);
template float fclDistance<float>(const ::fcl::CollisionGeometry<float>*, const ::fcl::Transform3<float>&,
                                  const ::fcl::CollisionGeometry<float>*, const ::fcl::Transform3<float>&,
                                  const ::fcl::DistanceRequest<float>&, ::fcl::DistanceResult<float>&);
template double fclDistance<double>(const ::fcl::CollisionGeometry<double>*, const ::fcl::Transform3<double>&,
                                    const ::fcl::CollisionGeometry<double>*, const ::fcl::Transform3<double>&,
                                    const ::fcl::DistanceRequest<double>&, ::fcl::DistanceResult<double>&);

}  // namespace internal
}  // namespace gq::fcl
