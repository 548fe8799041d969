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

namespace gq::bullet {

// Hull of the unscaled points (the shape's local scaling becomes the gq MeshScale). Null if qhull refuses them.
std::shared_ptr<const ConvexMesh<Real>> cachedHull(const btConvexHullShape& shape);

// The hull of the spheres at the shape's (uniform) local scaling; null for non-uniform scaling or a radius <= 0.
std::shared_ptr<const MultiSphereShape> cachedMultiSphere(const btMultiSphereShape& shape);

struct CookedMesh {
  std::shared_ptr<const TriangleMesh<Real>> mesh;              // unscaled vertices, all sub-parts concatenated
  std::shared_ptr<const std::vector<std::uint32_t>> partStarts;  // first triangle of each sub-part
};
bool cachedMesh(const btStridingMeshInterface& meshInterface, CookedMesh& out);

struct CookedHeightField {
  std::shared_ptr<const HeightField<Real>> heightField;  // heights already scaled and centred as Bullet does
  Real rowScale = Real(1), columnScale = Real(1);
  Pose localPose;              // gq grid frame in the Bullet shape frame (axis permutation + centring offset)
  bool rowsAreX = true;        // gq rows follow Bullet's first grid index
};
// False for layouts gq's grid does not reproduce (flipped, diamond or zigzag quad edges; non-positive scaling).
bool cachedHeightField(const btHeightfieldTerrainShape& shape, CookedHeightField& out);

}  // namespace gq::bullet
