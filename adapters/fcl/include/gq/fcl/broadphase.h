#pragma once
// gq::fcl::DynamicAABBTreeCollisionManager<S>: a drop-in ::fcl::BroadPhaseCollisionManager<S>.
//  - World bounds are gq's exact AABBs of each geometry at the object's current transform (computeGeomBounds), not
//    FCL's CollisionObject::computeAABB, which for any rotated object takes the cube around the bounding sphere.
//    They are read from getTransform() at setup()/update(): calling computeAABB() is not needed.
//  - The tree is a binary AABB tree built top-down (median split along the widest centroid axis); update() refits
//    it bottom-up and rebuilds it when the refit root grew by more than kRebuildGrowth in surface area.
//  - Callbacks follow FCL: return true to stop; a distance callback lowers `dist`, which prunes the traversal.
//    Self collision reports each overlapping pair once. DefaultCollisionFunction / DefaultDistanceFunction below run
//    gq::fcl::collide / distance on ::fcl::DefaultCollisionData / DefaultDistanceData.
#include <cstddef>
#include <memory>
#include <unordered_map>
#include <vector>

#include <fcl/broadphase/broadphase_collision_manager.h>
#include <fcl/broadphase/default_broadphase_callbacks.h>
#include <fcl/broadphase/detail/hierarchy_tree.h>

#include "gq/fcl/collision.h"

namespace gq::fcl {

template <typename S>
class DynamicAABBTreeCollisionManager : public ::fcl::BroadPhaseCollisionManager<S> {
  // FCL's tree type, filled by getTree() from gq's tree (declared first: the public references below bind to it).
  mutable ::fcl::detail::HierarchyTree<::fcl::AABB<S>> fclTree_;

 public:
  // FCL's public typedefs and tuning members, with FCL's defaults. gq's own tree does not use FCL's balancing:
  // tree_init_level, tree_topdown_balance_threshold and tree_topdown_level shape the FCL tree getTree() returns;
  // max_tree_nonbalanced_level and tree_incremental_balance_pass are accepted and have no effect (gq rebuilds its
  // tree when a refit grows the root's area by more than 2x); octree_as_geometry_collide / _distance are accepted and
  // an octree object is always queried as one geometry (FCL's answer with the flag true; with it false FCL calls the
  // callback once per occupied cell with a temporary box object, the same pairs and the same minimum distance).
  using DynamicAABBNode = ::fcl::detail::NodeBase<::fcl::AABB<S>>;
  using DynamicAABBTable = std::unordered_map<::fcl::CollisionObject<S>*, DynamicAABBNode*>;

  int max_tree_nonbalanced_level = 10;
  int tree_incremental_balance_pass = 10;
  int& tree_topdown_balance_threshold;
  int& tree_topdown_level;
  int tree_init_level = 0;
  bool octree_as_geometry_collide = true;
  bool octree_as_geometry_distance = false;

  using Object = ::fcl::CollisionObject<S>;
  using CollisionCallBack = ::fcl::CollisionCallBack<S>;
  using DistanceCallBack = ::fcl::DistanceCallBack<S>;

  DynamicAABBTreeCollisionManager();
  ~DynamicAABBTreeCollisionManager() override;

  void registerObjects(const std::vector<Object*>& objects) override;
  void registerObject(Object* obj) override;
  void unregisterObject(Object* obj) override;
  void setup() override;
  void update() override;
  void update(Object* updated) override;
  void update(const std::vector<Object*>& updated) override;
  void clear() override;
  void getObjects(std::vector<Object*>& objs) const override;
  void collide(Object* obj, void* cdata, CollisionCallBack callback) const override;
  void distance(Object* obj, void* cdata, DistanceCallBack callback) const override;
  void collide(void* cdata, CollisionCallBack callback) const override;
  void distance(void* cdata, DistanceCallBack callback) const override;
  void collide(::fcl::BroadPhaseCollisionManager<S>* other, void* cdata, CollisionCallBack callback) const override;
  void distance(::fcl::BroadPhaseCollisionManager<S>* other, void* cdata, DistanceCallBack callback) const override;
  bool empty() const override;
  size_t size() const override;

  // FCL's HierarchyTree over the registered objects (node data = the CollisionObject*), built on each call from gq's
  // world boxes with FCL's init(leaves, tree_init_level); valid until the next getTree() call or the manager's end.
  // gq's queries do not use it.
  const ::fcl::detail::HierarchyTree<::fcl::AABB<S>>& getTree() const;

  // Number of AABB tests the last query ran (diagnostics).
  std::size_t lastBoxTests() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

using DynamicAABBTreeCollisionManagerf = DynamicAABBTreeCollisionManager<float>;
using DynamicAABBTreeCollisionManagerd = DynamicAABBTreeCollisionManager<double>;

// FCL's default callbacks with gq::fcl's narrow phase: cdata is ::fcl::DefaultCollisionData<S> /
// ::fcl::DefaultDistanceData<S>; stop once the request is satisfied (collision) or the distance is <= 0.
template <typename S> bool DefaultCollisionFunction(::fcl::CollisionObject<S>* o1, ::fcl::CollisionObject<S>* o2, void* data) {
  auto* cdata = static_cast<::fcl::DefaultCollisionData<S>*>(data);
  if (cdata->done) return true;
  gq::fcl::collide(o1, o2, cdata->request, cdata->result);
  if (!cdata->request.enable_cost && cdata->result.isCollision() &&
      cdata->result.numContacts() >= cdata->request.num_max_contacts)
    cdata->done = true;
  return cdata->done;
}

template <typename S>
bool DefaultDistanceFunction(::fcl::CollisionObject<S>* o1, ::fcl::CollisionObject<S>* o2, void* data, S& dist) {
  auto* cdata = static_cast<::fcl::DefaultDistanceData<S>*>(data);
  if (cdata->done) {
    dist = cdata->result.min_distance;
    return true;
  }
  gq::fcl::distance(o1, o2, cdata->request, cdata->result);
  dist = cdata->result.min_distance;
  return dist <= 0 || cdata->done;  // in collision or touching: stop (FCL does not set done here)
}

}  // namespace gq::fcl
