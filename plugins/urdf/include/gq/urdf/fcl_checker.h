#pragma once
// A self-collision checker built on FCL 0.7 for reference and benchmarks: the same RobotModel (shapes, forward
// kinematics, allowed-collision matrix) with every shape converted to FCL (sphere, box, capsule, fcl::Convex for
// hulls, BVHModel<OBBRSS> for meshes), AABB-culled shape pairs and fcl::collide. Double precision only.
#include <memory>
#include <vector>

#include "gq/urdf/self_collision.h"

namespace gq::urdf {

class FclSelfCollisionChecker {
 public:
  static Status create(std::shared_ptr<const RobotModel<double>> model, std::unique_ptr<FclSelfCollisionChecker>& out);
  ~FclSelfCollisionChecker();

  Status checkSelfCollision(const std::vector<double>& q, CollisionResult& result,
                            const CollisionRequest& request = CollisionRequest());
  // MoveIt's narrow-phase pattern: fcl::distance over the checked shape pairs with the result pre-seeded by the
  // smallest distance so far (FCL prunes its BVH traversals with it), signed distance on. FCL stops at the first
  // penetration (its DistanceRequest::isSatisfied), so a colliding configuration's answer is some negative value,
  // not the deepest (gq's selfDistance reports the deepest); apart, both are the clearance.
  Status selfDistance(const std::vector<double>& q, SelfDistanceResult<double>& result);

 private:
  Status place(const std::vector<double>& q);
  struct Impl;
  explicit FclSelfCollisionChecker(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace gq::urdf
