#include "contact_algorithm.h"

#include <new>

#include <BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h>
#include <BulletCollision/CollisionDispatch/btManifoldResult.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>

#include "contacts.h"
#include "gq/bullet/collision_configuration.h"

namespace gq::bullet {
namespace {

// Writes contacts into Bullet's manifold result (which stores them in the persistent manifold, or hands them to a
// contactTest callback), naming the mesh/heightfield triangle as Bullet's own algorithms do.
class ManifoldSink final : public ContactSink {
 public:
  explicit ManifoldSink(btManifoldResult& result) : result_(result) {}
  void add(const V3& normalOnB, const V3& pointOnB, Real depth, TriangleIds ids, bool surfaceIsB) override {
    if (ids.part >= 0 || ids.index >= 0) {
      if (surfaceIsB)
        result_.setShapeIdentifiersB(ids.part, ids.index);
      else
        result_.setShapeIdentifiersA(ids.part, ids.index);
    }
    result_.addContactPoint(toBt(normalOnB), toBt(pointOnB), depth);
  }

 private:
  btManifoldResult& result_;
};

bool pairHasGqPath(ShapeKind a, ShapeKind b) { return a == ShapeKind::Convex || b == ShapeKind::Convex; }

}  // namespace

ContactAlgorithm::ContactAlgorithm(btPersistentManifold* sharedManifold, const btCollisionAlgorithmConstructionInfo& ci,
                                   const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1)
    : btActivatingCollisionAlgorithm(ci, body0, body1), manifold_(sharedManifold), ownManifold_(false) {}

ContactAlgorithm::~ContactAlgorithm() {
  if (ownManifold_ && manifold_) m_dispatcher->releaseManifold(manifold_);
}

void ContactAlgorithm::processCollision(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                                        const btDispatcherInfo&, btManifoldResult* result) {
  ShapeView va, vb;
  const bool answerable = isFinite(body0->getWorldTransform()) && isFinite(body1->getWorldTransform()) &&
                          viewShape(body0->getCollisionShape(), va) == Support::Gq &&
                          viewShape(body1->getCollisionShape(), vb) == Support::Gq;
  if (!answerable) {
    // Bad input (or a shape edited into one gq does not model): no contact, and none kept from earlier frames.
    if (manifold_ && ownManifold_) manifold_->clearManifold();
    return;
  }
  if (!manifold_) {
    manifold_ = m_dispatcher->getNewManifold(body0->getCollisionObject(), body1->getCollisionObject());
    ownManifold_ = true;
  }
  result->setPersistentManifold(manifold_);
  const PlacedShape a{&va, toGq(body0->getWorldTransform()) * va.localPose};
  const PlacedShape b{&vb, toGq(body1->getWorldTransform()) * vb.localPose};
  // Bullet's algorithms report points up to the breaking threshold; contactTest widens it by its own threshold.
  const Real threshold = manifold_->getContactBreakingThreshold() + result->m_closestPointDistanceThreshold;
  ManifoldSink sink(*result);
  pairContacts(a, b, threshold, sink);
  if (ownManifold_) result->refreshContactPoints();
}

void ContactAlgorithm::getAllContactManifolds(btManifoldArray& manifolds) {
  if (manifold_ && ownManifold_) manifolds.push_back(manifold_);
}

btCollisionAlgorithm* ContactCreateFunc::CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& ci,
                                                                  const btCollisionObjectWrapper* body0,
                                                                  const btCollisionObjectWrapper* body1) {
  ShapeView va, vb;
  const Support a = viewShape(body0->getCollisionShape(), va), b = viewShape(body1->getCollisionShape(), vb);
  // Invalid shapes get gq's algorithm too: it reports no contact while they stay invalid (Bullet's own algorithms
  // would report NaN contacts for some, or crash on a hull without points).
  const bool gqPath = (a == Support::Gq && b == Support::Gq && pairHasGqPath(va.kind, vb.kind)) ||
                      a == Support::Invalid || b == Support::Invalid;
  if (gqPath) {
    void* memory = ci.m_dispatcher1->allocateCollisionAlgorithm(sizeof(ContactAlgorithm));
    return new (memory) ContactAlgorithm(ci.m_manifold, ci, body0, body1);
  }
  btCollisionAlgorithmCreateFunc* bulletFunc = config_.bulletCreateFunc(
      body0->getCollisionShape()->getShapeType(), body1->getCollisionShape()->getShapeType(), closest_);
  return bulletFunc->CreateCollisionAlgorithm(ci, body0, body1);
}

}  // namespace gq::bullet
