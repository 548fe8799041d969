#pragma once
// The pairs gq does not answer go to FCL itself, unchanged (the only translation unit that instantiates FCL's
// narrow phase).
#include <cstddef>

#include <fcl/narrowphase/collision_object.h>
#include <fcl/narrowphase/collision_request.h>
#include <fcl/narrowphase/collision_result.h>
#include <fcl/narrowphase/distance_request.h>
#include <fcl/narrowphase/distance_result.h>

#include "gq/fcl/collision.h"

namespace gq::fcl::internal {

template <class S>
std::size_t fclCollide(const ::fcl::CollisionGeometry<S>* o1, const ::fcl::Transform3<S>& tf1,
                       const ::fcl::CollisionGeometry<S>* o2, const ::fcl::Transform3<S>& tf2,
                       const ::fcl::CollisionRequest<S>& request, ::fcl::CollisionResult<S>& result);
template <class S>
S fclDistance(const ::fcl::CollisionGeometry<S>* o1, const ::fcl::Transform3<S>& tf1,
              const ::fcl::CollisionGeometry<S>* o2, const ::fcl::Transform3<S>& tf2,
              const ::fcl::DistanceRequest<S>& request, ::fcl::DistanceResult<S>& result);

// The calling thread's counts of pairs gq answered and pairs FCL answered (adapterCounters()). Inline, constant
// initialised: a count is one increment of a thread-local word (an out-of-line call cost the fast path its saved
// registers).
inline thread_local AdapterCounters tCounters;
inline void countGq() { ++tCounters.gq; }
inline void countFallback() { ++tCounters.fallback; }

}  // namespace gq::fcl::internal
