#pragma once
// Options::meshFitting's entries (gq/fcl/fit.h): collide and distance with triangle BVHModels replaced by their fits.
#include <cstddef>

#include "gq/fcl/collision.h"

namespace gq::fcl::internal {

// options.meshFitting is not null. A side that is not a fittable model, or whose fit failed, is queried as it is.
template <class S>
std::size_t collideFitted(const ::fcl::CollisionGeometry<S>* o1, const ::fcl::Transform3<S>& tf1,
                          const ::fcl::CollisionGeometry<S>* o2, const ::fcl::Transform3<S>& tf2,
                          const ::fcl::CollisionRequest<S>& request, ::fcl::CollisionResult<S>& result,
                          const Options& options);
template <class S>
S distanceFitted(const ::fcl::CollisionGeometry<S>* o1, const ::fcl::Transform3<S>& tf1,
                 const ::fcl::CollisionGeometry<S>* o2, const ::fcl::Transform3<S>& tf2,
                 const ::fcl::DistanceRequest<S>& request, ::fcl::DistanceResult<S>& result, const Options& options);

// The cached fits of one geometry, or of all.
template <class S> void forgetFits(const ::fcl::CollisionGeometry<S>* geometry);
void clearFits();

}  // namespace gq::fcl::internal
