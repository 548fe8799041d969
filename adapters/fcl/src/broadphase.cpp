// The broadphase manager: exact per-object world AABBs in a binary AABB tree (see gq/fcl/broadphase.h).
#include "gq/fcl/broadphase.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "convert.h"
#include "fcl_tree.h"
#include "gq/query.h"

namespace gq::fcl {
namespace {

// update() rebuilds the tree when refitting grew the root's surface area by more than this factor (a refit tree
// whose objects moved far apart overlaps itself and loses its pruning).
constexpr double kRebuildGrowth = 2.0;

template <class S> S surfaceArea(const Bounds3<S>& b) {
  const Vec3<S> e = (b.max - b.min).cwiseMax(Vec3<S>::Zero());
  return S(2) * (e.x() * e.y() + e.y() * e.z() + e.z() * e.x());
}

// Euclidean distance between two boxes (0 when they overlap).
template <class S> S boxDistance(const Bounds3<S>& a, const Bounds3<S>& b) {
  const Vec3<S> gap = (a.min - b.max).cwiseMax(b.min - a.max).cwiseMax(Vec3<S>::Zero());
  return gap.norm();
}

template <class S> Bounds3<S> merged(const Bounds3<S>& a, const Bounds3<S>& b) {
  Bounds3<S> m = a;
  m.include(b);
  return m;
}

// World AABB of an object: gq's exact bounds of the converted geometry (a BVHModel not cooked yet: its FCL root
// BV's box, placed); FCL's own AABB for geometries gq does not convert (octrees, point clouds) or whose bounds are
// unbounded (planes, half-spaces: FCL's huge box).
template <class S> Bounds3<S> worldBounds(::fcl::CollisionObject<S>* obj) {
  internal::Converted<S> c;
  const auto* geometry = obj->collisionGeometry().get();
  if (internal::convert(geometry, c, internal::MeshUse::TreeAllowed) == internal::Conversion::Ok && !c.isPlaneLike()) {
    Bounds3<S> b;
    const Transform<S> pose = internal::shapePose(c, obj->getTransform());
    if (c.isTree()) b = internal::treeBounds(c.tree(), pose);
    if (c.isTree() ? isFinite(b.min) && isFinite(b.max) : computeGeomBounds(b, c.geometry(), pose, S(0), S(1)).ok() && isFinite(b.min) && isFinite(b.max)) return b;
  }
  obj->computeAABB();
  const ::fcl::AABB<S>& a = obj->getAABB();
  return Bounds3<S>::fromMinMax(a.min_, a.max_);
}

}  // namespace

template <typename S> struct DynamicAABBTreeCollisionManager<S>::Impl {
  struct Node {
    Bounds3<S> box;
    int left = -1, right = -1;  // children; both -1 for a leaf
    int item = -1;              // object index of a leaf
    int parent = -1;
    bool leaf() const { return left < 0; }
  };

  std::vector<Object*> objects;
  std::vector<Bounds3<S>> bounds;  // per object, world frame
  std::unordered_map<const Object*, std::size_t> index;
  std::vector<Node> nodes;
  std::vector<int> leafOf;  // object -> leaf node
  int root = -1;
  S builtArea = S(0);
  bool dirty = true;
  std::size_t boxTests = 0;

  // ---- build / refit ----
  int build(std::vector<int>& items, std::size_t begin, std::size_t end, int parent) {
    const int id = int(nodes.size());
    nodes.emplace_back();
    nodes[id].parent = parent;
    if (end - begin == 1) {
      nodes[id].item = items[begin];
      nodes[id].box = bounds[std::size_t(items[begin])];
      leafOf[std::size_t(items[begin])] = id;
      return id;
    }
    Bounds3<S> centroids;
    for (std::size_t i = begin; i < end; ++i) centroids.include(bounds[std::size_t(items[i])].center());
    int axis = 0;
    (centroids.max - centroids.min).maxCoeff(&axis);
    const std::size_t mid = begin + (end - begin) / 2;
    std::nth_element(items.begin() + long(begin), items.begin() + long(mid), items.begin() + long(end), [&](int a, int b) {
      return bounds[std::size_t(a)].center()[axis] < bounds[std::size_t(b)].center()[axis];
    });
    const int left = build(items, begin, mid, id);
    const int right = build(items, mid, end, id);
    nodes[id].left = left;
    nodes[id].right = right;
    nodes[id].box = merged(nodes[left].box, nodes[right].box);
    return id;
  }

  void rebuild() {
    nodes.clear();
    leafOf.assign(objects.size(), -1);
    root = -1;
    if (!objects.empty()) {
      std::vector<int> items(objects.size());
      for (std::size_t i = 0; i < items.size(); ++i) items[i] = int(i);
      nodes.reserve(2 * objects.size());
      root = build(items, 0, items.size(), -1);
      builtArea = surfaceArea(nodes[root].box);
    }
    dirty = false;
  }

  // Parents precede their children in `nodes`, so one reverse sweep refits every box.
  void refitAll() {
    for (std::size_t n = nodes.size(); n-- > 0;) {
      Node& node = nodes[n];
      node.box = node.leaf() ? bounds[std::size_t(node.item)] : merged(nodes[node.left].box, nodes[node.right].box);
    }
  }

  void refitPath(int leaf) {
    nodes[leaf].box = bounds[std::size_t(nodes[leaf].item)];
    for (int n = nodes[leaf].parent; n >= 0; n = nodes[n].parent)
      nodes[n].box = merged(nodes[nodes[n].left].box, nodes[nodes[n].right].box);
  }

  void ensureBuilt() {
    if (dirty) rebuild();
  }

  bool overlaps(const Bounds3<S>& a, const Bounds3<S>& b) {
    ++boxTests;
    return a.overlaps(b);
  }

  // ---- collision traversals; each returns true when the callback asked to stop ----
  bool collideQuery(int n, const Bounds3<S>& box, Object* query, void* cdata, CollisionCallBack cb) {
    if (!overlaps(nodes[n].box, box)) return false;
    if (nodes[n].leaf()) return cb(objects[std::size_t(nodes[n].item)], query, cdata);
    return collideQuery(nodes[n].left, box, query, cdata, cb) || collideQuery(nodes[n].right, box, query, cdata, cb);
  }

  // Node a of this tree against node b of `other` (other == this for self collision).
  bool collidePair(int a, const Impl& other, int b, void* cdata, CollisionCallBack cb) {
    const Node& na = nodes[a];
    const Node& nb = other.nodes[b];
    if (!overlaps(na.box, nb.box)) return false;
    if (na.leaf() && nb.leaf()) return cb(objects[std::size_t(na.item)], other.objects[std::size_t(nb.item)], cdata);
    // Descend the larger box (or the only inner node).
    if (nb.leaf() || (!na.leaf() && surfaceArea(na.box) >= surfaceArea(nb.box)))
      return collidePair(na.left, other, b, cdata, cb) || collidePair(na.right, other, b, cdata, cb);
    return collidePair(a, other, nb.left, cdata, cb) || collidePair(a, other, nb.right, cdata, cb);
  }

  bool collideSelf(int n, void* cdata, CollisionCallBack cb) {
    const Node& node = nodes[n];
    if (node.leaf()) return false;
    return collideSelf(node.left, cdata, cb) || collideSelf(node.right, cdata, cb) ||
           collidePair(node.left, *this, node.right, cdata, cb);
  }

  // ---- distance traversals: `dist` is the best distance so far; subtrees farther than it are skipped ----
  bool distanceQuery(int n, const Bounds3<S>& box, Object* query, void* cdata, DistanceCallBack cb, S& dist) {
    ++boxTests;
    if (boxDistance(nodes[n].box, box) > dist) return false;
    if (nodes[n].leaf()) return cb(objects[std::size_t(nodes[n].item)], query, cdata, dist);
    int first = nodes[n].left, second = nodes[n].right;
    if (boxDistance(nodes[second].box, box) < boxDistance(nodes[first].box, box)) std::swap(first, second);
    return distanceQuery(first, box, query, cdata, cb, dist) || distanceQuery(second, box, query, cdata, cb, dist);
  }

  bool distancePair(int a, const Impl& other, int b, void* cdata, DistanceCallBack cb, S& dist) {
    const Node& na = nodes[a];
    const Node& nb = other.nodes[b];
    ++boxTests;
    if (boxDistance(na.box, nb.box) > dist) return false;
    if (na.leaf() && nb.leaf())
      return cb(objects[std::size_t(na.item)], other.objects[std::size_t(nb.item)], cdata, dist);
    if (nb.leaf() || (!na.leaf() && surfaceArea(na.box) >= surfaceArea(nb.box))) {
      int first = na.left, second = na.right;
      if (boxDistance(nodes[second].box, nb.box) < boxDistance(nodes[first].box, nb.box)) std::swap(first, second);
      return distancePair(first, other, b, cdata, cb, dist) || distancePair(second, other, b, cdata, cb, dist);
    }
    int first = nb.left, second = nb.right;
    if (boxDistance(na.box, other.nodes[second].box) < boxDistance(na.box, other.nodes[first].box)) std::swap(first, second);
    return distancePair(a, other, first, cdata, cb, dist) || distancePair(a, other, second, cdata, cb, dist);
  }

  bool distanceSelf(int n, void* cdata, DistanceCallBack cb, S& dist) {
    const Node& node = nodes[n];
    if (node.leaf()) return false;
    return distanceSelf(node.left, cdata, cb, dist) || distanceSelf(node.right, cdata, cb, dist) ||
           distancePair(node.left, *this, node.right, cdata, cb, dist);
  }
};

template <typename S>
DynamicAABBTreeCollisionManager<S>::DynamicAABBTreeCollisionManager()
    : fclTree_(),
      tree_topdown_balance_threshold(fclTree_.bu_threshold),
      tree_topdown_level(fclTree_.topdown_level),
      impl_(new Impl()) {
  tree_topdown_balance_threshold = 2;  // FCL's defaults
  tree_topdown_level = 0;
}
template <typename S> DynamicAABBTreeCollisionManager<S>::~DynamicAABBTreeCollisionManager() = default;

template <typename S> void DynamicAABBTreeCollisionManager<S>::registerObjects(const std::vector<Object*>& objs) {
  for (Object* o : objs) registerObject(o);
  setup();
}

template <typename S> void DynamicAABBTreeCollisionManager<S>::registerObject(Object* obj) {
  if (!obj || impl_->index.count(obj)) return;
  impl_->index.emplace(obj, impl_->objects.size());
  impl_->objects.push_back(obj);
  impl_->bounds.push_back(worldBounds(obj));
  impl_->dirty = true;
}

template <typename S> void DynamicAABBTreeCollisionManager<S>::unregisterObject(Object* obj) {
  auto it = impl_->index.find(obj);
  if (it == impl_->index.end()) return;
  const std::size_t i = it->second, last = impl_->objects.size() - 1;
  impl_->index.erase(it);
  if (i != last) {  // move the last object into the hole
    impl_->objects[i] = impl_->objects[last];
    impl_->bounds[i] = impl_->bounds[last];
    impl_->index[impl_->objects[i]] = i;
  }
  impl_->objects.pop_back();
  impl_->bounds.pop_back();
  impl_->dirty = true;
}

template <typename S> void DynamicAABBTreeCollisionManager<S>::setup() { impl_->rebuild(); }

template <typename S> void DynamicAABBTreeCollisionManager<S>::update() {
  Impl& m = *impl_;
  for (std::size_t i = 0; i < m.objects.size(); ++i) m.bounds[i] = worldBounds(m.objects[i]);
  if (m.dirty || m.root < 0) return m.rebuild();
  m.refitAll();
  if (surfaceArea(m.nodes[m.root].box) > S(kRebuildGrowth) * m.builtArea) m.rebuild();
}

template <typename S> void DynamicAABBTreeCollisionManager<S>::update(Object* updated) {
  Impl& m = *impl_;
  auto it = m.index.find(updated);
  if (it == m.index.end()) return;
  m.bounds[it->second] = worldBounds(updated);
  if (!m.dirty) m.refitPath(m.leafOf[it->second]);
}

template <typename S> void DynamicAABBTreeCollisionManager<S>::update(const std::vector<Object*>& updated) {
  for (Object* o : updated) update(o);
}

template <typename S> void DynamicAABBTreeCollisionManager<S>::clear() {
  impl_->objects.clear();
  impl_->bounds.clear();
  impl_->index.clear();
  impl_->dirty = true;
  impl_->rebuild();
}

template <typename S> void DynamicAABBTreeCollisionManager<S>::getObjects(std::vector<Object*>& objs) const {
  objs = impl_->objects;
}

template <typename S>
void DynamicAABBTreeCollisionManager<S>::collide(Object* obj, void* cdata, CollisionCallBack callback) const {
  Impl& m = *impl_;
  m.ensureBuilt();
  m.boxTests = 0;
  if (m.root < 0 || !obj) return;
  m.collideQuery(m.root, worldBounds(obj), obj, cdata, callback);
}

template <typename S>
void DynamicAABBTreeCollisionManager<S>::distance(Object* obj, void* cdata, DistanceCallBack callback) const {
  Impl& m = *impl_;
  m.ensureBuilt();
  m.boxTests = 0;
  if (m.root < 0 || !obj) return;
  S dist = std::numeric_limits<S>::max();
  m.distanceQuery(m.root, worldBounds(obj), obj, cdata, callback, dist);
}

template <typename S> void DynamicAABBTreeCollisionManager<S>::collide(void* cdata, CollisionCallBack callback) const {
  Impl& m = *impl_;
  m.ensureBuilt();
  m.boxTests = 0;
  if (m.root >= 0) m.collideSelf(m.root, cdata, callback);
}

template <typename S> void DynamicAABBTreeCollisionManager<S>::distance(void* cdata, DistanceCallBack callback) const {
  Impl& m = *impl_;
  m.ensureBuilt();
  m.boxTests = 0;
  S dist = std::numeric_limits<S>::max();
  if (m.root >= 0) m.distanceSelf(m.root, cdata, callback, dist);
}

template <typename S>
void DynamicAABBTreeCollisionManager<S>::collide(::fcl::BroadPhaseCollisionManager<S>* other, void* cdata,
                                                 CollisionCallBack callback) const {
  Impl& m = *impl_;
  m.ensureBuilt();
  m.boxTests = 0;
  if (!other || m.root < 0 || other->empty()) return;
  if (auto* same = dynamic_cast<DynamicAABBTreeCollisionManager<S>*>(other)) {
    Impl& o = *same->impl_;
    o.ensureBuilt();
    m.collidePair(m.root, o, o.root, cdata, callback);
    return;
  }
  // Another manager type: its objects one by one against this tree (this manager's object first, as FCL).
  std::vector<Object*> theirs;
  other->getObjects(theirs);
  for (Object* obj : theirs)
    if (m.collideQuery(m.root, worldBounds(obj), obj, cdata, callback)) return;
}

template <typename S>
void DynamicAABBTreeCollisionManager<S>::distance(::fcl::BroadPhaseCollisionManager<S>* other, void* cdata,
                                                  DistanceCallBack callback) const {
  Impl& m = *impl_;
  m.ensureBuilt();
  m.boxTests = 0;
  if (!other || m.root < 0 || other->empty()) return;
  S dist = std::numeric_limits<S>::max();
  if (auto* same = dynamic_cast<DynamicAABBTreeCollisionManager<S>*>(other)) {
    Impl& o = *same->impl_;
    o.ensureBuilt();
    m.distancePair(m.root, o, o.root, cdata, callback, dist);
    return;
  }
  std::vector<Object*> theirs;
  other->getObjects(theirs);
  for (Object* obj : theirs)
    if (m.distanceQuery(m.root, worldBounds(obj), obj, cdata, callback, dist)) return;
}

template <typename S> bool DynamicAABBTreeCollisionManager<S>::empty() const { return impl_->objects.empty(); }
template <typename S> size_t DynamicAABBTreeCollisionManager<S>::size() const { return impl_->objects.size(); }
template <typename S>
const ::fcl::detail::HierarchyTree<::fcl::AABB<S>>& DynamicAABBTreeCollisionManager<S>::getTree() const {
  fclTree_.clear();
  const Impl& m = *impl_;
  if (m.objects.empty()) return fclTree_;
  std::vector<DynamicAABBNode*> leaves(m.objects.size());
  for (std::size_t i = 0; i < m.objects.size(); ++i) {
    auto* node = new DynamicAABBNode();  // owned by fclTree_ once init() runs
    node->bv = ::fcl::AABB<S>(m.bounds[i].min, m.bounds[i].max);
    node->parent = nullptr;
    node->children[0] = node->children[1] = nullptr;
    node->data = m.objects[i];
    leaves[i] = node;
  }
  fclTree_.init(leaves, tree_init_level);
  return fclTree_;
}

template <typename S> std::size_t DynamicAABBTreeCollisionManager<S>::lastBoxTests() const { return impl_->boxTests; }

template class DynamicAABBTreeCollisionManager<float>;
template class DynamicAABBTreeCollisionManager<double>;

}  // namespace gq::fcl
