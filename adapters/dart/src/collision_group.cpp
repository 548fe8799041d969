#include "collision_group.h"

#include <algorithm>

#include "collision_object.h"

namespace gq {
namespace dart {

CollisionGroup::CollisionGroup(const ::dart::collision::CollisionDetectorPtr& detector)
    : ::dart::collision::CollisionGroup(detector) {}

CollisionGroup::~CollisionGroup() = default;

void CollisionGroup::synchronize() { updateEngineData(); }

CollisionObject* CollisionGroup::object(InstanceId id) const {
  const auto it = byId_.find(id);
  return it == byId_.end() ? nullptr : it->second;
}

InstanceId CollisionGroup::idOf(const CollisionObject* object) const {
  const auto it = entries_.find(object);
  return it == entries_.end() ? 0 : it->second.id;
}

void CollisionGroup::initializeEngineData() {}

void CollisionGroup::insert(CollisionObject* object, Entry& entry) {
  entry.generation = object->generation();
  entry.inScene = false;
  if (!object->converted()) return;
  entry.inScene = scene_.add(entry.id, object->shape(), object->pose()).ok();
}

void CollisionGroup::addCollisionObjectToEngine(::dart::collision::CollisionObject* base) {
  auto* object = static_cast<CollisionObject*>(base);
  if (entries_.count(object) != 0) return;
  Entry& entry = entries_[object];
  entry.id = nextId_++;
  byId_[entry.id] = object;
  objects_.push_back(object);
  insert(object, entry);
}

void CollisionGroup::addCollisionObjectsToEngine(const std::vector<::dart::collision::CollisionObject*>& objects) {
  for (auto* object : objects) addCollisionObjectToEngine(object);
}

void CollisionGroup::removeCollisionObjectFromEngine(::dart::collision::CollisionObject* base) {
  auto* object = static_cast<CollisionObject*>(base);
  const auto it = entries_.find(object);
  if (it == entries_.end()) return;
  if (it->second.inScene) (void)scene_.remove(it->second.id);
  byId_.erase(it->second.id);
  entries_.erase(it);
  objects_.erase(std::remove(objects_.begin(), objects_.end(), object), objects_.end());
}

void CollisionGroup::removeAllCollisionObjectsFromEngine() {
  scene_.clear();
  entries_.clear();
  byId_.clear();
  objects_.clear();
}

void CollisionGroup::updateCollisionGroupEngineData() {
  for (CollisionObject* object : objects_) {
    Entry& entry = entries_[object];
    if (entry.generation != object->generation()) {
      if (entry.inScene) (void)scene_.remove(entry.id);
      insert(object, entry);
    } else if (entry.inScene) {
      (void)scene_.setPose(entry.id, object->pose());
    }
  }
}

}  // namespace dart
}  // namespace gq
