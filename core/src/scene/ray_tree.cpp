// The scene's 8-wide ray tree (scene/ray_tree.h).
#include "scene/ray_tree.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "bvh/build.h"
#include "bvh/traverse.h"
#include "scene/aabb_tree.h"

namespace gq::detail {
namespace {

// Coordinates the float tree takes: well inside float's range, so that a box rounded outward stays finite.
constexpr double kFloatReach = 1e30;

template <class T> bool withinFloatReach(const Vec3<T>& v) {
  return std::abs(double(v.x())) <= kFloatReach && std::abs(double(v.y())) <= kFloatReach &&
         std::abs(double(v.z())) <= kFloatReach;
}

template <class T> bool withinFloatReach(const Bounds3<T>& b) {
  return withinFloatReach(b.min) && withinFloatReach(b.max);
}

// Capacity for one more element, grown by doubling (insertions one at a time stay amortized O(1) in copies).
template <class V> void roomForOneMore(V& v) {
  if (v.size() == v.capacity()) v.reserve(std::max<std::size_t>(16, 2 * v.size()));
}

// The box of a node's lane.
Bounds3<float> laneBox(const Bvh8Node& node, int lane) {
  return Bounds3<float>::fromMinMax(Vec3<float>(node.minX[lane], node.minY[lane], node.minZ[lane]),
                                    Vec3<float>(node.maxX[lane], node.maxY[lane], node.maxZ[lane]));
}

// The walk for one node test (Lanes), the leaves' instances handed to visit.
template <class Lanes, class T>
void walkLeaves(const Bvh8& bvh, const std::uint32_t* instanceOf, const BvhRay<8>& ray, T limit,
                typename SceneRayTree<T>::Visit visit, void* context) {
  float tMax = floatCeil(limit);
  walkRayLeaves<true, std::is_same_v<T, double>, Lanes>(bvh, ray, tMax, [&](std::uint32_t ref) {
    const std::uint32_t first = Bvh8Node::leafFirst(ref), end = first + Bvh8Node::leafCount(ref);
    for (std::uint32_t k = first; k < end; ++k) {
      limit = visit(context, instanceOf[k]);
      if (limit < T(0)) return true;
    }
    tMax = floatCeil(limit);
    return false;
  });
}

#ifdef GQ_SSE42
template <class T>
__attribute__((target("avx2"), flatten)) void walkAvx2(const Bvh8& bvh, const std::uint32_t* instanceOf,
                                                      const BvhRay<8>& ray, T limit,
                                                      typename SceneRayTree<T>::Visit visit, void* context) {
  if (ray.mayGiveNaN)
    walkLeaves<Bvh8LanesAvx2>(bvh, instanceOf, ray, limit, visit, context);
  else
    walkLeaves<Bvh8LanesAvx2NaNFree>(bvh, instanceOf, ray, limit, visit, context);
}
#endif

}  // namespace

template <class T>
bool SceneRayTree<T>::build(const std::vector<std::uint32_t>& instances, const std::vector<Bounds3<T>>& boxes) {
  clear();
  if (boxes.size() > Bvh8Node::kLeafFirstMask) return false;
  std::vector<Bounds3<float>> prims;
  prims.reserve(boxes.size());
  for (const Bounds3<T>& b : boxes) {
    if (!withinFloatReach(b)) return false;
    prims.push_back(roundOutward(b.min, b.max));
  }
  try {
    std::vector<std::uint32_t> order;
    BvhBuildSettings settings;
    settings.maxLeafSize = 1;  // each instance's own box in its parent's node test
    bvh_ = buildBvh8(prims, order, settings);
    std::uint32_t maxInstance = 0;
    for (std::uint32_t i : instances) maxInstance = std::max(maxInstance, i);
    instanceOf_.resize(order.size());
    boxes_.resize(order.size());
    positionOf_.assign(instances.empty() ? 0 : std::size_t(maxInstance) + 1, kNone);
    for (std::size_t k = 0; k < order.size(); ++k) {
      instanceOf_[k] = instances[order[k]];
      boxes_[k] = prims[order[k]];
      positionOf_[instanceOf_[k]] = std::uint32_t(k);
    }
    // Where each node and each position hangs: the path a refit climbs.
    leafSlot_.assign(order.size(), kNone);
    parentSlot_.assign(bvh_.nodes.size(), kNone);
    for (std::uint32_t n = 0; n < bvh_.nodes.size(); ++n) {
      for (std::uint32_t lane = 0; lane < 8; ++lane) {
        const std::uint32_t ref = bvh_.nodes[n].child[lane];
        if (ref == Bvh8Node::kEmpty) continue;
        if (Bvh8Node::isLeaf(ref)) {
          noteLeafSlot(8 * n + lane, ref);
        } else {
          parentSlot_[ref] = 8 * n + lane;
        }
      }
    }
  } catch (...) {
    clear();
    throw;
  }
  ready_ = true;
  return true;
}

template <class T> void SceneRayTree<T>::reset() noexcept {
  clear();
  ready_ = true;
}

template <class T> void SceneRayTree<T>::clear() noexcept {
  bvh_.nodes.clear();
  bvh_.rootChild = Bvh8Node::kEmpty;
  boxes_.clear();
  instanceOf_.clear();
  positionOf_.clear();
  leafSlot_.clear();
  parentSlot_.clear();
  ready_ = false;
}

template <class T> void SceneRayTree<T>::writeLane(std::uint32_t slot, const Bounds3<float>& b) noexcept {
  setBvhLaneBox(bvh_.nodes[slot / 8], int(slot % 8), b);
}

template <class T> Bounds3<float> SceneRayTree<T>::leafUnion(std::uint32_t ref) const noexcept {
  const std::uint32_t first = Bvh8Node::leafFirst(ref);
  Bounds3<float> u = boxes_[first];
  for (std::uint32_t k = first + 1; k < first + Bvh8Node::leafCount(ref); ++k) u = boxUnion(u, boxes_[k]);
  return u;
}

template <class T> Bounds3<float> SceneRayTree<T>::nodeUnion(std::uint32_t n) const noexcept {
  const Bvh8Node& node = bvh_.nodes[n];
  // Lanes over subtrees that removals emptied hold the empty box, the identity of unions: they bound nothing.
  Bounds3<float> u = emptyBvhLaneBox();
  for (int lane = 0; lane < 8; ++lane)
    if (node.child[lane] != Bvh8Node::kEmpty) u = boxUnion(u, laneBox(node, lane));
  return u;
}

template <class T> bool SceneRayTree<T>::refit(std::uint32_t instance, const Bounds3<T>& box) noexcept {
  if (!ready_ || instance >= positionOf_.size() || positionOf_[instance] == kNone) return ready_;
  if (!withinFloatReach(box)) {
    clear();
    return false;
  }
  const std::uint32_t k = positionOf_[instance];
  boxes_[k] = roundOutward(box.min, box.max);
  std::uint32_t slot = leafSlot_[k];
  if (slot == kNone) return true;  // the root is a leaf: no boxes are tested
  writeLane(slot, leafUnion(bvh_.nodes[slot / 8].child[slot % 8]));
  refitAncestors(slot / 8);
  return true;
}

template <class T> void SceneRayTree<T>::refitAncestors(std::uint32_t node) noexcept {
  for (std::uint32_t n = node; parentSlot_[n] != kNone; n = parentSlot_[n] / 8) writeLane(parentSlot_[n], nodeUnion(n));
}

template <class T> void SceneRayTree<T>::remove(std::uint32_t instance, std::uint32_t moved) noexcept {
  if (!ready_) return;
  if (instance < positionOf_.size() && positionOf_[instance] != kNone) {
    const std::uint32_t k = positionOf_[instance];
    positionOf_[instance] = kNone;
    const std::uint32_t slot = leafSlot_[k];
    if (slot == kNone) {  // the root is its leaf
      bvh_.rootChild = Bvh8Node::kEmpty;
    } else {  // leaves hold one instance: its lane empties (an empty box, which the slab tests reject)
      bvh_.nodes[slot / 8].child[slot % 8] = Bvh8Node::kEmpty;
      writeLane(slot, emptyBvhLaneBox());
      refitAncestors(slot / 8);
    }
  }
  if (moved != instance && moved < positionOf_.size() && positionOf_[moved] != kNone) {
    const std::uint32_t k = positionOf_[moved];
    positionOf_[moved] = kNone;
    positionOf_[instance] = k;  // instance < moved: within the array
    instanceOf_[k] = instance;
  }
}

template <class T> std::uint32_t SceneRayTree<T>::newNode(std::uint32_t parentSlot) {
  const auto n = std::uint32_t(bvh_.nodes.size());
  bvh_.nodes.emplace_back();
  parentSlot_.push_back(parentSlot);
  for (std::uint32_t lane = 0; lane < 8; ++lane) {
    bvh_.nodes[n].child[lane] = Bvh8Node::kEmpty;
    writeLane(8 * n + lane, emptyBvhLaneBox());
  }
  return n;
}

// The leaf leafRef's positions hang at lane `slot`.
template <class T> void SceneRayTree<T>::noteLeafSlot(std::uint32_t slot, std::uint32_t leafRef) noexcept {
  const std::uint32_t first = Bvh8Node::leafFirst(leafRef);
  for (std::uint32_t k = first; k < first + Bvh8Node::leafCount(leafRef); ++k) leafSlot_[k] = slot;
}

// Lane `slot` holds the leaf leafRef: its reference, its box, and where its positions hang.
template <class T> void SceneRayTree<T>::setLeafLane(std::uint32_t slot, std::uint32_t leafRef) {
  bvh_.nodes[slot / 8].child[slot % 8] = leafRef;
  writeLane(slot, leafUnion(leafRef));
  noteLeafSlot(slot, leafRef);
}

template <class T> bool SceneRayTree<T>::insert(std::uint32_t instance, const Bounds3<T>& box) noexcept {
  if (!ready_) return false;
  if (!withinFloatReach(box) || instanceOf_.size() >= Bvh8Node::kLeafFirstMask) {
    clear();
    return false;
  }
  try {
    // Everything that allocates, first.
    const auto k = std::uint32_t(instanceOf_.size());
    roomForOneMore(instanceOf_);
    roomForOneMore(boxes_);
    roomForOneMore(leafSlot_);
    roomForOneMore(bvh_.nodes);  // a node at most: its references stay valid below
    roomForOneMore(parentSlot_);
    if (positionOf_.size() <= instance) positionOf_.resize(std::size_t(instance) + 1, kNone);
    instanceOf_.push_back(instance);
    boxes_.push_back(roundOutward(box.min, box.max));
    leafSlot_.push_back(kNone);
    positionOf_[instance] = k;
    const std::uint32_t leaf = Bvh8Node::makeLeaf(k, 1);
    const std::uint32_t root = bvh_.rootChild;
    if (root == Bvh8Node::kEmpty) {
      bvh_.rootChild = leaf;
      return true;
    }
    if (Bvh8Node::isLeaf(root)) {  // a root node over the root leaf and the inserted one
      const std::uint32_t n = newNode(kNone);
      setLeafLane(8 * n, root);
      setLeafLane(8 * n + 1, leaf);
      bvh_.rootChild = n;
      return true;
    }
    const Bounds3<float>& b = boxes_[k];
    std::uint32_t n = root;
    for (int depth = 1;; ++depth) {
      const Bvh8Node& node = bvh_.nodes[n];
      int pick = -1;
      float growth = std::numeric_limits<float>::infinity(), area = growth;
      for (int lane = 0; lane < 8; ++lane) {
        if (node.child[lane] == Bvh8Node::kEmpty) {  // an empty lane takes the leaf
          setLeafLane(8 * n + std::uint32_t(lane), leaf);
          refitAncestors(n);
          return true;
        }
        const Bounds3<float> c = laneBox(node, lane);
        const float a = boxArea(c), g = boxArea(boxUnion(c, b)) - a;
        if (g < growth || (g == growth && a < area)) {
          pick = lane;
          growth = g;
          area = a;
        }
      }
      // A lane over a subtree that removals emptied (the empty box: infinite area, a growth of -inf) is taken first,
      // so the new leaf reuses its nodes. No lane compared (areas overflowed to NaN): any lane will do, the refit
      // below making its box the union.
      if (pick < 0) pick = 0;
      const std::uint32_t slot = 8 * n + std::uint32_t(pick), ref = node.child[pick];
      if (depth + 1 > kMaxInsertDepth) break;  // a node below this one would be deeper than the walk allows
      if (!Bvh8Node::isLeaf(ref)) {
        n = ref;
        continue;
      }
      // The leaf lane becomes a node over that leaf and the inserted one.
      const std::uint32_t m = newNode(slot);
      setLeafLane(8 * m, ref);
      setLeafLane(8 * m + 1, leaf);
      bvh_.nodes[n].child[pick] = m;
      writeLane(slot, nodeUnion(m));
      refitAncestors(n);
      return true;
    }
  } catch (const std::bad_alloc&) {
  }
  clear();
  return false;
}

template <class T>
bool SceneRayTree<T>::walkRay(const Vec3<T>& o, const Vec3<T>& d, T limit, Visit visit, void* context) const {
  if (!ready_ || !withinFloatReach(o)) return false;
  const BvhRay<8> ray = makeBvhRay<8>(o, d);
#ifdef GQ_SSE42
  if (hasAvx2()) {
    walkAvx2<T>(bvh_, instanceOf_.data(), ray, limit, visit, context);
    return true;
  }
#endif
  walkLeaves<Bvh8LanesBaseline>(bvh_, instanceOf_.data(), ray, limit, visit, context);
  return true;
}

template class SceneRayTree<float>;
template class SceneRayTree<double>;

}  // namespace gq::detail
