#pragma once
// FCL 0.7's contact set of two boxes (its box routine, ODE's dBoxBox rules), built around gq's exact minimum
// translation: FCL's axis choice is replaced by the exact normal and depth, its point rules are kept.
//  - Normal along a face axis of one box (the reference box; box a when both are, as FCL tests a's axes first): the
//    other box's face most opposed to it (incident face) is projected on the reference face and clipped to it; each
//    clipped point below the reference face (depth >= 0) is a contact, placed midway between its incident-face point
//    and the reference face, with its own depth. More than 4: the deepest, then the 3 whose angles about the clipped
//    polygon's centroid are nearest the deepest's plus 90, 180 and 270 degrees (FCL's culling). Coincident centres
//    leave the normal's sign free: FCL's, + the reference box's axis.
//  - Otherwise (an edge pair): one contact midway between the closest points of the lines through the two touching
//    edges (each box's edge perpendicular to the normal at its vertex farthest towards the other box), at the depth.
#include <algorithm>
#include <cmath>
#include <limits>

#include "gq/kernels/clip.h"
#include "gq/math.h"

namespace gq::fcl::internal {

template <class S> struct BoxContact {
  Vec3<S> position;
  S depth;
};

// A box: centre, axes (columns), half extents.
template <class S> struct OrientedBox {
  Vec3<S> centre;
  Mat3<S> axes;
  Vec3<S> half;
};

template <class S> constexpr S kFaceAxisCos = S(1) - S(64) * std::numeric_limits<S>::epsilon();

// The axis of `box` most aligned with unit `n`: its index and n's component along it.
template <class S> int mostAlignedAxis(const OrientedBox<S>& box, const Vec3<S>& n, S& component) {
  const Vec3<S> local = box.axes.transpose() * n;
  int k = 0;
  local.cwiseAbs().maxCoeff(&k);
  component = local[k];
  return k;
}

// FCL's culling of a clipped polygon's points (2D, in order around it) to `keep`: the deepest (`first`), then for
// j = 1..keep-1 the unused point whose angle about the polygon's area centroid is nearest angle(first) + 2 pi j / keep.
template <class S> int cullToAngles(const S (*xy)[2], int count, int first, int keep, int* chosen) {
  S cx = 0, cy = 0;
  if (count == 1) {
    cx = xy[0][0], cy = xy[0][1];
  } else if (count == 2) {
    cx = S(0.5) * (xy[0][0] + xy[1][0]), cy = S(0.5) * (xy[0][1] + xy[1][1]);
  } else {
    S area2 = 0;  // twice the signed area; the centroid is sum((p_i + p_i+1) cross_i) / (3 area2)
    for (int i = 0; i < count; ++i) {
      const int j = i + 1 == count ? 0 : i + 1;
      const S cross = xy[i][0] * xy[j][1] - xy[j][0] * xy[i][1];
      area2 += cross;
      cx += cross * (xy[i][0] + xy[j][0]);
      cy += cross * (xy[i][1] + xy[j][1]);
    }
    const S scale = std::abs(area2) > std::numeric_limits<S>::epsilon() ? S(1) / (S(3) * area2) : S(1e18);
    cx *= scale, cy *= scale;
  }
  const S pi = S(3.14159265358979323846);
  S angle[8];
  bool used[8] = {};
  for (int i = 0; i < count; ++i) angle[i] = std::atan2(xy[i][1] - cy, xy[i][0] - cx);
  chosen[0] = first;
  used[first] = true;
  for (int j = 1; j < keep; ++j) {
    S target = angle[first] + S(j) * (S(2) * pi / S(keep));
    if (target > pi) target -= S(2) * pi;
    int best = first;
    S bestDiff = S(1e9);
    for (int i = 0; i < count; ++i) {
      if (used[i]) continue;
      S diff = std::abs(angle[i] - target);
      if (diff > pi) diff = S(2) * pi - diff;
      if (diff < bestDiff) bestDiff = diff, best = i;
    }
    used[best] = true;
    chosen[j] = best;
  }
  return keep;
}

// The face case: `ref`'s face with outward unit normal `up` (towards `inc`), the incident face of `inc` clipped to it.
template <class S>
int boxFaceContacts(const OrientedBox<S>& ref, int axis, const Vec3<S>& up, const OrientedBox<S>& inc,
                    BoxContact<S>* out) {
  const int u = axis == 0 ? 1 : 0, w = axis == 2 ? 1 : 2;  // the reference face's in-plane axes, in FCL's order
  S towards;
  const int f = mostAlignedAxis(inc, up, towards);
  const int a1 = f == 0 ? 1 : 0, a2 = f == 2 ? 1 : 2;
  const Vec3<S> faceCentre = inc.centre - inc.axes.col(f) * (towards < 0 ? -inc.half[f] : inc.half[f]);
  const Vec3<S> e1 = inc.axes.col(a1) * inc.half[a1], e2 = inc.axes.col(a2) * inc.half[a2];
  const S s1[4] = {-1, -1, 1, 1}, s2[4] = {-1, 1, 1, -1};
  kernels::RectanglePoint<S> bufferA[8], bufferB[8];
  for (int c = 0; c < 4; ++c) {
    const Vec3<S> d = faceCentre + e1 * s1[c] + e2 * s2[c] - ref.centre;
    bufferA[c] = {{d.dot(ref.axes.col(u)), d.dot(ref.axes.col(w)), d.dot(up)}};
  }
  kernels::RectanglePoint<S>* clipped = nullptr;
  const int n = kernels::clipToRectangle(bufferA, bufferB, 4, 8, ref.half[u], ref.half[w], clipped);
  S xy[8][2];
  BoxContact<S> all[8];
  int kept = 0, deepest = 0;
  for (int i = 0; i < n; ++i) {
    const S depth = ref.half[axis] - clipped[i].c[2];
    if (!(depth >= S(0))) continue;
    xy[kept][0] = clipped[i].c[0], xy[kept][1] = clipped[i].c[1];
    const Vec3<S> onIncident = ref.centre + ref.axes.col(u) * clipped[i].c[0] + ref.axes.col(w) * clipped[i].c[1] +
                               up * clipped[i].c[2];
    all[kept] = {Vec3<S>(onIncident + up * (depth / S(2))), depth};
    if (depth > all[deepest].depth) deepest = kept;
    ++kept;
  }
  int order[8] = {0, 1, 2, 3, 4, 5, 6, 7};
  const int count = kept > 4 ? cullToAngles<S>(xy, kept, deepest, 4, order) : kept;
  for (int j = 0; j < count; ++j) out[j] = all[order[j]];
  return count;
}

// The edge case: the lines through box a's edge along axis i at its vertex farthest along n and box b's along axis j
// at its vertex farthest against n; their closest points (the lines' own, not clamped to the edges), midway.
template <class S>
Vec3<S> boxEdgeContact(const OrientedBox<S>& a, const OrientedBox<S>& b, const Vec3<S>& n) {
  Vec3<S> pa = a.centre, pb = b.centre;
  for (int k = 0; k < 3; ++k) {
    pa += a.axes.col(k) * (a.axes.col(k).dot(n) > 0 ? a.half[k] : -a.half[k]);
    pb += b.axes.col(k) * (b.axes.col(k).dot(n) > 0 ? -b.half[k] : b.half[k]);
  }
  int i = 0, j = 0;
  (a.axes.transpose() * n).cwiseAbs().minCoeff(&i);
  (b.axes.transpose() * n).cwiseAbs().minCoeff(&j);
  const Vec3<S> ua = a.axes.col(i), ub = b.axes.col(j), d = pb - pa;
  const S c = ua.dot(ub), denom = S(1) - c * c;
  S alpha = 0, beta = 0;
  if (denom > S(1e-4)) {  // FCL treats nearer-parallel lines as crossing at pa and pb
    const S qa = ua.dot(d), qb = ub.dot(d);
    alpha = (qa - c * qb) / denom;
    beta = (c * qa - qb) / denom;
  }
  return (pa + ua * alpha + pb + ub * beta) / S(2);
}

// The set for boxes a, b whose exact minimum translation is `n` (unit, from a to b) and `depth`: at most 4 contacts
// written to `out` (FCL's order), their common normal (from a to b) to `normal`.
template <class S>
int fclBoxContactSet(const OrientedBox<S>& a, const OrientedBox<S>& b, const Vec3<S>& n, S depth, Vec3<S>& normal,
                     BoxContact<S>* out) {
  S ca, cb;
  const int ka = mostAlignedAxis(a, n, ca), kb = mostAlignedAxis(b, n, cb);
  // Coincident centres: both signs of the axis are minimum translations; FCL's is + the reference box's axis.
  const bool concentric = a.centre == b.centre;
  if (std::abs(ca) >= kFaceAxisCos<S>) {
    normal = a.axes.col(ka) * (ca < 0 && !concentric ? S(-1) : S(1));
    return boxFaceContacts(a, ka, normal, b, out);
  }
  if (std::abs(cb) >= kFaceAxisCos<S>) {
    normal = b.axes.col(kb) * (cb < 0 && !concentric ? S(-1) : S(1));
    return boxFaceContacts(b, kb, Vec3<S>(-normal), a, out);
  }
  normal = n;
  out[0] = {boxEdgeContact(a, b, n), depth};
  return 1;
}

}  // namespace gq::fcl::internal
