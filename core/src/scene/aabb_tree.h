#pragma once
// The scene's dynamic binary AABB tree: leaves hold an item index and its exact box; inner boxes are the union of
// their children. Insertion descends to the sibling whose union grows the tree's surface area least (surface-area
// heuristic, as in Box2D's and Bullet's dynamic trees); removal replaces the parent by the sibling; a moved leaf
// refits its ancestors. The summed surface area of the inner boxes measures the tree's quality: insertions and
// removals move a baseline along with it, refits do not, so the ratio says how much moves alone degraded the tree.
// rebuild() keeps every leaf's index (items keep their leaf) and builds new inner nodes top down, splitting the
// longest axis of the leaves' centres where a binned surface-area heuristic is lowest.
#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include "gq/math.h"

namespace gq::detail {

template <class T> inline T boxArea(const Bounds3<T>& b) {
  const Vec3<T> d = b.max - b.min;
  return T(2) * (d.x() * d.y() + d.y() * d.z() + d.z() * d.x());
}

template <class T> inline Bounds3<T> boxUnion(const Bounds3<T>& a, const Bounds3<T>& b) {
  return Bounds3<T>{a.min.cwiseMin(b.min), a.max.cwiseMax(b.max)};
}

template <class T> class AabbTree {
 public:
  static constexpr std::int32_t kNull = -1;

  struct Node {
    Bounds3<T> box;
    std::int32_t parent = kNull;
    std::int32_t left = kNull;  // kNull for a leaf
    std::int32_t right = kNull;
    std::int32_t item = kNull;  // a leaf's item
    bool isLeaf() const { return left == kNull; }
  };

  std::int32_t root() const { return root_; }
  const Node& node(std::int32_t i) const { return nodes_[std::size_t(i)]; }
  std::size_t leafCount() const { return leafCount_; }
  double innerArea() const { return innerArea_; }
  double baselineArea() const { return baselineArea_; }

  void clear() {
    nodes_.clear();
    free_.clear();
    root_ = kNull;
    leafCount_ = 0;
    innerArea_ = baselineArea_ = 0;
  }

  // Allocation failures throw std::bad_alloc; the scene reserves before it mutates.
  void reserve(std::size_t leaves) {
    const std::size_t need = 2 * leaves;
    if (nodes_.capacity() < need) nodes_.reserve(std::max(need, 2 * nodes_.capacity()));
    if (free_.capacity() < need) free_.reserve(std::max(need, 2 * free_.capacity()));
  }

  std::int32_t insert(const Bounds3<T>& box, std::int32_t item) {
    const double before = innerArea_;
    const std::int32_t leaf = allocate();
    Node& n = nodes_[std::size_t(leaf)];
    n.box = box;
    n.item = item;
    insertLeaf(leaf);
    ++leafCount_;
    baselineArea_ += innerArea_ - before;
    return leaf;
  }

  void remove(std::int32_t leaf) {
    const double before = innerArea_;
    removeLeaf(leaf);
    release(leaf);
    --leafCount_;
    baselineArea_ += innerArea_ - before;
    if (leafCount_ == 0) innerArea_ = baselineArea_ = 0;
  }

  void setItem(std::int32_t leaf, std::int32_t item) { nodes_[std::size_t(leaf)].item = item; }

  // A moved leaf: its new box, then every ancestor's union.
  void refit(std::int32_t leaf, const Bounds3<T>& box) {
    nodes_[std::size_t(leaf)].box = box;
    refitAncestors(nodes_[std::size_t(leaf)].parent);
  }

  bool degraded(double factor) const { return baselineArea_ > 0 && innerArea_ > factor * baselineArea_; }

  void rebuild() {
    std::vector<std::int32_t> leaves;
    leaves.reserve(leafCount_);
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      Node& n = nodes_[i];
      if (n.item == kNull) continue;  // inner or free
      leaves.push_back(std::int32_t(i));
    }
    // Free every inner node.
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      Node& n = nodes_[i];
      if (n.item == kNull && !isFree(std::int32_t(i))) release(std::int32_t(i));
    }
    innerArea_ = 0;
    root_ = leaves.empty() ? kNull : build(leaves, 0, leaves.size(), kNull);
    baselineArea_ = innerArea_;
  }

  std::uint32_t depth() const { return root_ == kNull ? 0 : depthOf(root_); }

 private:
  bool isFree(std::int32_t i) const { return nodes_[std::size_t(i)].parent == kFreeMark; }

  std::int32_t allocate() {
    std::int32_t i;
    if (!free_.empty()) {
      i = free_.back();
      free_.pop_back();
    } else {
      i = std::int32_t(nodes_.size());
      nodes_.emplace_back();
    }
    nodes_[std::size_t(i)] = Node{};
    return i;
  }
  void release(std::int32_t i) {
    Node& n = nodes_[std::size_t(i)];
    n = Node{};
    n.parent = kFreeMark;
    free_.push_back(i);
  }

  void setInnerBox(std::int32_t i, const Bounds3<T>& box) {
    Node& n = nodes_[std::size_t(i)];
    innerArea_ += double(boxArea(box)) - double(boxArea(n.box));
    n.box = box;
  }

  void refitAncestors(std::int32_t i) {
    while (i != kNull) {
      const Node& n = nodes_[std::size_t(i)];
      setInnerBox(i, boxUnion(nodes_[std::size_t(n.left)].box, nodes_[std::size_t(n.right)].box));
      i = nodes_[std::size_t(i)].parent;
    }
  }

  void insertLeaf(std::int32_t leaf) {
    if (root_ == kNull) {
      root_ = leaf;
      nodes_[std::size_t(leaf)].parent = kNull;
      return;
    }
    const Bounds3<T> box = nodes_[std::size_t(leaf)].box;
    // Descend: at each inner node, stop here (a new parent of this node and the leaf) or go to the child whose
    // growth costs least; costs are the areas the insertion adds along the way.
    std::int32_t index = root_;
    while (!nodes_[std::size_t(index)].isLeaf()) {
      const Node& n = nodes_[std::size_t(index)];
      const T area = boxArea(n.box);
      const T combined = boxArea(boxUnion(n.box, box));
      const T cost = T(2) * combined;                // a new parent here
      const T inherited = T(2) * (combined - area);  // what every box below grows by at least
      auto childCost = [&](std::int32_t c) {
        const Node& child = nodes_[std::size_t(c)];
        const T u = boxArea(boxUnion(child.box, box));
        return child.isLeaf() ? u + inherited : (u - boxArea(child.box)) + inherited;
      };
      const T costLeft = childCost(n.left);
      const T costRight = childCost(n.right);
      if (cost < costLeft && cost < costRight) break;
      index = costLeft <= costRight ? n.left : n.right;
    }
    const std::int32_t sibling = index;
    const std::int32_t oldParent = nodes_[std::size_t(sibling)].parent;
    const std::int32_t newParent = allocate();
    {
      Node& p = nodes_[std::size_t(newParent)];
      p.parent = oldParent;
      p.left = sibling;
      p.right = leaf;
      p.box = Bounds3<T>{Vec3<T>::Zero(), Vec3<T>::Zero()};
    }
    setInnerBox(newParent, boxUnion(box, nodes_[std::size_t(sibling)].box));
    if (oldParent != kNull) {
      Node& op = nodes_[std::size_t(oldParent)];
      (op.left == sibling ? op.left : op.right) = newParent;
    } else {
      root_ = newParent;
    }
    nodes_[std::size_t(sibling)].parent = newParent;
    nodes_[std::size_t(leaf)].parent = newParent;
    refitAncestors(oldParent);
  }

  void removeLeaf(std::int32_t leaf) {
    if (leaf == root_) {
      root_ = kNull;
      return;
    }
    const std::int32_t parent = nodes_[std::size_t(leaf)].parent;
    const std::int32_t grand = nodes_[std::size_t(parent)].parent;
    const Node& p = nodes_[std::size_t(parent)];
    const std::int32_t sibling = p.left == leaf ? p.right : p.left;
    innerArea_ -= double(boxArea(p.box));
    if (grand != kNull) {
      Node& g = nodes_[std::size_t(grand)];
      (g.left == parent ? g.left : g.right) = sibling;
      nodes_[std::size_t(sibling)].parent = grand;
      release(parent);
      refitAncestors(grand);
    } else {
      root_ = sibling;
      nodes_[std::size_t(sibling)].parent = kNull;
      release(parent);
    }
  }

  // Splits leaves[begin, end) along `axis` where the surface-area heuristic is lowest over kBins bins of the
  // centres (the count-weighted areas of the two sides); the median when the centres coincide or no split beats it.
  // Ties are broken by leaf index, so the same leaves always give the same tree.
  std::size_t splitBySah(std::vector<std::int32_t>& leaves, std::size_t begin, std::size_t end, int axis, T lo,
                         T spread) {
    constexpr int kBins = 16;
    const std::size_t n = end - begin;
    const auto centre = [&](std::int32_t leaf) { return nodes_[std::size_t(leaf)].box.center()[axis]; };
    auto median = [&] {
      const std::size_t mid = begin + n / 2;
      std::nth_element(leaves.begin() + std::ptrdiff_t(begin), leaves.begin() + std::ptrdiff_t(mid),
                       leaves.begin() + std::ptrdiff_t(end), [&](std::int32_t a, std::int32_t b) {
                         const T ca = centre(a), cb = centre(b);
                         return ca < cb || (ca == cb && a < b);
                       });
      return mid;
    };
    if (n <= 2 || !(spread > T(0))) return median();
    const T scale = T(kBins) / spread;
    auto binOf = [&](std::int32_t leaf) {
      const int b = int((centre(leaf) - lo) * scale);
      return b < 0 ? 0 : (b >= kBins ? kBins - 1 : b);
    };
    Bounds3<T> binBox[kBins];
    std::size_t binCount[kBins] = {};
    for (std::size_t i = begin; i < end; ++i) {
      const int b = binOf(leaves[i]);
      binBox[b].include(nodes_[std::size_t(leaves[i])].box);
      ++binCount[b];
    }
    // Areas and counts left of each boundary k (bins < k) and right of it (bins >= k).
    T leftArea[kBins] = {}, rightArea[kBins] = {};
    std::size_t leftCount[kBins] = {}, rightCount[kBins] = {};
    Bounds3<T> acc;
    std::size_t count = 0;
    for (int k = 1; k < kBins; ++k) {
      if (binCount[k - 1]) acc.include(binBox[k - 1]);
      count += binCount[k - 1];
      leftArea[k] = count ? boxArea(acc) : T(0);
      leftCount[k] = count;
    }
    acc = Bounds3<T>();
    count = 0;
    for (int k = kBins - 1; k >= 1; --k) {
      if (binCount[k]) acc.include(binBox[k]);
      count += binCount[k];
      rightArea[k] = count ? boxArea(acc) : T(0);
      rightCount[k] = count;
    }
    int best = 0;
    T bestCost = std::numeric_limits<T>::infinity();
    for (int k = 1; k < kBins; ++k) {
      if (leftCount[k] == 0 || rightCount[k] == 0) continue;
      const T cost = leftArea[k] * T(leftCount[k]) + rightArea[k] * T(rightCount[k]);
      if (cost < bestCost) {
        bestCost = cost;
        best = k;
      }
    }
    if (best == 0) return median();
    const auto middle = std::partition(leaves.begin() + std::ptrdiff_t(begin), leaves.begin() + std::ptrdiff_t(end),
                                       [&](std::int32_t leaf) { return binOf(leaf) < best; });
    return std::size_t(middle - leaves.begin());
  }

  std::int32_t build(std::vector<std::int32_t>& leaves, std::size_t begin, std::size_t end, std::int32_t parent) {
    if (end - begin == 1) {
      const std::int32_t leaf = leaves[begin];
      nodes_[std::size_t(leaf)].parent = parent;
      return leaf;
    }
    Bounds3<T> centres;
    for (std::size_t i = begin; i < end; ++i) centres.include(nodes_[std::size_t(leaves[i])].box.center());
    const Vec3<T> spread = centres.max - centres.min;
    int axis = 0;
    if (spread.y() > spread[axis]) axis = 1;
    if (spread.z() > spread[axis]) axis = 2;
    const std::size_t mid = splitBySah(leaves, begin, end, axis, centres.min[axis], spread[axis]);
    const std::int32_t inner = allocate();
    nodes_[std::size_t(inner)].parent = parent;
    nodes_[std::size_t(inner)].box = Bounds3<T>{Vec3<T>::Zero(), Vec3<T>::Zero()};
    const std::int32_t l = build(leaves, begin, mid, inner);
    const std::int32_t r = build(leaves, mid, end, inner);
    nodes_[std::size_t(inner)].left = l;
    nodes_[std::size_t(inner)].right = r;
    setInnerBox(inner, boxUnion(nodes_[std::size_t(l)].box, nodes_[std::size_t(r)].box));
    return inner;
  }

  std::uint32_t depthOf(std::int32_t i) const {
    const Node& n = nodes_[std::size_t(i)];
    if (n.isLeaf()) return 1;
    return 1 + std::max(depthOf(n.left), depthOf(n.right));
  }

  static constexpr std::int32_t kFreeMark = -2;

  std::vector<Node> nodes_;
  std::vector<std::int32_t> free_;
  std::int32_t root_ = kNull;
  std::size_t leafCount_ = 0;
  double innerArea_ = 0;
  double baselineArea_ = 0;
};

}  // namespace gq::detail
