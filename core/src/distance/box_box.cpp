// Overlapping boxes, in box 0's frame (the FCL adapter's fast path; separated boxes go to GJK).
//  - Depth and normal: the 15-axis SAT (overlap/box_box_sat.h), exact; face axes win ties (as penetrationBoxBox).
//  - Witnesses: box 1 moved out by the depth along the normal touches box 0. The touching set is the intersection of
//    the two support features along the normal. Generically it is a support vertex of one box on the other's face
//    or the crossing of the two support edges (genericTouch). Otherwise (parallel features) a point of it lies on
//    an edge through box 0's support vertex along n or through box 1's support vertex along -n, found by the exact
//    segment-box closest points (overlap/segment_box.h) of those six edges against the other box. When none
//    touches either (parallel faces whose contact polygon avoids these edges) the caller falls back to GJK/EPA.
#include <limits>

#include "distance/distance.h"
#include "shapes/segment.h"
#include "gq/tolerances.h"
#include "overlap/box_box_sat.h"
#include "overlap/segment_box.h"

namespace gq::detail {
namespace {

// A touching edge of the moved box pair is found when its segment-box distance is round-off: kTouchUlps machine
// epsilons of the pair's size.
constexpr double kTouchUlps = 64.0;

template <class T> struct Touch {
  T distSq = std::numeric_limits<T>::max();
  Vec3<T> point = Vec3<T>::Zero();  // on box 0, box 0's frame
};

// The box vertex with the signs of `dir` (ties to +).
template <class T> Vec3<T> supportVertex(const Vec3<T>& h, const Vec3<T>& dir) {
  return Vec3<T>(dir.x() < T(0) ? -h.x() : h.x(), dir.y() < T(0) ? -h.y() : h.y(), dir.z() < T(0) ? -h.z() : h.z());
}

template <class T> bool inBox(const Vec3<T>& p, const Vec3<T>& h, T tolerance) {
  return ((p.cwiseAbs() - h).array() <= tolerance).all();
}

template <class T> Eigen::Index mostPerpendicular(const Vec3<T>& dir) {
  Eigen::Index i;
  dir.cwiseAbs().minCoeff(&i);
  return i;
}

// The generic touching configurations, cheapest first (box 1 at (r, t) after the move; n from box 0 to box 1):
// box 1's support vertex on box 0's face, box 0's support vertex on box 1's face, or the crossing of the two
// support edges (each the box edge through its support vertex most perpendicular to n). False: none within
// `tolerance` (degenerate, parallel features).
template <class T>
bool genericTouch(const BoxPair<T>& s, const Vec3<T>& n, const Vec3<T>& t, T tolerance, Vec3<T>& point) {
  const Vec3<T> nInB = s.r.transpose() * n;
  const Vec3<T> vb = supportVertex(s.b, Vec3<T>(-nInB));
  const Vec3<T> vbInA = s.r * vb + t;
  if (inBox(vbInA, s.a, tolerance)) return point = vbInA, true;
  const Vec3<T> va = supportVertex(s.a, n);
  if (inBox(Vec3<T>(s.r.transpose() * (va - t)), s.b, tolerance)) return point = va, true;
  const Eigen::Index i = mostPerpendicular(n), j = mostPerpendicular(nInB);
  Vec3<T> vaEnd = va;
  vaEnd[i] = -va[i];
  const Vec3<T> vbEnd = vbInA - T(2) * vb[j] * Vec3<T>(s.r.col(j));
  const SegmentClosest<T> c = closestSegmentSegment<T>(va, vaEnd, vbInA, vbEnd);
  if (!((c.c0 - c.c1).squaredNorm() <= tolerance * tolerance)) return false;
  point = c.c0;
  return true;
}

// Box 0's edges through its support vertex along n, against box 1 at (r, t): closest points in box 1's frame.
template <class T>
void edgesOfBox0(const BoxPair<T>& s, const Vec3<T>& n, const Vec3<T>& t, Touch<T>& best) {
  const Vec3<T> v = supportVertex(s.a, n);
  for (int k = 0; k < 3; ++k) {
    Vec3<T> mid = v;
    mid[k] = T(0);  // the edge along axis k through v runs from v to v with coordinate k negated
    Vec3<T> half = Vec3<T>::Zero();
    half[k] = v[k];
    const SegmentBoxClosest<T> c = closestSegmentBox(Vec3<T>(s.r.transpose() * (mid - t)), Vec3<T>(s.r.transpose() * half), s.b);
    if (c.distSq < best.distSq) best = {c.distSq, Vec3<T>(s.r * c.onSegment + t)};
  }
}

// Box 1's edges through its support vertex along -n, against box 0: closest points in box 0's frame.
template <class T>
void edgesOfBox1(const BoxPair<T>& s, const Vec3<T>& n, const Vec3<T>& t, Touch<T>& best) {
  const Vec3<T> v = supportVertex(s.b, Vec3<T>(-(s.r.transpose() * n)));
  for (int k = 0; k < 3; ++k) {
    Vec3<T> mid = v;
    mid[k] = T(0);
    const SegmentBoxClosest<T> c = closestSegmentBox(Vec3<T>(s.r * mid + t), Vec3<T>(s.r.col(k) * v[k]), s.a);
    if (c.distSq < best.distSq) best = {c.distSq, c.onBox};
  }
}

}  // namespace

template <class T>
bool distanceBoxBoxOverlapping(const Vec3<T>& h0, const Vec3<T>& h1, const Mat3<T>& r01, const Vec3<T>& t01,
                               DistanceResult<T>& local) {
  const BoxPair<T> pair = boxPair(h0, h1, r01, t01);
  T depth;
  Vec3<T> n;  // towards box 1
  if (!leastOverlapAxis(pair, depth, n)) return false;
  const Vec3<T> moved = t01 + depth * n;  // box 1 touching box 0
  const T size = h0.norm() + h1.norm() + t01.norm();
  const T tolerance = T(kTouchUlps) * std::numeric_limits<T>::epsilon() * size;
  Touch<T> touch;
  if (!genericTouch(pair, n, moved, tolerance, touch.point)) {
    edgesOfBox0(pair, n, moved, touch);
    edgesOfBox1(pair, n, moved, touch);
    if (!(touch.distSq <= tolerance * tolerance)) return false;
  }
  local.distance = -depth;
  local.normal = n;
  local.point0 = touch.point;
  local.point1 = touch.point - depth * n;
  return true;
}

template bool distanceBoxBoxOverlapping<float>(const Vec3<float>&, const Vec3<float>&, const Mat3<float>&, const Vec3<float>&, DistanceResult<float>&);
template bool distanceBoxBoxOverlapping<double>(const Vec3<double>&, const Vec3<double>&, const Mat3<double>&, const Vec3<double>&, DistanceResult<double>&);

}  // namespace gq::detail
