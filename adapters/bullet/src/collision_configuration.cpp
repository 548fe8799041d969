#include "gq/bullet/collision_configuration.h"

#include <algorithm>

#include "contact_algorithm.h"
#include "mesh_fitting.h"
#include "shape_view.h"

namespace gq::bullet {
namespace {

// Bullet sizes its algorithm pool from its own algorithms; make room for gq's (Bullet checks it only by assert).
btDefaultCollisionConstructionInfo withGqElementSize(btDefaultCollisionConstructionInfo info) {
  info.m_customCollisionAlgorithmMaxElementSize =
      std::max(info.m_customCollisionAlgorithmMaxElementSize, int(sizeof(ContactAlgorithm)));
  return info;
}

}  // namespace

CollisionConfiguration::CollisionConfiguration(const btDefaultCollisionConstructionInfo& info)
    : btDefaultCollisionConfiguration(withGqElementSize(info)),
      contactCreateFunc_(new ContactCreateFunc(*this, false)),
      closestPointsCreateFunc_(new ContactCreateFunc(*this, true)),
      fittedMeshCreateFunc_{newFittedMeshCreateFunc(*this, false), newFittedMeshCreateFunc(*this, true)} {}

CollisionConfiguration::~CollisionConfiguration() {
  delete contactCreateFunc_;
  delete closestPointsCreateFunc_;
  for (btCollisionAlgorithmCreateFunc* f : fittedMeshCreateFunc_) delete f;
}

bool CollisionConfiguration::routesToGq(int proxyType0, int proxyType1) {
  return isGqShapeType(proxyType0) && isGqShapeType(proxyType1) &&
         (isGqConvexType(proxyType0) || isGqConvexType(proxyType1));
}

btCollisionAlgorithmCreateFunc* CollisionConfiguration::getCollisionAlgorithmCreateFunc(int proxyType0,
                                                                                        int proxyType1) {
  if (isFittedMeshPair(proxyType0, proxyType1)) return fittedMeshCreateFunc_[0];
  return routesToGq(proxyType0, proxyType1) ? contactCreateFunc_
                                            : bulletCreateFunc(proxyType0, proxyType1, false);
}

btCollisionAlgorithmCreateFunc* CollisionConfiguration::getClosestPointsAlgorithmCreateFunc(int proxyType0,
                                                                                            int proxyType1) {
  if (isFittedMeshPair(proxyType0, proxyType1)) return fittedMeshCreateFunc_[1];
  return routesToGq(proxyType0, proxyType1) ? closestPointsCreateFunc_
                                            : bulletCreateFunc(proxyType0, proxyType1, true);
}

btCollisionAlgorithmCreateFunc* CollisionConfiguration::bulletCreateFunc(int proxyType0, int proxyType1,
                                                                         bool closestPoints) {
  return closestPoints ? btDefaultCollisionConfiguration::getClosestPointsAlgorithmCreateFunc(proxyType0, proxyType1)
                       : btDefaultCollisionConfiguration::getCollisionAlgorithmCreateFunc(proxyType0, proxyType1);
}

std::size_t contactAlgorithmSize() { return sizeof(ContactAlgorithm); }

}  // namespace gq::bullet
