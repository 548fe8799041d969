#pragma once
// gq as Bullet's narrow phase. A host changes its construction lines only:
//   gq::bullet::CollisionConfiguration config;              // was btDefaultCollisionConfiguration
//   gq::bullet::CollisionDispatcher dispatcher(&config);     // was btCollisionDispatcher
// Contact and closest-point algorithms for the shape pairs gq handles (see routesToGq) then come from gq; every
// other pair keeps Bullet's own algorithm. Compound shapes keep Bullet's compound algorithm, whose child pairs are
// dispatched through the same tables and so reach gq. Works with btCollisionDispatcherMt too (pass the
// configuration to it): the gq algorithms share only the cooked-shape cache, which is locked.
#include <cstddef>

#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionDispatch/btDefaultCollisionConfiguration.h>

#include "gq/fit.h"

namespace gq::bullet {

class CollisionConfiguration : public btDefaultCollisionConfiguration {
 public:
  // The algorithm pool's element size is raised to fit gq's algorithm if needed.
  explicit CollisionConfiguration(const btDefaultCollisionConstructionInfo& info = btDefaultCollisionConstructionInfo());
  ~CollisionConfiguration() override;
  CollisionConfiguration(const CollisionConfiguration&) = delete;
  CollisionConfiguration& operator=(const CollisionConfiguration&) = delete;

  btCollisionAlgorithmCreateFunc* getCollisionAlgorithmCreateFunc(int proxyType0, int proxyType1) override;
  btCollisionAlgorithmCreateFunc* getClosestPointsAlgorithmCreateFunc(int proxyType0, int proxyType1) override;

  // Bullet's own create functions (what btDefaultCollisionConfiguration would answer): the fallback for shapes
  // whose parameters gq does not model (e.g. a heightfield with diamond subdivision).
  btCollisionAlgorithmCreateFunc* bulletCreateFunc(int proxyType0, int proxyType1, bool closestPoints);

  // Whether a pair of broadphase proxy types is routed to gq: sphere, capsule, box, convex hull, cylinder, cone and
  // multi-sphere against each other, and against static planes, BVH triangle meshes (also scaled) and heightfields.
  static bool routesToGq(int proxyType0, int proxyType1);

  // Opt-in, off by default (null): btGImpactMeshShape sides answered by their gq::fitShape fit under these settings
  // (a compound of the fit's parts, fitted once per mesh; docs/bullet.md). Read when a pair's algorithm is created.
  const FitOptions<double>* meshFitting = nullptr;

 private:
  btCollisionAlgorithmCreateFunc* contactCreateFunc_;
  btCollisionAlgorithmCreateFunc* closestPointsCreateFunc_;
  btCollisionAlgorithmCreateFunc* fittedMeshCreateFunc_[2];  // contacts, closest points
};

// A btCollisionDispatcher over any configuration. Nothing is overridden: registerCollisionCreateFunc and
// setNearCallback keep Bullet's meaning (a host's own create function replaces gq's for that pair).
class CollisionDispatcher : public btCollisionDispatcher {
 public:
  explicit CollisionDispatcher(btCollisionConfiguration* configuration) : btCollisionDispatcher(configuration) {}
};

// sizeof the gq contact algorithm (must fit the dispatcher's pool element; tests assert it).
std::size_t contactAlgorithmSize();

// Cooked gq data (hulls, meshes, heightfields) is cached per Bullet shape and reused while the shape's data is
// unchanged. Call this after deleting shapes whose memory may be reused, or to free the cache.
void clearShapeCache();

}  // namespace gq::bullet
