#pragma once
// Cooked gq data for Bullet shapes, cooked once per shape and shared (thread-safe: one lock around the table).
#include <cstdint>
#include <memory>
#include <vector>

#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/CollisionShapes/btHeightfieldTerrainShape.h>
#include <BulletCollision/CollisionShapes/btMultiSphereShape.h>
#include <BulletCollision/CollisionShapes/btStridingMeshInterface.h>

#include "bt_convert.h"
#include "gq/cooking.h"
#include "multi_sphere.h"
#include "support.h"

namespace gq::bullet {

// Each lookup answers Gq with `out` filled, Bullet (valid data gq does not model) or Invalid (bad input).

// Hull of the unscaled points (the shape's local scaling becomes the gq MeshScale). Invalid for no points or a
// non-finite one; Bullet when qhull refuses the points (fewer than 4, coplanar: Bullet rounds them by its margin).
Support cachedHull(const btConvexHullShape& shape, std::shared_ptr<const ConvexMesh<Real>>& out);
// Caches `hull`, already cooked, as the hull of `shape`, whose points must be exactly its vertices (a fit's hull
// part): cachedHull then answers it without running qhull again. False, nothing cached, for a null hull or a shape
// cachedHull would call Invalid.
bool shareHull(const btConvexHullShape& shape, std::shared_ptr<const ConvexMesh<Real>> hull);

// The hull of the spheres at the shape's (uniform) local scaling. Invalid for no spheres, a radius <= 0 or a
// non-finite number; Bullet for non-uniform or negative scaling.
Support cachedMultiSphere(const btMultiSphereShape& shape, std::shared_ptr<const MultiSphereShape>& out);

struct CookedMesh {
  std::shared_ptr<const TriangleMesh<Real>> mesh;              // unscaled vertices, all sub-parts concatenated
  std::shared_ptr<const std::vector<std::uint32_t>> partStarts;  // first triangle of each sub-part
};
// A hash of what a mesh's cooked data is made from (sub-part count; each part's buffers, counts, strides and types);
// false for no sub-part or a malformed one. cachedMesh finds its data by it; a pair's side compares it every frame.
bool meshFingerprint(const btStridingMeshInterface& meshInterface, std::uint64_t& out);
// Invalid for a malformed sub-part (negative counts, null buffers, unknown types) and for every mesh gq's cooking
// refuses: no triangles, all degenerate, an index past the vertex count, a non-finite vertex.
Support cachedMesh(const btStridingMeshInterface& meshInterface, CookedMesh& out);

struct CookedHeightField {
  std::shared_ptr<const HeightField<Real>> heightField;  // heights already scaled and centred as Bullet does
  Real rowScale = Real(1), columnScale = Real(1);
  Pose localPose;              // gq grid frame in the Bullet shape frame (axis permutation + centring offset)
  bool rowsAreX = true;        // gq rows follow Bullet's first grid index
};
// A hash of what a heightfield's cooked data is made from (data pointer, sample counts, up axis, scaling, quad
// layout), read without touching a sample; false for absurd dimensions, an up axis outside 0..2 or no data.
bool heightFieldFingerprint(const btHeightfieldTerrainShape& shape, std::uint64_t& out);
// Bullet for layouts gq's grid does not reproduce (flipped, diamond or zigzag quad edges; negative scaling).
// Invalid, checked before any sample is read: fewer than 2 x 2 samples, more than kMaxHeightFieldSamples, an up
// axis outside 0..2, no height data, a zero or non-finite scaling; and a non-finite height (found at cooking).
Support cachedHeightField(const btHeightfieldTerrainShape& shape, CookedHeightField& out);

}  // namespace gq::bullet
