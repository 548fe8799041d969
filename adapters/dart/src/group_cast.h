#pragma once
// The gq group behind a DART group pointer, or null when the group belongs to another detector.
#include "collision_group.h"

namespace gq {
namespace dart {

inline CollisionGroup* gqGroup(::dart::collision::CollisionGroup* group) {
  return dynamic_cast<CollisionGroup*>(group);
}

// The gq groups behind `group1` and `group2`, synchronised for a query (a group given twice once); false, with
// nothing synchronised, when either belongs to another detector.
inline bool synchronizedGroups(::dart::collision::CollisionGroup* group1, ::dart::collision::CollisionGroup* group2,
                               CollisionGroup*& g1, CollisionGroup*& g2) {
  g1 = gqGroup(group1);
  g2 = gqGroup(group2);
  if (g1 == nullptr || g2 == nullptr) return false;
  g1->synchronize();
  if (g2 != g1) g2->synchronize();
  return true;
}

}  // namespace dart
}  // namespace gq
