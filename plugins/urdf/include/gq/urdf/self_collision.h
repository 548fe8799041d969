#pragma once
// Self-collision and self-distance of a RobotModel: forward kinematics, a broadphase over link bounding spheres
// (the link pairs the allowed-collision matrix leaves, listed once), shape spheres and oriented boxes, then
// gq::overlap / gq::distance on the shape pairs that survive.
// A checker owns scratch buffers: use one per thread (the model itself is shared and immutable).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "gq/math.h"
#include "gq/query.h"
#include "gq/urdf/robot.h"

namespace gq::urdf {

namespace detail {
template <class T> class KinematicChain;
}

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

  const RobotModel<T>& model() const { return *model_; }

  // Unsupported when a checked pair has no gq overlap kernel (e.g. mesh mode before mesh-mesh overlap lands).
  Status checkSelfCollision(const std::vector<T>& q, CollisionResult& result,
                            const CollisionRequest& request = CollisionRequest());
  Status selfDistance(const std::vector<T>& q, SelfDistanceResult<T>& result);
  // colliding[i] = 1 when configuration i collides (first pair found ends that configuration's check).
  Status checkSelfCollisionBatch(const std::vector<std::vector<T>>& qs, std::vector<std::uint8_t>& colliding);

  // Shape pairs that survived the broadphase in the last call (diagnostic).
  std::size_t lastNarrowPhasePairs() const { return lastNarrow_; }

 private:
  // Fixed per shape, in the frame of its rigid body (the links joined to it by fixed joints): an enclosing sphere
  // and an enclosing box, both grown by the culling slack; the box is carried to the world as an oriented box.
  struct ShapeBound {
    std::uint32_t body = 0;
    Transform<T> poseInBody;
    Vec3<T> centreInBody = Vec3<T>::Zero();
    T radius = T(0);
    Vec3<T> boxCentre = Vec3<T>::Zero();   // body frame
    Mat3<T> boxAxes = Mat3<T>::Identity();  // columns: box axes in the body frame
    Vec3<T> halfExtents = Vec3<T>::Zero();
    bool hasCapsule = false;  // an enclosing capsule (body frame) tighter than the sphere; else the sphere
    Vec3<T> capsuleStart = Vec3<T>::Zero(), capsuleSpan = Vec3<T>::Zero();
    T capsuleRadius = T(0);
    bool hasHull = false;  // mesh shapes: `hull` is their convex hull, tested before the triangles
    Geometry<T> hull;
    bool valid = false;     // validateGeometry passed (shape and hull): core's kernels may be called directly
    bool exactBox = false;  // a box whose culling box is itself: the oriented-box SAT decides box-box pairs
  };
  // Capsule enclosing every shape of a link (body frame), when tighter than the link sphere.
  struct LinkCapsule {
    bool used = false;
    Vec3<T> start = Vec3<T>::Zero(), span = Vec3<T>::Zero();
    T radius = T(0);
  };
  // A link pair the allowed-collision matrix leaves, with what its shape loop needs.
  struct CheckedPair {
    LinkPair links;
    T reach2 = T(0);            // (sum of the link sphere radii)^2: centres farther apart than this cull the pair
    bool shapeSpheres = false;  // a link has several shapes: test shape spheres and capsules before the boxes
    bool linkCapsules = false;  // a link has a capsule: test link capsules after the link spheres
  };

  void orderPairsByContactFrequency(std::uint32_t samples);
  Status placeBodies(const std::vector<T>& q);
  void placeLinkSpheres();
  void placeShapeSpheres();
  void placeShape(std::uint32_t shape);
  void placeCapsule(std::uint32_t shape);
  void placeLinkCapsule(std::uint32_t link);
  bool linkCapsulesDisjoint(std::uint32_t linkA, std::uint32_t linkB);
  const Transform<T>& shapePose(std::uint32_t shape);
  bool shapesMayTouch(std::uint32_t shapeA, std::uint32_t shapeB, bool shapeSpheres);
  Status overlapShapes(const Geometry<T>& a, const Transform<T>& poseA, const Geometry<T>& b, const Transform<T>& poseB,
                       bool valid, bool& hit);
  Status narrowPhase(std::uint32_t shapeA, std::uint32_t shapeB, bool& hit);
  Status linkPairCollides(const CheckedPair& pair, bool& hit);

  std::shared_ptr<const RobotModel<T>> model_;
  std::shared_ptr<const detail::KinematicChain<T>> chain_;  // compiled forward kinematics (immutable, shared)
  std::vector<CheckedPair> checkedPairs_;    // link pairs with shapes that the allowed-collision matrix leaves,
                                             // most often touching first (orderPairsByContactFrequency)
  std::vector<std::uint32_t> shapedLinks_;   // links with at least one shape
  std::vector<ShapeBound> shapeBounds_;
  std::vector<std::uint32_t> linkBody_;
  std::vector<Vec3<T>> linkCentreInBody_;    // per link: sphere enclosing its shapes' spheres
  std::vector<T> linkRadius_;
  std::vector<LinkCapsule> linkCapsules_;
  T slack_ = T(0);                           // absolute culling slack (rounding of world placements)
  // Per configuration.
  std::vector<Mat3<T>> bodyRotations_;
  std::vector<Vec3<T>> bodyPositions_;
  std::vector<Quat<T>> bodyQuats_;                   // valid when quatStamp_[b] == stamp_
  std::vector<Vec3<T>> linkCentres_, shapeCentres_;  // world sphere centres
  std::vector<Transform<T>> shapePoses_;             // valid when poseStamp_[s] == stamp_
  std::vector<OrientedBox<T>> shapeBoxes_;           // valid when boxStamp_[s] == stamp_
  std::vector<Vec3<T>> capsuleStarts_, capsuleSpans_;  // world; valid when capsuleStamp_[s] == stamp_
  std::vector<Vec3<T>> linkCapsuleStarts_, linkCapsuleSpans_;  // world; valid when linkCapsuleStamp_[l] == stamp_
  std::vector<std::uint32_t> boxStamp_, poseStamp_, quatStamp_, capsuleStamp_, linkCapsuleStamp_;
  std::uint32_t stamp_ = 0;
  std::vector<LinkPair> hits_;              // colliding pairs found so far in this call
  std::size_t lastNarrow_ = 0;
};

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
