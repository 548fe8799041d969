#pragma once
// Contact sets of one overlapping pair, in DART's convention.
#include <cstddef>

#include <dart/collision/CollisionResult.hpp>

namespace gq {
namespace dart {

class CollisionObject;

// Adds the contacts of the pair (object1, object2) to `result`, at most `room` of them, and returns how many it added
// (0: the pair does not touch, or gq does not answer it: two heightmaps).
// Each contact: normal unit from object 2 towards object 1, penetrationDepth >= 0, the point between the surfaces,
// triID1 / triID2 the triangle of a mesh or heightmap side (-1 otherwise).
//  - box on box, box on plane, capsule on plane: up to 4 points, the incident face (edge) clipped to the reference
//    face, all sharing one normal;
//  - a solid against a mesh or heightmap: the triangles under the solid's bounds, each through
//    gq::generateTriangleContacts (capsule, box, convex mesh) or, for spheres and custom shapes overlapping the
//    triangle, the deepest point below the triangle's plane along its face normal; at most 4 points a pair (the
//    deepest kept);
//  - mesh against mesh or heightmap: gq::generateMeshContacts (each crossing triangle pair along the shallower of
//    its two face normals), at most 4 (the deepest kept);
//  - other solid pairs: one contact at the signed distance's witness points.
std::size_t fillContacts(const CollisionObject& object1, const CollisionObject& object2, std::size_t room,
                         ::dart::collision::CollisionResult& result);

}  // namespace dart
}  // namespace gq
