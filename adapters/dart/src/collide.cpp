#include <vector>

#include <dart/collision/CollisionFilter.hpp>

#include "collision_object.h"
#include "contacts.h"
#include "gq/dart/collision_detector.h"
#include "group_cast.h"

namespace gq {
namespace dart {
namespace {

namespace dc = ::dart::collision;

// The pairs of `pairs` (ids of `first` and `second`) in order; stops at the first collision without a result, or
// when maxNumContacts are reached.
bool collidePairs(const CollisionGroup& first, const CollisionGroup& second, const std::vector<ScenePair>& pairs,
                  const dc::CollisionOption& option, dc::CollisionResult* result) {
  bool colliding = false;
  for (const ScenePair& pair : pairs) {
    const CollisionObject* o1 = first.object(pair.id0);
    const CollisionObject* o2 = second.object(pair.id1);
    if (o1 == nullptr || o2 == nullptr || o1 == o2) continue;
    if (option.collisionFilter && option.collisionFilter->ignoresCollision(o1, o2)) continue;
    if (result == nullptr) return true;
    const std::size_t have = result->getNumContacts();
    if (have >= option.maxNumContacts) break;
    if (!option.enableContact) {
      // A contact without geometry names the pair, as DART's other detectors report it.
      dc::CollisionResult pairContacts;
      if (fillContacts(*o1, *o2, 1, pairContacts) == 0) continue;
      dc::Contact contact;
      contact.collisionObject1 = const_cast<CollisionObject*>(o1);
      contact.collisionObject2 = const_cast<CollisionObject*>(o2);
      result->addContact(contact);
      colliding = true;
      continue;
    }
    if (fillContacts(*o1, *o2, option.maxNumContacts - have, *result) > 0) colliding = true;
  }
  return colliding;
}

}  // namespace

bool CollisionDetector::collide(dc::CollisionGroup* group, const dc::CollisionOption& option,
                                dc::CollisionResult* result) {
  if (result != nullptr) result->clear();
  CollisionGroup *g = nullptr, *same = nullptr;
  if (option.maxNumContacts == 0 || !synchronizedGroups(group, group, g, same)) return false;
  std::vector<ScenePair> pairs;
  if (!g->scene().overlappingPairs(pairs).ok()) return false;
  return collidePairs(*g, *g, pairs, option, result);
}

bool CollisionDetector::collide(dc::CollisionGroup* group1, dc::CollisionGroup* group2,
                                const dc::CollisionOption& option, dc::CollisionResult* result) {
  if (result != nullptr) result->clear();
  CollisionGroup *g1 = nullptr, *g2 = nullptr;
  if (option.maxNumContacts == 0 || !synchronizedGroups(group1, group2, g1, g2)) return false;
  std::vector<ScenePair> pairs;
  if (!g1->scene().overlappingPairs(g2->scene(), pairs).ok()) return false;
  return collidePairs(*g1, *g2, pairs, option, result);
}

}  // namespace dart
}  // namespace gq
