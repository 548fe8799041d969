#pragma once
// The scene's tree for rays: the mesh raycast's 8-wide BVH (bvh/build.h) and front-to-back walk (bvh/traverse.h)
// over the scene's bounded instance boxes, built when the scene's tree is rebuilt top down. Its float child boxes
// are tested 8 at a time (one AVX2 test where the CPU has it), where the dynamic binary tree (scene/aabb_tree.h)
// tests two double boxes a node. An added instance takes an empty lane on the path of least area growth (a leaf lane
// there becomes a node over both), a moved one refits its leaf's lane and the ancestors', a removed one empties its
// lane; a rebuild builds it again top down.
#include <cstdint>
#include <vector>

#include "bvh/bvh.h"
#include "gq/math.h"

namespace gq::detail {

template <class T> class SceneRayTree {
 public:
  // Called for each instance of a leaf the ray enters: returns the distance beyond which nothing matters any more
  // (the current limit to go on, a smaller one to prune, a negative one to stop the walk).
  using Visit = T (*)(void* context, std::uint32_t instance);

  // Builds the tree over boxes[j] of instances[j]; false (and the tree cleared) when a box does not fit float's
  // range, whose boxes the float slab tests cannot bound, or there are more boxes than leaf references can number
  // (2^28). May throw std::bad_alloc (the tree is then cleared).
  bool build(const std::vector<std::uint32_t>& instances, const std::vector<Bounds3<T>>& boxes);
  // The tree of no instances, ready (as constructed); clear() leaves no tree (not ready) until the next build.
  void reset() noexcept;
  void clear() noexcept;
  bool ready() const noexcept { return ready_; }
  // Leaf positions in use, removed instances' included (a build keeps only live ones).
  std::size_t positions() const noexcept { return instanceOf_.size(); }
  // An instance's new box: its leaf's lane and every ancestor's lane become the unions again. Returns whether the
  // tree is ready afterwards: a box beyond float's range clears it; an instance not in it changes nothing.
  bool refit(std::uint32_t instance, const Bounds3<T>& box) noexcept;
  // An instance removed, whose index the instance numbered `moved` takes (the scene's last one; moved == instance
  // when it was the last): its lane is emptied and the ancestors' lanes refit, and the moved one keeps its leaf.
  void remove(std::uint32_t instance, std::uint32_t moved) noexcept;
  // An instance added with its box. Returns whether the tree is ready afterwards: a box beyond float's range, a
  // path deeper than the walk's stack allows (kMaxInsertDepth), 2^28 positions (removals do not free theirs until
  // the next build) or no memory clears it (rays then walk the binary tree until the next build).
  bool insert(std::uint32_t instance, const Bounds3<T>& box) noexcept;
  // Walks the leaves the ray o + t d (t in [0, limit]) enters, nearest first, calling visit on each of their
  // instances (in no particular order: the callers' answers do not depend on it). False when the ray cannot be
  // walked in float (an origin beyond float's range): the caller walks the binary tree instead.
  bool walkRay(const Vec3<T>& o, const Vec3<T>& d, T limit, Visit visit, void* context) const;

 private:
  static constexpr std::uint32_t kNone = 0xffffffffu;
  // Nodes on an inserted leaf's path at most: the depth the walk's fixed stack is sized for (bvh/traverse.h,
  // kBvhStackSize: 7 entries a level). Insertions in sorted order can otherwise chain nodes.
  static constexpr int kMaxInsertDepth = 60;
  std::uint32_t newNode(std::uint32_t parentSlot);
  void setLeafLane(std::uint32_t slot, std::uint32_t leafRef);
  void noteLeafSlot(std::uint32_t slot, std::uint32_t leafRef) noexcept;
  void writeLane(std::uint32_t slot, const Bounds3<float>& box) noexcept;
  void refitAncestors(std::uint32_t node) noexcept;
  Bounds3<float> nodeUnion(std::uint32_t node) const noexcept;
  Bounds3<float> leafUnion(std::uint32_t ref) const noexcept;

  Bvh8 bvh_;
  std::vector<Bounds3<float>> boxes_;       // by position in the tree's order
  std::vector<std::uint32_t> instanceOf_;   // position -> instance index
  std::vector<std::uint32_t> positionOf_;   // instance index -> position (kNone: not in the tree)
  std::vector<std::uint32_t> leafSlot_;     // position -> node * 8 + lane of the leaf holding it (kNone: root leaf)
  std::vector<std::uint32_t> parentSlot_;   // node -> parent node * 8 + lane (kNone: the root)
  bool ready_ = true;
};

}  // namespace gq::detail
