#pragma once
// gq::fcl: include this instead of <fcl/fcl.h> and switch a host from FCL to gq by one alias line:
//   namespace coll = ::fcl;      // before
//   namespace coll = gq::fcl;    // after
// gq::fcl declares collide, distance, DynamicAABBTreeCollisionManager, DefaultCollisionFunction and
// DefaultDistanceFunction; every other name (Sphered, CollisionObjectd, CollisionRequestd, Transform3d,
// DefaultCollisionData, ...) is FCL's own, reached through the using-directive below (qualified lookup of
// gq::fcl::X finds gq's declaration first and FCL's only when gq has none).
#include <fcl/fcl.h>

#include "gq/fcl/broadphase.h"
#include "gq/fcl/collision.h"

namespace gq::fcl {
using namespace ::fcl;
}  // namespace gq::fcl
