#pragma once
// The cache of cooked geometry per CollisionGeometry*: Convex -> cooked hull, triangle BVHModel -> cooked mesh.
//
// Identity rules (when an entry is reused):
//  - Convex: FCL 0.7 holds its vertices in a `shared_ptr<const std::vector>` fixed at construction. The entry keeps
//    a copy of the Convex (sharing that vector), so the vector cannot be freed while the entry lives and its address
//    identifies the vertex set: an entry is reused while the geometry's vertex vector is the same object.
//  - BVHModel: vertices and triangles can be edited in place (beginReplaceModel / beginUpdateModel). An entry is
//    reused while a fingerprint matches: counts, array addresses and up to kFingerprintSamples vertices and
//    triangles sampled evenly. An edit that changes none of them needs forgetGeometry().
// A new BVHModel is not cooked at once: lookups that allow it (MeshUse::TreeAllowed) get its FCL tree (fcl_tree.h)
// and each such query charges its work; once the work reaches the cook's estimate (kCookWorkPerTriangle a triangle, measured)
// the model is cooked, so a model queried a few times never pays the cook and one queried often pays it once (ski
// rental: the total stays within twice the better of the two choices). A cook first looks for an identical model
// cooked before (a 128-bit hash of the vertex and triangle arrays: a pass over them, a fraction of a cook).
// Lookups go through a small per-thread table in front of the shared map (no lock, no reference counting on a hit);
// forget/clear bump a generation that turns every per-thread slot stale. A Convex hit reads a trivially
// destructible mirror of that table (geometry, vertex vector, generation, entry) in a small function of its own:
// ~20 instructions a lookup where the general path's frame and thread_local wrapper cost ~75.
#include <fcl/geometry/collision_geometry.h>

#include "convert.h"

namespace gq::fcl::internal {

// The cooked geometry of a Convex or a triangle BVHModel (`out`; `type` is the geometry's node type), or the reason
// there is none: Invalid for an empty, unfinished or uncookable model; NotModelled for point clouds and octrees. The
// pointers stay valid until this thread's next lookup of two more geometries (a call looks up at most two).
template <class T>
Conversion cachedGeometry(const ::fcl::CollisionGeometry<T>* geometry, ::fcl::NODE_TYPE type, Cooked<T>& out,
                          MeshUse use = MeshUse::Cooked);

// Adds a tree query's work to its model's entry; the query that reaches the cook's estimate cooks the model.
template <class T> void chargeTree(const MeshTree<T>& tree, std::uint64_t work);

// Two Convex geometries' cooked data at once (the Convex pairs): true when both are cooked hulls.
template <class T>
bool cachedHulls(const ::fcl::CollisionGeometry<T>* a, const ::fcl::CollisionGeometry<T>* b, Cooked<T>& ca,
                 Cooked<T>& cb);

template <class T> void forgetCached(const ::fcl::CollisionGeometry<T>* geometry);
void clearCached();

}  // namespace gq::fcl::internal
