#include "gq/dart/collision_detector.h"

#include <dart/dynamics/ShapeFrame.hpp>

#include "collision_group.h"
#include "collision_object.h"

namespace gq {
namespace dart {

CollisionDetector::CollisionDetector() {
  mCollisionObjectManager.reset(new ManagerForSharableCollisionObjects(this));
}

CollisionDetector::~CollisionDetector() = default;

std::shared_ptr<CollisionDetector> CollisionDetector::create() {
  return std::shared_ptr<CollisionDetector>(new CollisionDetector());
}

std::shared_ptr<::dart::collision::CollisionDetector> CollisionDetector::cloneWithoutCollisionObjects() const {
  return create();
}

const std::string& CollisionDetector::getType() const { return getStaticType(); }

const std::string& CollisionDetector::getStaticType() {
  static const std::string type = "gq";
  return type;
}

std::unique_ptr<::dart::collision::CollisionGroup> CollisionDetector::createCollisionGroup() {
  return std::make_unique<CollisionGroup>(shared_from_this());
}

std::unique_ptr<::dart::collision::CollisionObject> CollisionDetector::createCollisionObject(
    const ::dart::dynamics::ShapeFrame* shapeFrame) {
  return std::unique_ptr<::dart::collision::CollisionObject>(new CollisionObject(this, shapeFrame));
}

void CollisionDetector::refreshCollisionObject(::dart::collision::CollisionObject* object) {
  static_cast<CollisionObject*>(object)->refresh();
}

}  // namespace dart
}  // namespace gq
