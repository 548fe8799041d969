#pragma once
// The gq group behind a DART group pointer, or null when the group belongs to another detector.
#include "collision_group.h"

namespace gq {
namespace dart {

inline CollisionGroup* gqGroup(::dart::collision::CollisionGroup* group) {
  return dynamic_cast<CollisionGroup*>(group);
}

}  // namespace dart
}  // namespace gq
