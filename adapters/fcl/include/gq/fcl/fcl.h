#pragma once
// gq::fcl: include this instead of <fcl/fcl.h> and switch a host from FCL to gq by one alias line:
//   namespace coll = ::fcl;      // before
//   namespace coll = gq::fcl;    // after
// gq::fcl declares collide, distance, DynamicAABBTreeCollisionManager, DefaultCollisionFunction and
// DefaultDistanceFunction, and forwards FCL's collide/distance overloads that gq does not answer (continuous
// collision, NarrowPhaseSolver-taking overloads: gq/fcl/forwarding.h) so every FCL 0.7 call resolves; every other
// name (Sphered, CollisionObjectd, CollisionRequestd, Transform3d, DefaultCollisionData, ...) is FCL's own, reached through the using-directive below (qualified lookup of
// gq::fcl::X finds gq's declaration first and FCL's only when gq has none).
#include <fcl/fcl.h>

#include "gq/fcl/broadphase.h"
#include "gq/fcl/collision.h"
#include "gq/fcl/forwarding.h"

namespace gq::fcl {
using namespace ::fcl;
}  // namespace gq::fcl
