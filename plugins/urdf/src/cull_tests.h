#pragma once
// Conservative culling tests of the self-collision checker, cheapest first: enclosing spheres, enclosing capsules
// (segment distance against the radii: tight around the long links of arms), oriented boxes (15-axis SAT). Each
// answers "disjoint" only when the volumes are; the volumes carry the checker's rounding slack.
#include <algorithm>
#include <cmath>
#include <limits>

#include "gq/urdf/self_collision.h"
#include "shapes/segment.h"  // core/src (private include path)

namespace gq::urdf::detail {

template <class T> bool spheresOverlap(const Vec3<T>& ca, T ra, const Vec3<T>& cb, T rb) {
  return (ca - cb).squaredNorm() <= (ra + rb) * (ra + rb);
}

// Squared distance between segments p0 + s d0 and p1 + t d1, s, t in [0, 1], from core's closest points (the
// cross-product form: for nearly parallel segments its error stays at rounding of |p0 - p1|, where the two-clamp
// form with a e - b^2 lost up to sqrt(eps) |d|; tests/urdf/cull_tests_test.cpp).
template <class T>
T segmentSquaredDistance(const Vec3<T>& p0, const Vec3<T>& d0, const Vec3<T>& p1, const Vec3<T>& d1) {
  const gq::detail::SegmentClosest<T> c =
      gq::detail::closestSegmentSegment<T>(p0, Vec3<T>(p0 + d0), p1, Vec3<T>(p1 + d1));
  return (c.c0 - c.c1).squaredNorm();
}

// Capsules (segment from `start` along `span`, radius) are disjoint when their segments are farther apart than the
// sum of the radii.
template <class T>
bool capsulesDisjoint(const Vec3<T>& startA, const Vec3<T>& spanA, T ra, const Vec3<T>& startB, const Vec3<T>& spanB,
                      T rb) {
  return segmentSquaredDistance(startA, spanA, startB, spanB) > (ra + rb) * (ra + rb);
}

// Oriented boxes (centre c, rotation columns r, half extents e, all world) are disjoint when one of the 15 axes of
// the separating-axis theorem (3 + 3 face normals, 9 edge cross products) separates their projections.
template <class T> bool orientedBoxesDisjoint(const OrientedBox<T>& a, const OrientedBox<T>& b) {
  const Mat3<T> r = a.axes.transpose() * b.axes;  // b's axes in a's frame
  // Unitless guard on |R|: near-parallel edges give a near-zero cross product, whose axis must not cull.
  const T parallelGuard = T(16) * std::numeric_limits<T>::epsilon();
  const Mat3<T> absR = r.cwiseAbs().array() + parallelGuard;
  const Vec3<T> t = a.axes.transpose() * (b.centre - a.centre);
  for (int i = 0; i < 3; ++i)
    if (std::abs(t[i]) > a.halfExtents[i] + absR.row(i).dot(b.halfExtents)) return true;
  for (int j = 0; j < 3; ++j)
    if (std::abs(t.dot(r.col(j))) > absR.col(j).dot(a.halfExtents) + b.halfExtents[j]) return true;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      const T ra = a.halfExtents[i1] * absR(i2, j) + a.halfExtents[i2] * absR(i1, j);
      const T rb = b.halfExtents[j1] * absR(i, j2) + b.halfExtents[j2] * absR(i, j1);
      if (std::abs(t[i2] * r(i1, j) - t[i1] * r(i2, j)) > ra + rb) return true;
    }
  return false;
}

}  // namespace gq::urdf::detail
