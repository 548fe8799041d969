#include "collision_object.h"

#include <dart/dynamics/Shape.hpp>
#include <dart/dynamics/ShapeFrame.hpp>

namespace gq {
namespace dart {

CollisionObject::CollisionObject(::dart::collision::CollisionDetector* detector,
                                 const ::dart::dynamics::ShapeFrame* frame)
    : ::dart::collision::CollisionObject(detector, frame) {
  refresh();
}

void CollisionObject::refresh() {
  ++generation_;
  const auto shape = mShapeFrame->getShape();
  shapeSeen_ = shape.get();
  versionSeen_ = shape ? shape->getVersion() : 0;
  if (!shape) {
    status_ = Status(StatusCode::InvalidArgument, "the shape frame has no shape");
    converted_ = ConvertedShape();
    return;
  }
  ConvertedShape converted;
  status_ = convertShape(*shape, converted);
  converted_ = status_.ok() ? std::move(converted) : ConvertedShape();
  updateEngineData();
}

void CollisionObject::updateEngineData() {
  const auto& shape = mShapeFrame->getShape();
  if (shape.get() != shapeSeen_ || (shape && shape->getVersion() != versionSeen_)) {
    refresh();
    return;
  }
  const Eigen::Isometry3d& world = mShapeFrame->getWorldTransform();
  Transform<double> frame(world.translation(), Quat<double>(world.linear()).normalized());
  pose_ = frame * converted_.offset;
  pose_.q.normalize();
}

}  // namespace dart
}  // namespace gq
