#pragma once
// Dynamic triangle meshes (btGImpactMeshShape) answered by their gq::fitShape fit, on request
// (CollisionConfiguration::meshFitting, off by default). The fit's parts become the children of a btCompoundShape
// (hulls as btConvexHullShape, the fit's cooked hull handed to the hull cache as theirs; spheres, capsules and
// boxes as Bullet's own shapes; margins 0: a containing fit already encloses the mesh), fitted in Bullet's scalar
// once per mesh, scaling and settings and shared by every pair; a pair is then
// answered by Bullet's compound algorithm, whose child pairs reach gq through the same dispatcher. The cylinder
// (a gq custom geometry) and the mesh itself are never chosen: a mesh whose fit fails keeps Bullet's algorithm.
#include <BulletCollision/CollisionDispatch/btCollisionCreateFunc.h>

namespace gq::bullet {

class CollisionConfiguration;

// Whether either side of a pair is a btGImpactMeshShape.
bool isFittedMeshPair(int proxyType0, int proxyType1);

// The create function for those pairs: the fitted compound while the configuration's meshFitting is set, else
// Bullet's own algorithm for the pair (what btDefaultCollisionConfiguration answers). Owned by the caller.
btCollisionAlgorithmCreateFunc* newFittedMeshCreateFunc(CollisionConfiguration& config, bool closestPoints);

// Frees every cached fit (clearShapeCache calls it); pairs already made keep theirs.
void clearFittedMeshes();

}  // namespace gq::bullet
