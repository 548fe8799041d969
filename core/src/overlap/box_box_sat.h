#pragma once
// Separating axes of two oriented boxes, worked in box 0's frame (Gottschalk, Lin & Manocha 1996): box 0's three
// face normals, box 1's three, and the nine edge-pair cross products. With R = R0^T R1 (box 1's axes as columns in
// box 0's frame) and t = box 1's centre in box 0's frame, an axis L has projected radii
// ra = sum_i a_i |L.e_i|, rb = sum_j b_j |L.r_j| and centre gap |t.L|; the boxes' projections overlap by
// ra + rb - |t.L|. A box is centrally symmetric, so this is exact on every axis, and the minimum over the 15
// axes (normalised) is the exact minimum translation distance: the facet normals of the Minkowski difference are
// among them, and any other axis only overestimates.
#include <cmath>
#include <limits>

#include "gq/geometry.h"
#include "gq/tolerances.h"
#include "gq/transform.h"

namespace gq::detail {

template <class T> struct BoxPair {
  Mat3<T> r;     // box 1's axes in box 0's frame (columns)
  Mat3<T> absR;  // |r|
  Vec3<T> t;     // box 1's centre in box 0's frame
  Vec3<T> a, b;  // half extents
};

// Box 1 given by its axes r (columns) and centre t in box 0's frame (a matrix pose).
template <class T> BoxPair<T> boxPair(const Vec3<T>& a, const Vec3<T>& b, const Mat3<T>& r, const Vec3<T>& t) {
  BoxPair<T> s;
  s.r = r;
  s.absR = r.cwiseAbs();
  s.t = t;
  s.a = a;
  s.b = b;
  return s;
}

template <class T>
BoxPair<T> boxPair(const BoxGeometry<T>& g0, const Transform<T>& p0, const BoxGeometry<T>& g1, const Transform<T>& p1) {
  return boxPair<T>(g0.halfExtents, g1.halfExtents, (p0.q.conjugate() * p1.q).toRotationMatrix(), p0.transformInv(p1.p));
}

// One candidate axis (in box 0's frame, not normalised): overlap of the projections (scaled by |axis|) and the
// signed centre gap t.L.
template <class T> struct BoxAxis {
  Vec3<T> axis;
  T overlap, gap, length;
  int edge0 = -1, edge1 = -1;  // an edge axis e_edge0 x r_edge1; -1 for face axes
};

// Box 0's face axis e_i and box 1's r_j (unit).
template <class T> [[gnu::always_inline]] inline BoxAxis<T> faceAxisOfBox0(const BoxPair<T>& s, int i) {
  const T rb = s.b.dot(s.absR.row(i).transpose());
  return BoxAxis<T>{Vec3<T>::Unit(i), s.a[i] + rb - std::abs(s.t[i]), s.t[i], T(1)};
}
template <class T> [[gnu::always_inline]] inline BoxAxis<T> faceAxisOfBox1(const BoxPair<T>& s, int j) {
  const T gap = s.t.dot(s.r.col(j));
  const T ra = s.a.dot(s.absR.col(j));
  return BoxAxis<T>{Vec3<T>(s.r.col(j)), ra + s.b[j] - std::abs(gap), gap, T(1)};
}

// e_i x c, written out (components (i + 1, i + 2) = (-c[i + 2], c[i + 1]) mod 3, component i = 0): no products, and
// built whole (set by index, a vector went through memory and its whole read stalled on the parts' writes).
template <class T> [[gnu::always_inline]] inline Vec3<T> unitCross(int i, const Vec3<T>& c) {
  if (i == 0) return Vec3<T>(T(0), -c.z(), c.y());
  if (i == 1) return Vec3<T>(c.z(), T(0), -c.x());
  return Vec3<T>(-c.y(), c.x(), T(0));
}

// The edge axis L = e_i x r_j: components (i1, i2) = (-r(i2, j), r(i1, j)), component i = 0, with its overlap and
// centre gap scaled by |L|, length not yet taken. Callers unroll their loops over i and j, so that the index
// arithmetic and unitCross's choice fold away.
template <class T> [[gnu::always_inline]] inline BoxAxis<T> edgeAxisUnnormalised(const BoxPair<T>& s, int i, int j) {
  const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
  const Vec3<T> axis = unitCross(i, Vec3<T>(s.r.col(j)));
  const T gap = s.t[i2] * s.r(i1, j) - s.t[i1] * s.r(i2, j);
  const T ra = s.a[i1] * s.absR(i2, j) + s.a[i2] * s.absR(i1, j);
  const T rb = s.b[j1] * s.absR(i, j2) + s.b[j2] * s.absR(i, j1);
  return BoxAxis<T>{axis, ra + rb - std::abs(gap), gap, std::numeric_limits<T>::quiet_NaN(), i, j};
}

// |L|^2 for the edge axis L = e_i x r_j, from r's entries: the same sum as L.squaredNorm() (L's components are
// -r(i2, j), r(i1, j) and 0), without reading back an L just stored a component at a time (that load could not be
// forwarded from the stores: box-box distance's survey lost ~7 % of its time there).
template <class T> [[gnu::always_inline]] inline T edgeAxisLengthSq(const BoxPair<T>& s, int i, int j) {
  const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
  return s.r(i2, j) * s.r(i2, j) + s.r(i1, j) * s.r(i1, j);
}

// The edge axis with its length, from L's components, not from 1 - r(i, j)^2, which cancels badly for nearly
// parallel edges.
template <class T> [[gnu::always_inline]] inline BoxAxis<T> edgeAxis(const BoxPair<T>& s, int i, int j) {
  BoxAxis<T> e = edgeAxisUnnormalised(s, i, j);
  e.length = std::sqrt(e.axis.squaredNorm());
  return e;
}

// Edge axes of (nearly) parallel edges carry no facet of their own (same rule as the polytope SAT): not axes. An
// edge axis whose squared length is at most parallelLengthSq is one.
template <class T> T parallelLengthSq() {
  const T eps = T(tol::Rel<T>::kEpsilon);
  return eps * eps;
}
template <class T> bool parallelEdges(const BoxAxis<T>& edge) { return edge.axis.squaredNorm() <= parallelLengthSq<T>(); }

// Calls visit(BoxAxis) for the 15 axes in the order face(0), face(1), edges; stops when visit returns true.
// Parallel edges' axes are skipped.
template <class T, class Visit> void forEachBoxAxis(const BoxPair<T>& s, Visit&& visit) {
  for (int i = 0; i < 3; ++i)
    if (visit(faceAxisOfBox0(s, i))) return;
  for (int j = 0; j < 3; ++j)
    if (visit(faceAxisOfBox1(s, j))) return;
#pragma GCC unroll 3
  for (int i = 0; i < 3; ++i) {
#pragma GCC unroll 3
    for (int j = 0; j < 3; ++j) {
      const BoxAxis<T> axis = edgeAxis(s, i, j);
      if (!parallelEdges(axis) && visit(axis)) return;
    }
  }
}

// The least normalised overlap over the 15 axes: its depth, the axis's code (0-2 box 0's faces, 3-5 box 1's,
// 6 + 3i + j box 0's edge i x box 1's edge j) and its unit axis pointing from box 0 towards box 1 (the sign of t.L),
// in box 0's frame. An edge axis must beat the best face axis by edgeSlack (0: the exact minimum, face axes winning
// ties). The survey stops at the first separating axis: separated, with that axis's gap.
template <class T> struct LeastOverlap {
  bool separated = false;
  int code = 0;
  T depth = std::numeric_limits<T>::max();
  T gap = T(0);
  Vec3<T> towardsBox1 = Vec3<T>::UnitX();
};
template <class T> LeastOverlap<T> leastOverlap(const BoxPair<T>& s, T edgeSlack = T(0)) {
  LeastOverlap<T> least;
  int face = 0;
  forEachBoxAxis(s, [&](const BoxAxis<T>& axis) {
    const int code = axis.edge0 < 0 ? face++ : 6 + 3 * axis.edge0 + axis.edge1;
    if (axis.overlap < T(0)) {
      least.separated = true;
      least.gap = -axis.overlap / axis.length;
      return true;
    }
    const T d = axis.overlap / axis.length;
    if (d < least.depth - (code >= 6 && least.code < 6 ? edgeSlack : T(0))) {
      least.depth = d;
      least.code = code;
      least.towardsBox1 = (axis.gap > T(0) ? axis.axis : Vec3<T>(-axis.axis)) / axis.length;
    }
    return false;
  });
  return least;
}

// The minimum translation distance and its axis (leastOverlap without slack). False when an axis separates.
template <class T> bool leastOverlapAxis(const BoxPair<T>& s, T& depth, Vec3<T>& towardsBox1) {
  const LeastOverlap<T> least = leastOverlap(s);
  depth = least.depth;
  towardsBox1 = least.towardsBox1;
  return !least.separated;
}

}  // namespace gq::detail
