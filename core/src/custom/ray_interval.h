#pragma once
// Ray parameter intervals for raycasts against intersections of convex regions: each region clips [enter, exit],
// remembering which boundary the ray enters through (for the hit normal).
#include <limits>

#include "gq/hit.h"
#include "gq/math.h"

namespace gq::detail {

template <class T> struct RayInterval {
  T enter = -std::numeric_limits<T>::infinity();
  T exit = std::numeric_limits<T>::infinity();
  int enterSurface = -1;  // which clip set `enter` (-1: none, the origin region is unbounded)
  bool empty() const { return !(enter <= exit); }
  void clip(T lo, T hi, int surface) {
    if (lo > enter) { enter = lo; enterSurface = surface; }
    exit = std::min(exit, hi);
  }
};

// Slab lo <= o + t d <= hi along one axis.
template <class T> void clipSlab(RayInterval<T>& r, T o, T d, T lo, T hi, int surface) {
  if (d == T(0)) {
    if (o < lo || o > hi) r.exit = -std::numeric_limits<T>::infinity();
    return;
  }
  const T t0 = (lo - o) / d, t1 = (hi - o) / d;
  r.clip(std::min(t0, t1), std::max(t0, t1), surface);
}

// Writes a solid-shape raycast answer from the clipped interval: inside -> distance 0, normal -dir, position origin.
// `normalAt(surface, point)` gives the outward normal of the entered surface. Returns false on a miss.
template <class T, class NormalFn>
bool writeIntervalHit(const RayInterval<T>& r, const Vec3<T>& origin, const Vec3<T>& dir, T maxDist, HitFlags flags,
                      NormalFn&& normalAt, RaycastHit<T>& hit) {
  if (r.empty() || r.exit < T(0)) return false;
  if (r.enter <= T(0)) {
    hit.distance = T(0);
    hit.position = origin;
    hit.normal = -dir;
    hit.flags = HitFlag::Position | HitFlag::Normal;
    return true;
  }
  if (r.enter > maxDist) return false;
  hit.distance = r.enter;
  hit.flags = HitFlags();
  const Vec3<T> p = origin + r.enter * dir;
  if (flags.has(HitFlag::Position)) { hit.position = p; hit.flags |= HitFlag::Position; }
  if (flags.has(HitFlag::Normal)) { hit.normal = normalAt(r.enterSurface, p); hit.flags |= HitFlag::Normal; }
  return true;
}

}  // namespace gq::detail
