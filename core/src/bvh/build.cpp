// Binned SAH BVH4 build: binary SAH splits (16 bins on each axis over the centroid bounds) are applied repeatedly to
// the child with the largest surface area until a node has 4 children or all children fit in a leaf.
#include "bvh/build.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace gq::detail {
namespace {

constexpr int kBins = 16;
// Past this depth the splits fall back to the median, bounding the traversal stack (see bvh/traverse.h).
constexpr int kMaxSahDepth = 32;

struct Range {
  std::uint32_t begin, end;
  Bounds3<float> bounds;
  std::uint32_t count() const { return end - begin; }
};

float halfArea(const Bounds3<float>& b) {
  if (b.isEmpty()) return 0.0f;
  const Vec3<float> d = b.max - b.min;
  return d.x() * d.y() + d.y() * d.z() + d.z() * d.x();
}

class Builder {
 public:
  Builder(const std::vector<Bounds3<float>>& prims, std::vector<std::uint32_t>& order)
      : prims_(prims), order_(order) {
    centroids_.reserve(prims.size());
    for (const auto& b : prims) centroids_.push_back(b.center());
  }

  Bvh4 run() {
    Bounds3<float> all;
    for (const auto& b : prims_) all.include(b);
    const Range root{0, std::uint32_t(order_.size()), all};
    bvh_.rootChild = buildRef(root, 0);
    return std::move(bvh_);
  }

 private:
  Bounds3<float> boundsOf(std::uint32_t begin, std::uint32_t end) const {
    Bounds3<float> b;
    for (std::uint32_t i = begin; i < end; ++i) b.include(prims_[order_[i]]);
    return b;
  }

  // Splits r in two (in place in order_) and returns the split position.
  std::uint32_t split(const Range& r, int depth) {
    Bounds3<float> cb;
    for (std::uint32_t i = r.begin; i < r.end; ++i) cb.include(centroids_[order_[i]]);
    const Vec3<float> ext = cb.max - cb.min;
    if (depth < kMaxSahDepth && ext.maxCoeff() > 0.0f) {
      float bestCost = std::numeric_limits<float>::max();
      int bestAxis = -1, bestBin = -1;
      for (int axis = 0; axis < 3; ++axis) {
        if (!(ext[axis] > 0.0f)) continue;
        std::array<Bounds3<float>, kBins> binBounds;
        std::array<std::uint32_t, kBins> binCount{};
        const float scale = kBins / ext[axis];
        for (std::uint32_t i = r.begin; i < r.end; ++i) {
          const int bin = binOf(centroids_[order_[i]][axis], cb.min[axis], scale);
          binBounds[bin].include(prims_[order_[i]]);
          ++binCount[bin];
        }
        // Sweep from the right to get suffix areas, then from the left to evaluate cost = A_L N_L + A_R N_R.
        std::array<float, kBins> rightArea{};
        std::array<std::uint32_t, kBins> rightCount{};
        Bounds3<float> acc;
        std::uint32_t n = 0;
        for (int b = kBins - 1; b > 0; --b) {
          acc.include(binBounds[b]);
          n += binCount[b];
          rightArea[b] = halfArea(acc);
          rightCount[b] = n;
        }
        acc = Bounds3<float>();
        n = 0;
        for (int b = 0; b < kBins - 1; ++b) {
          acc.include(binBounds[b]);
          n += binCount[b];
          if (n == 0 || rightCount[b + 1] == 0) continue;
          const float cost = halfArea(acc) * float(n) + rightArea[b + 1] * float(rightCount[b + 1]);
          if (cost < bestCost) { bestCost = cost; bestAxis = axis; bestBin = b; }
        }
      }
      if (bestAxis >= 0) {
        const float scale = kBins / ext[bestAxis];
        const float lo = cb.min[bestAxis];
        auto* mid = std::partition(order_.data() + r.begin, order_.data() + r.end, [&](std::uint32_t p) {
          return binOf(centroids_[p][bestAxis], lo, scale) <= bestBin;
        });
        const auto m = std::uint32_t(mid - order_.data());
        if (m > r.begin && m < r.end) return m;
      }
    }
    // Median split on the widest centroid axis (also handles coincident centroids).
    int axis = 0;
    ext.maxCoeff(&axis);
    const std::uint32_t m = r.begin + r.count() / 2;
    std::nth_element(order_.data() + r.begin, order_.data() + m, order_.data() + r.end,
                     [&](std::uint32_t a, std::uint32_t b) { return centroids_[a][axis] < centroids_[b][axis]; });
    return m;
  }

  // Clamped in float before the conversion: with extents beyond the float range (scale 0, offsets inf) or tiny ones
  // (scale inf) the product is NaN or inf, which int() must never see (found by fuzz_raycast under UBSan).
  static int binOf(float c, float lo, float scale) {
    const float t = (c - lo) * scale;
    if (!(t > 0.0f)) return 0;
    return t >= float(kBins - 1) ? kBins - 1 : int(t);
  }

  // Reference to the subtree over r.
  std::uint32_t buildRef(const Range& r, int depth) {
    if (r.count() <= Bvh4Node::kMaxLeafSize) return Bvh4Node::makeLeaf(r.begin, r.count());
    std::array<Range, 4> kids;
    int n = 1;
    kids[0] = r;
    while (n < 4) {
      // Split the splittable child with the largest area.
      int pick = -1;
      float best = -1.0f;
      for (int i = 0; i < n; ++i) {
        if (kids[i].count() <= Bvh4Node::kMaxLeafSize) continue;
        const float a = halfArea(kids[i].bounds);
        if (a > best) { best = a; pick = i; }
      }
      if (pick < 0) break;
      const Range p = kids[pick];
      const std::uint32_t m = split(p, depth);
      kids[pick] = Range{p.begin, m, boundsOf(p.begin, m)};
      kids[n++] = Range{m, p.end, boundsOf(m, p.end)};
    }
    const auto nodeIndex = std::uint32_t(bvh_.nodes.size());
    bvh_.nodes.emplace_back();
    std::array<std::uint32_t, 4> refs;
    refs.fill(Bvh4Node::kEmpty);
    for (int i = 0; i < n; ++i) refs[i] = buildRef(kids[i], depth + 1);
    Bvh4Node& node = bvh_.nodes[nodeIndex];
    const float inf = std::numeric_limits<float>::infinity();
    for (int i = 0; i < 4; ++i) {
      node.child[i] = refs[i];
      // Empty lanes get an all-+inf box, which every slab test rejects.
      const Bounds3<float> b = i < n ? kids[i].bounds : Bounds3<float>::fromMinMax(Vec3<float>::Constant(inf),
                                                                                  Vec3<float>::Constant(inf));
      node.minX[i] = b.min.x(); node.minY[i] = b.min.y(); node.minZ[i] = b.min.z();
      node.maxX[i] = b.max.x(); node.maxY[i] = b.max.y(); node.maxZ[i] = b.max.z();
    }
    return nodeIndex;
  }

  const std::vector<Bounds3<float>>& prims_;
  std::vector<std::uint32_t>& order_;
  std::vector<Vec3<float>> centroids_;
  Bvh4 bvh_;
};

template <class T> float roundDown(T x) {
  const float f = static_cast<float>(x);
  return T(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}
template <class T> float roundUp(T x) {
  const float f = static_cast<float>(x);
  return T(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

// Builds 8-wide nodes over a 4-wide tree, top down.
class Collapser {
 public:
  explicit Collapser(const Bvh4& bvh) : in_(bvh) {}

  Bvh8 run() {
    out_.rootChild = Bvh4Node::isLeaf(in_.rootChild) || in_.rootChild == Bvh4Node::kEmpty ? in_.rootChild
                                                                                             : collapse(in_.rootChild);
    return std::move(out_);
  }

 private:
  struct Slot {
    std::uint32_t ref;
    Bounds3<float> box;
  };

  static Bounds3<float> laneBox(const Bvh4Node& n, int lane) {
    return Bounds3<float>::fromMinMax(Vec3<float>(n.minX[lane], n.minY[lane], n.minZ[lane]),
                                      Vec3<float>(n.maxX[lane], n.maxY[lane], n.maxZ[lane]));
  }
  static int childCount(const Bvh4Node& n) {
    int c = 0;
    for (int lane = 0; lane < 4; ++lane) c += n.child[lane] != Bvh4Node::kEmpty;
    return c;
  }

  // Index of the 8-wide node over the 4-wide inner node `ref`.
  std::uint32_t collapse(std::uint32_t ref) {
    std::array<Slot, 8> slots;
    int n = 0;
    const Bvh4Node& root = in_.nodes[ref];
    for (int lane = 0; lane < 4; ++lane)
      if (root.child[lane] != Bvh4Node::kEmpty) slots[n++] = Slot{root.child[lane], laneBox(root, lane)};
    for (;;) {
      // Open the inner slot with the largest area whose children fit.
      int pick = -1;
      float best = -1.0f;
      for (int i = 0; i < n; ++i) {
        if (Bvh4Node::isLeaf(slots[i].ref)) continue;
        if (n - 1 + childCount(in_.nodes[slots[i].ref]) > 8) continue;
        const float a = halfArea(slots[i].box);
        if (a > best) { best = a; pick = i; }
      }
      if (pick < 0) break;
      const Bvh4Node& open = in_.nodes[slots[pick].ref];
      slots[pick] = slots[--n];
      for (int lane = 0; lane < 4; ++lane)
        if (open.child[lane] != Bvh4Node::kEmpty) slots[n++] = Slot{open.child[lane], laneBox(open, lane)};
    }
    // Largest surface area first (stable: equal areas keep their order, so cooking stays deterministic).
    std::stable_sort(slots.begin(), slots.begin() + n,
                     [](const Slot& a, const Slot& b) { return halfArea(a.box) > halfArea(b.box); });
    const auto index = std::uint32_t(out_.nodes.size());
    out_.nodes.emplace_back();
    std::array<std::uint32_t, 8> refs;
    refs.fill(Bvh8Node::kEmpty);
    for (int i = 0; i < n; ++i) refs[i] = Bvh4Node::isLeaf(slots[i].ref) ? slots[i].ref : collapse(slots[i].ref);
    Bvh8Node& node = out_.nodes[index];
    const float inf = std::numeric_limits<float>::infinity();
    for (int i = 0; i < 8; ++i) {
      node.child[i] = refs[i];
      // Empty lanes get an all-+inf box, as in the 4-wide tree.
      const Bounds3<float> b = i < n ? slots[i].box : Bounds3<float>::fromMinMax(Vec3<float>::Constant(inf),
                                                                                Vec3<float>::Constant(inf));
      node.minX[i] = b.min.x(); node.minY[i] = b.min.y(); node.minZ[i] = b.min.z();
      node.maxX[i] = b.max.x(); node.maxY[i] = b.max.y(); node.maxZ[i] = b.max.z();
    }
    return index;
  }

  const Bvh4& in_;
  Bvh8 out_;
};

}  // namespace

Bvh8 collapseToBvh8(const Bvh4& bvh) { return Collapser(bvh).run(); }

Bvh4 buildBvh4(const std::vector<Bounds3<float>>& primBounds, std::vector<std::uint32_t>& order) {
  order.resize(primBounds.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  if (primBounds.empty()) return Bvh4();
  return Builder(primBounds, order).run();
}

template <class T> Bounds3<float> roundOutward(const Vec3<T>& lo, const Vec3<T>& hi) {
  return Bounds3<float>::fromMinMax(Vec3<float>(roundDown(lo.x()), roundDown(lo.y()), roundDown(lo.z())),
                                    Vec3<float>(roundUp(hi.x()), roundUp(hi.y()), roundUp(hi.z())));
}

template Bounds3<float> roundOutward<float>(const Vec3<float>&, const Vec3<float>&);
template Bounds3<float> roundOutward<double>(const Vec3<double>&, const Vec3<double>&);

}  // namespace gq::detail
