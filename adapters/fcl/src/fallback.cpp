#include "fallback.h"

#include <exception>

#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>

#include "gq/fcl/collision.h"

namespace gq::fcl {

AdapterCounters adapterCounters() { return internal::tCounters; }
void resetAdapterCounters() { internal::tCounters = AdapterCounters(); }

namespace internal {

// FCL reports its own errors on std::cerr and returns; an exception (rare: Eigen or allocation) must not cross the
// adapter's API, so it is swallowed and the result left as FCL left it.
template <class S>
std::size_t fclCollide(const ::fcl::CollisionGeometry<S>* o1, const ::fcl::Transform3<S>& tf1,
                       const ::fcl::CollisionGeometry<S>* o2, const ::fcl::Transform3<S>& tf2,
                       const ::fcl::CollisionRequest<S>& request, ::fcl::CollisionResult<S>& result) {
  countFallback();
  try {
    return ::fcl::collide(o1, tf1, o2, tf2, request, result);
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
    return ::fcl::distance(o1, tf1, o2, tf2, request, result);
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
