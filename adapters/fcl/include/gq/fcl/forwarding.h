#pragma once
// FCL 0.7's query overloads that gq does not answer, declared in gq::fcl so that qualified calls (gq::fcl::collide,
// gq::fcl::distance) find them beside gq's own: a namespace that declares a name hides the using-directive's
// declarations of it. Each forwards to FCL unchanged (not counted in adapterCounters()):
//  - continuous collision on two ContinuousCollisionObjects (FCL's collide overload); continuousCollide is not
//    declared by gq and is reached through the using-directive in gq/fcl/fcl.h;
//  - the overloads taking a NarrowPhaseSolver*: the host asks for one of FCL's solvers, so FCL answers.
#include <cstddef>

#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/continuous_collision.h>
#include <fcl/narrowphase/distance.h>

#include "gq/fcl/collision.h"

namespace gq::fcl {

template <typename S>
S collide(const ::fcl::ContinuousCollisionObject<S>* o1, const ::fcl::ContinuousCollisionObject<S>* o2,
          const ::fcl::ContinuousCollisionRequest<S>& request, ::fcl::ContinuousCollisionResult<S>& result) {
  return ::fcl::collide(o1, o2, request, result);
}

template <typename S, typename NarrowPhaseSolver>
std::size_t collide(const ::fcl::CollisionObject<S>* o1, const ::fcl::CollisionObject<S>* o2,
                    const NarrowPhaseSolver* nsolver, const ::fcl::CollisionRequest<S>& request,
                    ::fcl::CollisionResult<S>& result) {
  return ::fcl::collide(o1, o2, nsolver, request, result);
}

template <typename S, typename NarrowPhaseSolver>
std::size_t collide(const ::fcl::CollisionGeometry<S>* o1, const ::fcl::Transform3<S>& tf1,
                    const ::fcl::CollisionGeometry<S>* o2, const ::fcl::Transform3<S>& tf2,
                    const NarrowPhaseSolver* nsolver, const ::fcl::CollisionRequest<S>& request,
                    ::fcl::CollisionResult<S>& result) {
  return ::fcl::collide(o1, tf1, o2, tf2, nsolver, request, result);
}

template <typename NarrowPhaseSolver>
typename NarrowPhaseSolver::S distance(const ::fcl::CollisionObject<typename NarrowPhaseSolver::S>* o1,
                                       const ::fcl::CollisionObject<typename NarrowPhaseSolver::S>* o2,
                                       const NarrowPhaseSolver* nsolver,
                                       const ::fcl::DistanceRequest<typename NarrowPhaseSolver::S>& request,
                                       ::fcl::DistanceResult<typename NarrowPhaseSolver::S>& result) {
  return ::fcl::distance<NarrowPhaseSolver>(o1, o2, nsolver, request, result);
}

template <typename NarrowPhaseSolver>
typename NarrowPhaseSolver::S distance(const ::fcl::CollisionGeometry<typename NarrowPhaseSolver::S>* o1,
                                       const ::fcl::Transform3<typename NarrowPhaseSolver::S>& tf1,
                                       const ::fcl::CollisionGeometry<typename NarrowPhaseSolver::S>* o2,
                                       const ::fcl::Transform3<typename NarrowPhaseSolver::S>& tf2,
                                       const NarrowPhaseSolver* nsolver,
                                       const ::fcl::DistanceRequest<typename NarrowPhaseSolver::S>& request,
                                       ::fcl::DistanceResult<typename NarrowPhaseSolver::S>& result) {
  return ::fcl::distance<NarrowPhaseSolver>(o1, tf1, o2, tf2, nsolver, request, result);
}

}  // namespace gq::fcl
