#pragma once
// Binned-SAH construction of an 8-wide BVH over primitives given by their float bounds.
#include <cstdint>
#include <vector>

#include "bvh/bvh.h"
#include "gq/math.h"

namespace gq::detail {

struct BvhBuildSettings {
  // Node levels split by the SAH (0 to 32; other values are clamped); deeper ranges are split at the centroid median
  // (as are ranges whose centroids coincide), which bounds the depth, and so the ray walk's fixed stack
  // (bvh/traverse.h, kBvhStackSize, sized for 32).
  int maxSahDepth = 32;
  // Most primitives a leaf holds (1 to BvhNode::kMaxLeafSize = 4; others are clamped). Triangles: 4, tested at once
  // by the leaf test; scene instances: 1, so the 8-wide node test bounds each instance by its own box.
  std::uint32_t maxLeafSize = 4;
};

// Builds the tree over primBounds (float boxes, already rounded outward by the caller). `order` receives the
// primitive permutation: leaf ranges [first, first + count) index into `order` (cooked position -> input primitive).
// A node's children are stored largest surface area first (the order the unordered any-hit walk takes them in).
Bvh8 buildBvh8(const std::vector<Bounds3<float>>& primBounds, std::vector<std::uint32_t>& order,
               const BvhBuildSettings& settings = BvhBuildSettings());

// Float box that contains the exact box [lo, hi] of type T (rounded outward with nextafter).
template <class T> Bounds3<float> roundOutward(const Vec3<T>& lo, const Vec3<T>& hi);

}  // namespace gq::detail
