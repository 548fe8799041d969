#pragma once
// One DART ShapeFrame as a gq shape and its world pose.
#include <cstdint>

#include <dart/collision/CollisionObject.hpp>

#include "shape_conversion.h"

namespace gq {
namespace dart {

class CollisionObject final : public ::dart::collision::CollisionObject {
 public:
  CollisionObject(::dart::collision::CollisionDetector* detector, const ::dart::dynamics::ShapeFrame* frame);

  // Converts the frame's shape again; generation() counts the conversions. updateEngineData() calls it when the
  // frame's shape or its version changed (DART's groups notice that only for shapes of subscribed skeletons and
  // body nodes).
  void refresh();
  std::uint64_t generation() const { return generation_; }
  // Whether gq models the shape (conversionStatus() says why not); an object gq does not model takes part in no
  // query.
  bool converted() const { return status_.ok(); }
  const Status& conversionStatus() const { return status_; }
  const Shape<double>& shape() const { return converted_.shape; }
  // The gq shape's world pose, as of the last updateEngineData().
  const Transform<double>& pose() const { return pose_; }

  void updateEngineData() override;

 private:
  ConvertedShape converted_;
  Status status_;
  Transform<double> pose_;
  std::uint64_t generation_ = 0;
  const void* shapeSeen_ = nullptr;
  std::size_t versionSeen_ = 0;
};

}  // namespace dart
}  // namespace gq
