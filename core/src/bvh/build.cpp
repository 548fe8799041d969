// Binned SAH BVH8 build: binary SAH splits (16 bins on each axis over the centroid bounds) are applied repeatedly to
// the child with the largest surface area until a node has 8 children or all children fit in a leaf. The SAH counts
// a side's primitives in leaves of the leaf size (triangles: ceil(n / 4)): a leaf is tested 4 triangles at once, so
// a split that fills leaves costs less than one that leaves them part empty.
#include "bvh/build.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace gq::detail {
namespace {

constexpr int kBins = 16;
constexpr int kWidth = 8;
using Node = BvhNode<kWidth>;
// The most SAH levels the ray walk's stack allows (bvh/traverse.h, kBvhStackSize).
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
  Builder(const std::vector<Bounds3<float>>& prims, std::vector<std::uint32_t>& order, const BvhBuildSettings& settings)
      : prims_(prims), order_(order), maxSahDepth_(std::clamp(settings.maxSahDepth, 0, kMaxSahDepth)),
        leafSize_(std::clamp(settings.maxLeafSize, 1u, Node::kMaxLeafSize)) {
    centroids_.reserve(prims.size());
    for (const auto& b : prims) centroids_.push_back(b.center());
  }

  Bvh8 run() {
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
    if (depth < maxSahDepth_ && ext.maxCoeff() > 0.0f) {
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
          const float cost = halfArea(acc) * leafBlocks(n) + rightArea[b + 1] * leafBlocks(rightCount[b + 1]);
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

  // The fewest leaves n primitives fill (leaves of leafSize_).
  float leafBlocks(std::uint32_t n) const { return float((n + leafSize_ - 1) / leafSize_); }

  // Clamped in float before the conversion: with extents beyond the float range (scale 0, offsets inf) or tiny ones
  // (scale inf) the product is NaN or inf, which int() must never see (found by fuzz_raycast under UBSan).
  static int binOf(float c, float lo, float scale) {
    const float t = (c - lo) * scale;
    if (!(t > 0.0f)) return 0;
    return t >= float(kBins - 1) ? kBins - 1 : int(t);
  }

  // Reference to the subtree over r.
  std::uint32_t buildRef(const Range& r, int depth) {
    if (r.count() <= leafSize_) return Node::makeLeaf(r.begin, r.count());
    std::array<Range, kWidth> kids;
    int n = 1;
    kids[0] = r;
    while (n < kWidth) {
      // Split the splittable child with the largest area.
      int pick = -1;
      float best = -1.0f;
      for (int i = 0; i < n; ++i) {
        if (kids[i].count() <= leafSize_) continue;
        const float a = halfArea(kids[i].bounds);
        if (a > best) { best = a; pick = i; }
      }
      if (pick < 0) break;
      const Range p = kids[pick];
      const std::uint32_t m = split(p, depth);
      kids[pick] = Range{p.begin, m, boundsOf(p.begin, m)};
      kids[n++] = Range{m, p.end, boundsOf(m, p.end)};
    }
    // Largest surface area first (stable: equal areas keep their order, so cooking stays deterministic): the order
    // the unordered any-hit walk takes them in.
    std::stable_sort(kids.begin(), kids.begin() + n,
                     [](const Range& a, const Range& b) { return halfArea(a.bounds) > halfArea(b.bounds); });
    const auto nodeIndex = std::uint32_t(bvh_.nodes.size());
    bvh_.nodes.emplace_back();
    std::array<std::uint32_t, kWidth> refs;
    refs.fill(Node::kEmpty);
    for (int i = 0; i < n; ++i) refs[i] = buildRef(kids[i], depth + 1);
    Node& node = bvh_.nodes[nodeIndex];
    for (int i = 0; i < kWidth; ++i) {
      node.child[i] = refs[i];
      setBvhLaneBox(node, i, i < n ? kids[i].bounds : emptyBvhLaneBox());
    }
    return nodeIndex;
  }

  const std::vector<Bounds3<float>>& prims_;
  std::vector<std::uint32_t>& order_;
  int maxSahDepth_;
  std::uint32_t leafSize_;
  std::vector<Vec3<float>> centroids_;
  Bvh8 bvh_;
};

template <class T> float roundDown(T x) {
  const float f = static_cast<float>(x);
  return T(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}
template <class T> float roundUp(T x) {
  const float f = static_cast<float>(x);
  return T(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

}  // namespace

Bvh8 buildBvh8(const std::vector<Bounds3<float>>& primBounds, std::vector<std::uint32_t>& order,
               const BvhBuildSettings& settings) {
  order.resize(primBounds.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  if (primBounds.empty()) return Bvh8();
  return Builder(primBounds, order, settings).run();
}

template <class T> Bounds3<float> roundOutward(const Vec3<T>& lo, const Vec3<T>& hi) {
  return Bounds3<float>::fromMinMax(Vec3<float>(roundDown(lo.x()), roundDown(lo.y()), roundDown(lo.z())),
                                    Vec3<float>(roundUp(hi.x()), roundUp(hi.y()), roundUp(hi.z())));
}

template Bounds3<float> roundOutward<float>(const Vec3<float>&, const Vec3<float>&);
template Bounds3<float> roundOutward<double>(const Vec3<double>&, const Vec3<double>&);

}  // namespace gq::detail
