#pragma once
// Binned-SAH construction of a 4-wide BVH over primitives given by their float bounds.
#include <cstdint>
#include <vector>

#include "bvh/bvh.h"
#include "gq/math.h"

namespace gq::detail {

// Builds the tree over primBounds (float boxes, already rounded outward by the caller). `order` receives the
// primitive permutation: leaf ranges [first, first + count) index into `order` (cooked position -> input primitive).
Bvh4 buildBvh4(const std::vector<Bounds3<float>>& primBounds, std::vector<std::uint32_t>& order);

// The same leaves under 8-wide nodes: each 8-wide node takes a 4-wide node's children and opens its inner children
// (largest surface area first) while their children fit in 8 lanes. Child boxes are copied, so they stay conservative.
// A node's children are stored largest surface area first (the order the unordered any-hit walk takes them in).
Bvh8 collapseToBvh8(const Bvh4& bvh);

// Float box that contains the exact box [lo, hi] of type T (rounded outward with nextafter).
template <class T> Bounds3<float> roundOutward(const Vec3<T>& lo, const Vec3<T>& hi);

}  // namespace gq::detail
