#pragma once
// Surface vs surface overlap for pairs without a dual tree (mesh-heightfield, heightfield-heightfield): every
// triangle of `a` under b's box, against b's triangles under that triangle's box, with the exact triangle-triangle
// test. `margin` > 0 turns it into a proximity test (triangle distance <= margin).
#include "mesh_pairs/surface.h"
#include "mesh_pairs/triangle_tests.h"

namespace gq::detail {

template <class T> bool trianglesWithin(const Triangle<T>& x, const Triangle<T>& y, T margin) {
  if (margin <= T(0)) return overlapTriangleTriangle(x, y);
  return closestTriangleTriangle(x, y).distSq <= margin * margin;
}

// fn(indexA, triA, indexB, triB) returns true to stop; returns whether it stopped.
template <class T, class SurfaceA, class SurfaceB, class PairFn>
bool forEachSurfacePair(const SurfaceA& a, const SurfaceB& b, T margin, PairFn&& fn) {
  return a.forEachTriangle(grown(b.worldBounds(), margin), [&](std::uint32_t ia, const Triangle<T>& ta) {
    return b.forEachTriangle(grown(triangleBounds(ta), margin), [&](std::uint32_t ib, const Triangle<T>& tb) {
      return trianglesWithin(ta, tb, margin) && fn(ia, ta, ib, tb);
    });
  });
}

}  // namespace gq::detail
