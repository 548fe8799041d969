#pragma once
// A DART CollisionGroup whose broadphase is a gq::Scene (a dynamic AABB tree; planes beside it).
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <dart/collision/CollisionGroup.hpp>

#include <gq/scene.h>

namespace gq {
namespace dart {

class CollisionObject;

class CollisionGroup final : public ::dart::collision::CollisionGroup {
 public:
  explicit CollisionGroup(const ::dart::collision::CollisionDetectorPtr& detector);
  ~CollisionGroup() override;

  // Brings the shapes (re-converted ones re-added) and their poses up to date, as DART does before every query.
  void synchronize();

  const Scene<double>& scene() const { return scene_; }
  // The object of a scene instance id.
  CollisionObject* object(InstanceId id) const;
  // The scene instance id of an object of this group (0: not in the group).
  InstanceId idOf(const CollisionObject* object) const;
  // Every object gq models, in the order they were added.
  const std::vector<CollisionObject*>& objects() const { return objects_; }

 protected:
  void initializeEngineData() override;
  void addCollisionObjectToEngine(::dart::collision::CollisionObject* object) override;
  void addCollisionObjectsToEngine(const std::vector<::dart::collision::CollisionObject*>& objects) override;
  void removeCollisionObjectFromEngine(::dart::collision::CollisionObject* object) override;
  void removeAllCollisionObjectsFromEngine() override;
  void updateCollisionGroupEngineData() override;

 private:
  struct Entry {
    InstanceId id = 0;
    std::uint64_t generation = 0;
    bool inScene = false;
  };
  void insert(CollisionObject* object, Entry& entry);

  Scene<double> scene_;
  std::unordered_map<const CollisionObject*, Entry> entries_;
  std::unordered_map<InstanceId, CollisionObject*> byId_;
  std::vector<CollisionObject*> objects_;
  InstanceId nextId_ = 1;
};

}  // namespace dart
}  // namespace gq
