#pragma once
// gq::dart::CollisionDetector: DART's collision detector interface answered by GeomQuery, registered in DART's factory
// under the name "gq" (CollisionDetector::getFactory()->create("gq"), a .skel file's <collision_detector>gq).
// Linking the gq::dart target is enough for the factory to know "gq": the target's link options keep the registering
// object file in every program that links it.
//
// Conventions (DART's):
//  - collide: contacts carry the normal from object 2 towards object 1, a positive penetrationDepth, the point
//    between the two surfaces, and triangle ids (triID1 / triID2) for meshes and heightmaps; maxNumContacts bounds
//    the contacts of the whole query; the CollisionFilter is asked for every candidate pair.
//  - distance: signed (negative: minus the penetration depth), clamped below by distanceLowerBound, nearest points
//    when asked; the query stops at the first pair at or below distanceLowerBound.
//  - raycast: the closest hit, or every hit sorted by distance (RaycastOption::mEnableAllHits); fraction along
//    from -> to.
// Shapes: docs/dart.md lists how each DART shape is converted.
#include <memory>
#include <string>

#include <dart/collision/CollisionDetector.hpp>

namespace gq {
namespace dart {

class CollisionDetector : public ::dart::collision::CollisionDetector {
 public:
  using ::dart::collision::CollisionDetector::createCollisionGroup;

  static std::shared_ptr<CollisionDetector> create();
  ~CollisionDetector() override;

  std::shared_ptr<::dart::collision::CollisionDetector> cloneWithoutCollisionObjects() const override;
  const std::string& getType() const override;
  // "gq": the factory key.
  static const std::string& getStaticType();

  std::unique_ptr<::dart::collision::CollisionGroup> createCollisionGroup() override;

  bool collide(::dart::collision::CollisionGroup* group,
               const ::dart::collision::CollisionOption& option = ::dart::collision::CollisionOption(false, 1u, nullptr),
               ::dart::collision::CollisionResult* result = nullptr) override;
  bool collide(::dart::collision::CollisionGroup* group1, ::dart::collision::CollisionGroup* group2,
               const ::dart::collision::CollisionOption& option = ::dart::collision::CollisionOption(false, 1u, nullptr),
               ::dart::collision::CollisionResult* result = nullptr) override;

  double distance(::dart::collision::CollisionGroup* group,
                  const ::dart::collision::DistanceOption& option = ::dart::collision::DistanceOption(false, 0.0,
                                                                                                     nullptr),
                  ::dart::collision::DistanceResult* result = nullptr) override;
  double distance(::dart::collision::CollisionGroup* group1, ::dart::collision::CollisionGroup* group2,
                  const ::dart::collision::DistanceOption& option = ::dart::collision::DistanceOption(false, 0.0,
                                                                                                     nullptr),
                  ::dart::collision::DistanceResult* result = nullptr) override;

  bool raycast(::dart::collision::CollisionGroup* group, const Eigen::Vector3d& from, const Eigen::Vector3d& to,
               const ::dart::collision::RaycastOption& option = ::dart::collision::RaycastOption(),
               ::dart::collision::RaycastResult* result = nullptr) override;

 protected:
  CollisionDetector();

  std::unique_ptr<::dart::collision::CollisionObject> createCollisionObject(
      const ::dart::dynamics::ShapeFrame* shapeFrame) override;
  void refreshCollisionObject(::dart::collision::CollisionObject* object) override;
};

}  // namespace dart
}  // namespace gq
