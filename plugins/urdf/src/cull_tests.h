#pragma once
// Conservative culling tests of the self-collision checker, cheapest first: enclosing spheres, enclosing capsules
// (segment distance against the radii: tight around the long links of arms), oriented boxes (core's 15-axis SAT). Each
// answers "disjoint" only when the volumes are; the volumes carry the checker's rounding slack.
#include <algorithm>
#include <cmath>
#include <limits>

#include "gq/kernels/overlap.h"
#include "gq/kernels/segment.h"
#include "gq/urdf/self_collision.h"

namespace gq::urdf::internal {

template <class T> bool spheresOverlap(const Vec3<T>& ca, T ra, const Vec3<T>& cb, T rb) {
  return (ca - cb).squaredNorm() <= (ra + rb) * (ra + rb);
}

// Squared distance between segments p0 + s d0 and p1 + t d1, s, t in [0, 1], from core's closest points (the
// cross-product form: for nearly parallel segments its error stays at rounding of |p0 - p1|, where the two-clamp
// form with a e - b^2 lost up to sqrt(eps) |d|; tests/urdf/cull_tests_test.cpp).
template <class T>
T segmentSquaredDistance(const Vec3<T>& p0, const Vec3<T>& d0, const Vec3<T>& p1, const Vec3<T>& d1) {
  const gq::kernels::SegmentClosest<T> c =
      gq::kernels::closestSegmentSegment<T>(p0, Vec3<T>(p0 + d0), p1, Vec3<T>(p1 + d1));
  return (c.c0 - c.c1).squaredNorm();
}

// Capsules (segment from `start` along `span`, radius) are disjoint when their segments are farther apart than the
// sum of the radii.
template <class T>
bool capsulesDisjoint(const Vec3<T>& startA, const Vec3<T>& spanA, T ra, const Vec3<T>& startB, const Vec3<T>& spanB,
                      T rb) {
  return segmentSquaredDistance(startA, spanA, startB, spanB) > (ra + rb) * (ra + rb);
}

// Oriented boxes (centre c, rotation columns r, half extents e, all world) are disjoint when core's box-box test
// (gq/kernels/overlap.h: the 15 axes of the separating-axis theorem, touching counts as overlapping) finds them
// apart, with b given in a's frame.
template <class T> bool orientedBoxesDisjoint(const OrientedBox<T>& a, const OrientedBox<T>& b) {
  const Mat3<T> r = a.axes.transpose() * b.axes;  // b's axes in a's frame
  const Vec3<T> t = a.axes.transpose() * (b.centre - a.centre);
  return !gq::kernels::overlapBoxBox<T>(a.halfExtents, b.halfExtents, r, t);
}

}  // namespace gq::urdf::internal
