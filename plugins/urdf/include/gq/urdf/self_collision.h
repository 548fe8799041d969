#pragma once
// Self-collision and self-distance of a RobotModel: forward kinematics, a broadphase over link bounding spheres
// (the link pairs the allowed-collision matrix leaves, listed once), shape spheres and oriented boxes, then
// gq::overlap / gq::distance on the shape pairs that survive.
// A checker owns scratch buffers: use one per thread (the model itself is shared and immutable). It is movable, not
// copyable (build another from the same model).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "gq/batch.h"
#include "gq/math.h"
#include "gq/query.h"
#include "gq/urdf/robot.h"

namespace gq::urdf {

struct LinkPair {
  std::uint32_t a = 0, b = 0;  // link indices, a < b
  bool operator==(const LinkPair& o) const { return a == o.a && b == o.b; }
  bool operator<(const LinkPair& o) const { return a != o.a ? a < o.a : b < o.b; }
};

struct CollisionRequest {
  bool allPairs = true;  // false: stop at the first colliding pair
};

struct CollisionResult {
  bool colliding = false;
  std::vector<LinkPair> pairs;  // sorted; one entry at most when !allPairs
};

template <class T> struct SelfDistanceResult {
  T distance = T(0);  // signed: < 0 is a penetration depth; +inf when no pair is checked
  LinkPair pair;
  Vec3<T> point0 = Vec3<T>::Zero(), point1 = Vec3<T>::Zero();  // witnesses on pair.a and pair.b (root frame)
};

// A shape's local bounding box carried to the world by its pose (midphase culling).
template <class T> struct OrientedBox {
  Vec3<T> centre = Vec3<T>::Zero();
  Mat3<T> axes = Mat3<T>::Identity();  // columns: the box axes in the world
  Vec3<T> halfExtents = Vec3<T>::Zero();
};

struct CheckerOptions {
  // At construction the checked link pairs are ordered by how often they touch over this many seeded random
  // configurations, so checks that stop at their first colliding pair end sooner (pair_order.h). 0 keeps the
  // model's order and makes construction cheaper (hosts that build a checker per short-lived model).
  std::uint32_t orderingSamples = 256;
};

template <class T> class SelfCollisionChecker {
 public:
  explicit SelfCollisionChecker(std::shared_ptr<const RobotModel<T>> model, const CheckerOptions& options = CheckerOptions());
  ~SelfCollisionChecker();
  SelfCollisionChecker(SelfCollisionChecker&&) noexcept;
  SelfCollisionChecker& operator=(SelfCollisionChecker&&) noexcept;

  const RobotModel<T>& model() const;

  // Unsupported when a checked pair has no gq overlap kernel (e.g. mesh mode before mesh-mesh overlap lands).
  Status checkSelfCollision(const std::vector<T>& q, CollisionResult& result,
                            const CollisionRequest& request = CollisionRequest());
  Status selfDistance(const std::vector<T>& q, SelfDistanceResult<T>& result);
  // colliding[i] = 1 when configuration i collides (first pair found ends that configuration's check).
  Status checkSelfCollisionBatch(const std::vector<std::vector<T>>& qs, std::vector<std::uint8_t>& colliding);

  // Shape pairs that survived the broadphase in the last call (diagnostic).
  std::size_t lastNarrowPhasePairs() const;

 private:
  // The checker's state (culling volumes, compiled kinematics, per-configuration scratch) lives in the library.
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Many configurations on gq's batch pool (gq/batch.h), one checker per worker: configuration i is the `dof` values
// starting at configs[i] (rows configs.stride bytes apart, so an (N, dof) array passes without a copy). The answers
// are the single checker's, whatever the thread count. statuses[i] (when given) is configuration i's Status; the
// call returns Ok, a Warning (index = how many failed) when some configuration failed, or InvalidArgument for a dof
// other than the model's, a stride shorter than a row, or a null output (nothing written).
// colliding[i] = 1 when configuration i collides (its first colliding pair ends its check).
template <class T>
Status checkSelfCollisionBatch(std::shared_ptr<const RobotModel<T>> model, StridedArray<T> configs, std::size_t dof,
                               std::uint8_t* colliding, Status* statuses = nullptr, const BatchSettings& settings = {},
                               const CheckerOptions& options = CheckerOptions());
// results[i] = the signed self-distance of configuration i.
template <class T>
Status selfDistanceBatch(std::shared_ptr<const RobotModel<T>> model, StridedArray<T> configs, std::size_t dof,
                         SelfDistanceResult<T>* results, Status* statuses = nullptr, const BatchSettings& settings = {},
                         const CheckerOptions& options = CheckerOptions());

// Pairs of links (with shapes, not already allowed) that never touched in `samples` random configurations.
struct NeverCollidingResult {
  std::vector<LinkPair> never;
  std::vector<std::uint64_t> contactCount;  // per link pair (row-major links x links), configurations in contact
  std::uint64_t samples = 0;
};
template <class T>
Status neverColliding(std::shared_ptr<const RobotModel<T>> model, std::uint64_t samples, std::uint64_t seed,
                      NeverCollidingResult& result);

// The SRDF <disable_collisions> list: model's SRDF pairs and adjacent links, plus `never` with reason "Never".
template <class T> std::string writeSrdfDisableCollisions(const RobotModel<T>& model, const std::vector<LinkPair>& never);

}  // namespace gq::urdf
