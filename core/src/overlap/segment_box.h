#pragma once
// A segment against a box, in the box's frame (box = [-h, h]): the kernels of the capsule/box pair (and of a sphere,
// the zero-length segment). The segment is c + s d for s in [-1, 1] (d = half of it).
//  - satSegmentBox: the separating axes of a segment and a box are the box's 3 face normals and the 3 cross
//    products d x e_k (the facet normals of box - segment). Returns the smallest normalised projection overlap
//    (negative = the largest separating gap) and its axis, oriented to move the segment away from the box.
//  - closestSegmentBox: exact closest points. dist^2(c + s d, box) is a sum over the axes of convex piecewise
//    quadratics whose breakpoints are where the segment crosses a slab plane; between breakpoints it is one
//    quadratic, minimised in closed form, so the global minimum is exact.
#include <algorithm>
#include <cmath>
#include <limits>

#include "gq/math.h"
#include "gq/tolerances.h"

namespace gq::detail {

template <class T> struct SegmentBoxSat {
  T overlap;          // min over axes; < 0: separated by -overlap along `direction`
  Vec3<T> direction;  // unit, box frame: moving the segment this way separates them (by overlap, if positive)
};

template <class T> SegmentBoxSat<T> satSegmentBox(const Vec3<T>& c, const Vec3<T>& d, const Vec3<T>& h) {
  SegmentBoxSat<T> best{std::numeric_limits<T>::max(), Vec3<T>::UnitX()};
  const auto consider = [&](const Vec3<T>& unitAxis, T overlap, T gap) {
    if (overlap < best.overlap) best = {overlap, gap >= T(0) ? unitAxis : Vec3<T>(-unitAxis)};
  };
  for (int k = 0; k < 3; ++k) consider(Vec3<T>::Unit(k), h[k] + std::abs(d[k]) - std::abs(c[k]), c[k]);
  const T eps = T(tol::Rel<T>::kEpsilon);
  const T dSq = d.squaredNorm();
  for (int k = 0; k < 3; ++k) {
    const Vec3<T> axis = d.cross(Vec3<T>::Unit(k));
    const T lenSq = axis.squaredNorm();
    if (lenSq <= eps * eps * dSq || !(lenSq > T(0))) continue;  // parallel to the box edge: no facet of its own
    const T len = std::sqrt(lenSq);
    const T gap = c.dot(axis);
    consider(Vec3<T>(axis / len), (h.dot(axis.cwiseAbs()) - std::abs(gap)) / len, gap);
  }
  return best;
}

template <class T> struct SegmentBoxClosest {
  T distSq;
  Vec3<T> onSegment, onBox;
};

template <class T> SegmentBoxClosest<T> closestSegmentBox(const Vec3<T>& c, const Vec3<T>& d, const Vec3<T>& h) {
  // Breakpoints: where c_k + s d_k = +-h_k inside (-1, 1).
  T cuts[8];
  int n = 0;
  cuts[n++] = T(-1);
  for (int k = 0; k < 3; ++k) {
    if (d[k] == T(0)) continue;
    for (T side : {-h[k], h[k]}) {
      const T s = (side - c[k]) / d[k];
      if (s > T(-1) && s < T(1)) cuts[n++] = s;
    }
  }
  cuts[n++] = T(1);
  if (n > 8) __builtin_unreachable();  // at most 1 + 6 + 1 cuts: tells GCC that std::sort's 16-element prefix pass is dead
  std::sort(cuts, cuts + n);
  const auto distSqAt = [&](T s) {
    const Vec3<T> p = c + s * d;
    return (p - p.cwiseMax(-h).cwiseMin(h)).squaredNorm();
  };
  T bestS = cuts[0], bestDistSq = distSqAt(cuts[0]);
  for (int i = 0; i + 1 < n; ++i) {
    const T s0 = cuts[i], s1 = cuts[i + 1];
    if (!(s1 > s0)) continue;
    // On (s0, s1) every axis stays below, inside or above its slab: f(s) = sum over outside axes of
    // (c_k + s d_k - side_k)^2, minimised at s = -sum d_k (c_k - side_k) / sum d_k^2.
    const Vec3<T> mid = c + (T(0.5) * (s0 + s1)) * d;
    T a = T(0), b = T(0);
    for (int k = 0; k < 3; ++k) {
      if (mid[k] > h[k]) {
        a += d[k] * d[k];
        b += d[k] * (c[k] - h[k]);
      } else if (mid[k] < -h[k]) {
        a += d[k] * d[k];
        b += d[k] * (c[k] + h[k]);
      }
    }
    const T s = a > T(0) ? std::clamp(-b / a, s0, s1) : s0;
    const T f = distSqAt(s);
    if (f < bestDistSq) {
      bestDistSq = f;
      bestS = s;
    }
  }
  const Vec3<T> p = c + bestS * d;
  return {bestDistSq, p, p.cwiseMax(-h).cwiseMin(h)};
}

}  // namespace gq::detail
