#pragma once
// The gq contact algorithm as a Bullet collision algorithm, and the create function the configuration installs.
#include <BulletCollision/CollisionDispatch/btActivatingCollisionAlgorithm.h>
#include <BulletCollision/CollisionDispatch/btCollisionCreateFunc.h>
#include <LinearMath/btTransform.h>

#include <memory>

namespace gq::bullet {

class CollisionConfiguration;
struct PairState;
struct ShapeView;

// Owns (or shares) a Bullet persistent manifold and refills it from gq's contacts every frame. It also keeps what
// it learned about its pair (the two shapes' views, prepared once and re-checked each frame against the shapes'
// parameters; the last separating direction). A pair runs on one thread per frame (btCollisionDispatcherMt
// dispatches each pair once), so the state needs no lock.
class ContactAlgorithm final : public btActivatingCollisionAlgorithm {
 public:
  ContactAlgorithm(btPersistentManifold* sharedManifold, const btCollisionAlgorithmConstructionInfo& ci,
                   const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1);
  ~ContactAlgorithm() override;

  void processCollision(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                        const btDispatcherInfo& info, btManifoldResult* result) override;
  // Discrete contacts only (continuous collision is left off, like Bullet's primitive algorithms).
  btScalar calculateTimeOfImpact(btCollisionObject*, btCollisionObject*, const btDispatcherInfo&,
                                 btManifoldResult*) override {
    return btScalar(1);
  }
  void getAllContactManifolds(btManifoldArray& manifolds) override;

 private:
  void collide(bool answerable, const ShapeView& va, const ShapeView& vb, const btCollisionObjectWrapper* body0,
               const btCollisionObjectWrapper* body1, btManifoldResult* result);

  // True when B's pose relative to A (`relative`) is close enough to the last exact frame's that the manifold's
  // points are kept (their normals turned with the manifold's B, at `manifoldPoseB`); false when they must be
  // recomputed.
  bool reuseContacts(const btTransform& relative, btScalar threshold, const btTransform& manifoldPoseB);
  // Remembers this exact frame for the reuse test; `size` is the length its tolerance is relative to.
  void rememberContacts(btScalar size, const btTransform& relative, btScalar threshold,
                        const btTransform& manifoldPoseB);

  btPersistentManifold* manifold_;
  bool ownManifold_;
  std::unique_ptr<PairState> state_;  // null if it could not be allocated: views are then built per frame
};

// Creates a ContactAlgorithm when both shapes convert to gq or either is bad input (which gets no contact),
// otherwise Bullet's own algorithm for the pair.
class ContactCreateFunc final : public btCollisionAlgorithmCreateFunc {
 public:
  ContactCreateFunc(CollisionConfiguration& config, bool closestPoints) : config_(config), closest_(closestPoints) {}
  btCollisionAlgorithm* CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& ci,
                                                 const btCollisionObjectWrapper* body0,
                                                 const btCollisionObjectWrapper* body1) override;

 private:
  CollisionConfiguration& config_;
  bool closest_;
};

}  // namespace gq::bullet
