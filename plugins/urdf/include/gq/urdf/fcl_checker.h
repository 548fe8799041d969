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

 private:
  struct Impl;
  explicit FclSelfCollisionChecker(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace gq::urdf
