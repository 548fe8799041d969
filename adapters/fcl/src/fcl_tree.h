#pragma once
// A BVHModel gq has not cooked, queried on FCL's own BV tree (built by FCL at endModel) through FCL's public
// BVHModel API (getBV: bv, first_child, primitiveId, isLeaf; vertices, tri_indices), with core's exact
// shape-triangle tests (gq::kernels::TriangleQueryShape) at the leaves. The cache (geometry_cache.h) answers a new
// model so until its queries have cost about as much as cooking it, then cooks it (ski rental).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "convert.h"
#include "pair_kernels.h"

namespace gq::fcl::internal {

// Work of a tree query in units of one node visit; the cache compares their sum with a cook's estimate.
inline constexpr std::uint64_t kNodeWork = 1;          // a node's box against the shape's box
inline constexpr std::uint64_t kTriangleTestWork = 4;  // a leaf's exact boolean shape-triangle test
inline constexpr std::uint64_t kTriangleGjkWork = 20;  // a leaf's contact or distance (GJK/EPA on the triangle)

// Whether the pair is a tree model against a shape core's shape-triangle tests take (a closed convex solid).
template <class T> bool treeAgainstSolid(const Converted<T>& a, const Converted<T>& b) {
  const auto solid = [](const Converted<T>& c) { return c.isSolid() && !c.isPlaneLike(); };
  return (a.isTree() && solid(b)) || (solid(a) && b.isTree());
}

// Contacts of the tree model against a solid (mesh first: b1 = triangle id, normal from the mesh to the shape), one
// per triangle the shape overlaps, in FCL's depth-first order; the same contacts as pairContacts on the cooked mesh.
template <class T>
Status treeContacts(const MeshTree<T>& mesh, const Transform<T>& meshPose, const Converted<T>& shape,
                    const Transform<T>& shapePose, bool withGeometry, std::size_t room, std::vector<PairContact<T>>& out);

// Distance of the tree model to a solid (mesh first: point1 on the mesh), >= 0 as the cooked mesh's; a pair proven
// farther than `farEnough` gets a lower bound at or above it and no witnesses.
template <class T>
Status treeDistance(const MeshTree<T>& mesh, const Transform<T>& meshPose, const Converted<T>& shape,
                    const Transform<T>& shapePose, PairDistance<T>& out, T farEnough);

// World bounds of the tree model: its root BV's box at `pose` (conservative; infinite for a BV type not handled).
template <class T> Bounds3<T> treeBounds(const MeshTree<T>& mesh, const Transform<T>& pose);

}  // namespace gq::fcl::internal
