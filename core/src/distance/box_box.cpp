// Boxes, in box 0's frame (box 1: axes r as columns, centre t): the 15-axis SAT decides (overlap/box_box_sat.h).
// Separated boxes (separatedClosest): the closest pair of two convex polytopes is a vertex of one against the other
// box (vertex-face, -edge, -vertex) or the interiors of two edges. Two edge interiors closest along n are both
// normal to n, so n = e_i x r_j, and each edge is its box's support edge along n (box 0's) or -n (box 1's), n
// oriented from box 0 to box 1 (n.t > 0: the centres lie behind the two supporting planes). Every candidate is a
// pair of points of the two boxes, an upper bound of the distance, so the least of the 16 vertex-box and the edge-edge
// candidates is the distance. An edge pair's interior closest pair is at the distance along its axis, which bounds
// every axis's gap, so only the axes of the largest gap among the SAT's 15 are tried (typically none or one; parallel
// edges give no candidate of their own: their closest pairs slide to a vertex). Replaces GJK for separated boxes
// (exact, and fewer instructions per FCL-adapter box-box distance than GJK: ~2,200 against ~3,500). Every axis's gap
// is a lower bound of the distance, so a candidate at the largest gap is proven without the others: first a vertex
// over the face of the largest face gap (the six face axes alone, faceCertificate), then an edge pair at the largest
// gap (before the 16 vertex candidates): the certificates save ~400 of the ~2,600 instructions of an adapter call.
// Overlapping boxes:
//  - Depth and normal: the SAT's least overlap, exact; face axes win ties (as penetrationBoxBox).
//  - Witnesses: box 1 moved out by the depth along the normal touches box 0. The touching set is the intersection of
//    the two support features along the normal. Generically it is a support vertex of one box on the other's face
//    or the crossing of the two support edges (genericTouch). Otherwise (parallel features) a point of it lies on
//    an edge through box 0's support vertex along n or through box 1's support vertex along -n, found by the exact
//    segment-box closest points (overlap/segment_box.h) of those six edges against the other box. When none
//    touches either (parallel faces whose contact polygon avoids these edges) the caller falls back to GJK/EPA.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "distance/distance.h"
#include "gjk/pair_scale.h"
#include "shapes/segment.h"
#include "gq/tolerances.h"
#include "overlap/box_box_sat.h"
#include "overlap/segment_box.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers
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

// A candidate pair: a point of each box, both in box 0's frame or, for box 0's vertices, both in box 1's (`inBox1`:
// the distance is the same; only the chosen pair goes back).
template <class T> struct Candidate {
  T distSq;
  Vec3<T> p0, p1;
  bool inBox1;
};

template <class T> Vec3<T> clampToBox(const Vec3<T>& p, const Vec3<T>& h) { return p.cwiseMax(-h).cwiseMin(h); }

// The 8 corners centre + sum_j (+-1) halfAxes.col(j), corner k taking + where bit j of k is set.
template <class T> std::array<Vec3<T>, 8> corners(const Vec3<T>& centre, const Mat3<T>& halfAxes) {
  std::array<Vec3<T>, 8> v;
  v[0] = centre - halfAxes.col(0) - halfAxes.col(1) - halfAxes.col(2);
  for (int j = 0; j < 3; ++j) {
    const Vec3<T> step = T(2) * halfAxes.col(j);
    for (int k = 0; k < (1 << j); ++k) v[k | (1 << j)] = v[k] + step;
  }
  return v;
}

// Candidates: the 16 vertices of either box against the other box (whose closest point is the vertex clamped into
// it; box 1's in box 0's frame, box 0's in box 1's) and a few edge pairs.
template <class T> struct Candidates {
  std::array<Vec3<T>, 8> of1, of0;  // box 1's corners (box 0's frame), box 0's corners (box 1's frame)
  std::array<T, 16> vertexDistSq;
  std::array<Candidate<T>, 9> edges;
  int edgeCount = 0;
  T least = std::numeric_limits<T>::infinity();

  void addEdge(const Vec3<T>& p0, const Vec3<T>& p1) {
    const T d = (p1 - p0).squaredNorm();
    edges[edgeCount++] = {d, p0, p1, false};
    least = std::min(least, d);
  }
  Candidate<T> vertex(int k, const BoxPair<T>& s) const {
    if (k < 8) return {vertexDistSq[k], clampToBox(of1[k], s.a), of1[k], false};
    return {vertexDistSq[k], of0[k - 8], clampToBox(of0[k - 8], s.b), true};
  }
};

template <class T> void vertexCandidates(const BoxPair<T>& s, Candidates<T>& out) {
  out.of1 = corners<T>(s.t, s.r * s.b.asDiagonal());
  out.of0 = corners<T>(Vec3<T>(-(s.r.transpose() * s.t)), s.r.transpose() * s.a.asDiagonal());
  for (int k = 0; k < 8; ++k) {
    out.vertexDistSq[k] = (out.of1[k] - clampToBox(out.of1[k], s.a)).squaredNorm();
    out.vertexDistSq[k + 8] = (out.of0[k] - clampToBox(out.of0[k], s.b)).squaredNorm();
  }
  out.least = std::min(out.least, *std::min_element(out.vertexDistSq.begin(), out.vertexDistSq.end()));
}

// The closest points of box 0's edge along e_i and box 1's along r_j that are the boxes' support edges along the
// unit axis n = e_i x r_j / |e_i x r_j| oriented from box 0 to box 1.
template <class T> void edgeCandidate(const BoxPair<T>& s, int i, int j, const Vec3<T>& n, Candidates<T>& out) {
  Vec3<T> c0 = supportVertex(s.a, n);
  c0[i] = T(0);
  Vec3<T> c1 = supportVertex(s.b, Vec3<T>(-(s.r.transpose() * n)));
  c1[j] = T(0);
  const Vec3<T> centre1 = s.r * c1 + s.t, half1 = s.b[j] * s.r.col(j);
  const Vec3<T> half0 = s.a[i] * Vec3<T>::Unit(i);
  const SegmentClosest<T> c = closestSegmentSegment<T>(c0 - half0, c0 + half0, centre1 - half1, centre1 + half1);
  out.addEdge(c.c0, c.c1);
}

// The 15 SAT axes surveyed: the least normalised overlap and its axis (face axes win ties, as leastOverlapAxis),
// which is also the largest gap's (negated overlap; positive: separated), and each edge axis's gap.
template <class T> struct AxisSurvey {
  T leastOverlap;
  Vec3<T> leastAxis;         // unit, towards box 1
  std::array<T, 9> edgeGap;  // e_i x r_j at 3 i + j; -inf for (nearly) parallel edges

  T largestGap() const { return -leastOverlap; }
  bool separated() const { return largestGap() > T(0); }
};

// Every axis's normalised overlap is computed before any is compared, the edge axes' square roots and divisions two
// to an instruction (Eigen's packets) and independent of the comparisons. Visiting the axes in turn (forEachBoxAxis)
// chained each axis's square root and division to the previous comparison and assembled each edge axis in memory:
// 56 % of an adapter box-box distance call's time by perf's samples, ~1.6x the time a call of the survey below takes.
template <class T> AxisSurvey<T> surveyAxes(const BoxPair<T>& s) {
  std::array<BoxAxis<T>, 15> axes;
  for (int i = 0; i < 3; ++i) axes[i] = faceAxisOfBox0(s, i);
  for (int j = 0; j < 3; ++j) axes[3 + j] = faceAxisOfBox1(s, j);
  Eigen::Array<T, 9, 1> lengthSq, scaled;
#pragma GCC unroll 3
  for (int i = 0; i < 3; ++i)
#pragma GCC unroll 3
    for (int j = 0; j < 3; ++j) {
      BoxAxis<T>& e = axes[6 + 3 * i + j];
      e = edgeAxisUnnormalised(s, i, j);
      lengthSq[3 * i + j] = edgeAxisLengthSq(s, i, j);
      scaled[3 * i + j] = e.overlap;
    }
  const Eigen::Array<T, 9, 1> length = lengthSq.sqrt();
  const Eigen::Array<T, 9, 1> edgeOverlap =  // parallel edges (parallelEdges): no axis
      (lengthSq <= parallelLengthSq<T>()).select(std::numeric_limits<T>::infinity(), scaled / length);
  std::array<T, 15> overlap;  // normalised
  for (int k = 0; k < 6; ++k) overlap[k] = axes[k].overlap;
  for (int k = 0; k < 9; ++k) overlap[6 + k] = edgeOverlap[k], axes[6 + k].length = length[k];
  const auto least = std::min_element(overlap.begin(), overlap.end());  // the first of equals
  const BoxAxis<T>& axis = axes[std::size_t(least - overlap.begin())];
  AxisSurvey<T> v;
  v.leastOverlap = *least;
  v.leastAxis = (axis.gap > T(0) ? axis.axis : Vec3<T>(-axis.axis)) / axis.length;
  for (int k = 0; k < 9; ++k) v.edgeGap[k] = -overlap[6 + k];
  return v;
}

// Edge pairs whose interiors may hold the closest pair: then the distance is the gap along their axis, and every
// axis's gap is a lower bound of the distance, so their axis has the largest gap of the 15 (within `slack`).
template <class T> void edgeCandidates(const BoxPair<T>& s, const AxisSurvey<T>& survey, T slack, Candidates<T>& out) {
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (!(survey.edgeGap[3 * i + j] >= survey.largestGap() - slack)) continue;
      const Vec3<T> n = unitCross(i, Vec3<T>(s.r.col(j))).normalized();
      edgeCandidate(s, i, j, n.dot(s.t) < T(0) ? Vec3<T>(-n) : n, out);
    }
  }
}

// The separation the plane normal to unit n (box 0's frame, from box 0 to box 1) proves: a lower bound of the
// distance, equal to it along the exact closest pair's direction.
template <class T> T gapAlong(const BoxPair<T>& s, const Vec3<T>& n) {
  return n.dot(s.t) - s.b.dot((s.r.transpose() * n).cwiseAbs()) - s.a.dot(n.cwiseAbs());
}

// |p_k| <= h_k on the two axes other than `axis`: p projects into the box's faces normal to that axis.
template <class T> bool overFace(const Vec3<T>& p, const Vec3<T>& h, int axis) {
  const int k1 = (axis + 1) % 3, k2 = (axis + 2) % 3;
  return std::abs(p[k1]) <= h[k1] && std::abs(p[k2]) <= h[k2];
}

// Vertex-face certificate, the common separated case, without the edge axes or the candidates: when the largest
// face gap (positive) lies along a face normal n of one box and the other box's support vertex towards it projects
// into that face, the vertex and its projection are a pair of points of the boxes whose distance is the gap along n.
// Every axis's gap is a lower bound of the distance, so this pair is a closest pair (its direction proves the whole
// distance, as separatedClosest's choice), whatever the edge axes would show.
// Inline: called out of line it read the pair its caller had just written (box-box distance 1,986 -> 1,914).
template <class T> [[gnu::always_inline]] inline bool faceCertificate(const BoxPair<T>& s, DistanceResult<T>& local) {
  // The six face gaps: |t_i| - a_i - (box 1's extent along e_i), |t.r_j| - b_j - (box 0's extent along r_j).
  const Vec3<T> along1 = s.r.transpose() * s.t;
  const Vec3<T> gap0 = s.t.cwiseAbs() - s.a - s.absR * s.b;
  const Vec3<T> gap1 = along1.cwiseAbs() - s.b - s.absR.transpose() * s.a;
  Eigen::Index i, j;
  const T g0 = gap0.maxCoeff(&i), g1 = gap1.maxCoeff(&j);
  if (!(std::max(g0, g1) > T(0))) return false;
  if (g0 >= g1) {  // box 1's vertex over box 0's face i, n = sign(t_i) e_i
    const T side = s.t[i] < T(0) ? T(-1) : T(1);
    const Vec3<T> v = s.r * supportVertex(s.b, Vec3<T>(-side * s.r.row(i).transpose())) + s.t;
    if (!overFace(v, s.a, int(i))) return false;
    Vec3<T> onFace = v;
    onFace[i] = side * s.a[i];
    local.distance = std::abs(v[i] - onFace[i]);
    local.normal = side * Vec3<T>::Unit(i);
    local.point0 = onFace;
    local.point1 = v;
  } else {  // box 0's vertex over box 1's face j (box 1's frame), n = sign(t.r_j) r_j
    const T side = along1[j] < T(0) ? T(-1) : T(1);
    const Vec3<T> n = side * s.r.col(j);
    const Vec3<T> u = supportVertex(s.a, n);
    const Vec3<T> q = s.r.transpose() * (u - s.t);
    if (!overFace(q, s.b, int(j))) return false;
    Vec3<T> onFace = q;
    onFace[j] = -side * s.b[j];  // box 1's face towards box 0
    local.distance = std::abs(q[j] - onFace[j]);
    local.normal = n;
    local.point0 = u;
    local.point1 = s.r * onFace + s.t;
  }
  return true;
}

// The pair is the candidate nearest to within rounding (`slack`) whose direction proves the largest gap. Nearer by
// rounding is not enough: candidates within d of the distance turn by up to sqrt(2 d / distance), and nearly
// parallel edges have a valley of closest pairs whose distance varies below rounding while their difference vector
// turns (a float pair 0.63 apart chose one 4e-4 off along its edges, its normal 6e-4 off, when every edge pair was
// tried; the exact pair ended at a vertex). The exact closest pair's direction proves the whole distance. (Since the
// edge pairs are pruned to the largest gap's axes no test pose needs this choice any more; it stays as the rule.)
template <class T> void separatedClosest(const BoxPair<T>& s, const AxisSurvey<T>& survey, DistanceResult<T>& local) {
  Candidates<T> c;
  const T size = s.a.norm() + s.b.norm() + s.t.norm();
  const T slack = T(kTouchUlps) * std::numeric_limits<T>::epsilon() * size;
  edgeCandidates(s, survey, slack, c);
  Candidate<T> best{c.least, Vec3<T>::Zero(), Vec3<T>::Zero(), false};
  T bestGap = -std::numeric_limits<T>::infinity();
  Vec3<T> bestNormal = survey.leastAxis;
  const auto certify = [&](const Candidate<T>& e) {
    const T d = std::sqrt(e.distSq);
    if (!(d > T(0))) return;  // touching to rounding: no direction of its own
    const Vec3<T> n = e.inBox1 ? Vec3<T>(s.r * ((e.p1 - e.p0) / d)) : Vec3<T>((e.p1 - e.p0) / d);
    const T gap = gapAlong(s, n);
    if (gap > bestGap) bestGap = gap, best = e, bestNormal = n;
  };
  // An edge pair at the largest gap (to rounding) is a closest pair: that gap is a lower bound of the distance. The
  // vertex candidates are needed only when no edge pair reaches it.
  const T reach = survey.largestGap() + slack;
  if (c.edgeCount > 0 && c.least <= reach * reach) {
    for (int k = 0; k < c.edgeCount; ++k)
      if (c.edges[k].distSq <= reach * reach) certify(c.edges[k]);
  }
  if (!(bestGap > -std::numeric_limits<T>::infinity())) {
    vertexCandidates(s, c);
    const T within = std::sqrt(c.least) + slack;
    best.distSq = c.least;
    for (int k = 0; k < 16; ++k)
      if (c.vertexDistSq[k] <= within * within) certify(c.vertex(k, s));
    for (int k = 0; k < c.edgeCount; ++k)
      if (c.edges[k].distSq <= within * within) certify(c.edges[k]);
  }
  if (!(bestGap > -std::numeric_limits<T>::infinity())) {  // touching to rounding: the largest gap's axis, any pair
    for (int k = 0; k < 16; ++k)
      if (c.vertexDistSq[k] == c.least) best = c.vertex(k, s);
    for (int k = 0; k < c.edgeCount; ++k)
      if (c.edges[k].distSq == c.least) best = c.edges[k];
  }
  local.distance = std::sqrt(best.distSq);
  local.normal = bestNormal;
  local.point0 = best.inBox1 ? Vec3<T>(s.r * best.p0 + s.t) : best.p0;
  local.point1 = best.inBox1 ? Vec3<T>(s.r * best.p1 + s.t) : best.p1;
}

// Answered: `local` holds the closest pair or the depth with witnesses. Overlapping (only without `witnessDepth`):
// nothing written. Unknown: overlapping, no witness found (the rare parallel-face case).
enum class BoxPairAnswer : std::uint8_t { Answered, Overlapping, Unknown };

template <class T>
BoxPairAnswer distanceInRange(const Vec3<T>& h0, const Vec3<T>& h1, const Mat3<T>& r01, const Vec3<T>& t01,
                              bool witnessDepth, DistanceResult<T>& local) {
  const BoxPair<T> pair = boxPair(h0, h1, r01, t01);
  if (faceCertificate(pair, local)) return BoxPairAnswer::Answered;
  const AxisSurvey<T> survey = surveyAxes(pair);
  if (survey.separated()) {
    separatedClosest(pair, survey, local);
    return BoxPairAnswer::Answered;
  }
  if (!witnessDepth) return BoxPairAnswer::Overlapping;
  const T depth = survey.leastOverlap;
  const Vec3<T> n = survey.leastAxis;  // towards box 1
  const Vec3<T> moved = t01 + depth * n;  // box 1 touching box 0
  const T size = h0.norm() + h1.norm() + t01.norm();
  const T tolerance = T(kTouchUlps) * std::numeric_limits<T>::epsilon() * size;
  Touch<T> touch;
  if (!genericTouch(pair, n, moved, tolerance, touch.point)) {
    edgesOfBox0(pair, n, moved, touch);
    edgesOfBox1(pair, n, moved, touch);
    if (!(touch.distSq <= tolerance * tolerance)) return BoxPairAnswer::Unknown;
  }
  local.distance = -depth;
  local.normal = n;
  local.point0 = touch.point;
  local.point1 = touch.point - depth * n;
  return BoxPairAnswer::Answered;
}

// Pairs whose squared lengths would leave T's range (tiny boxes: 1e-160 apart in double, 1e-20 in float) run scaled
// by an even power of two (gjk/pair_scale.h), exactly: the answer is the scaled pair's, scaled back.
template <class T>
BoxPairAnswer distanceScaled(const Vec3<T>& h0, const Vec3<T>& h1, const Mat3<T>& r01, const Vec3<T>& t01,
                             bool witnessDepth, DistanceResult<T>& local) {
  const T length = std::max({h0.cwiseAbs().maxCoeff(), h1.cwiseAbs().maxCoeff(), t01.cwiseAbs().maxCoeff()});
  if (!needsRescale(length)) return distanceInRange(h0, h1, r01, t01, witnessDepth, local);
  const T factor = rescaleFactor(length);
  const BoxPairAnswer answer =
      distanceInRange(Vec3<T>(h0 * factor), Vec3<T>(h1 * factor), r01, Vec3<T>(t01 * factor), witnessDepth, local);
  if (answer != BoxPairAnswer::Answered) return answer;
  local.distance /= factor;
  local.point0 /= factor;
  local.point1 /= factor;
  return answer;
}

}  // namespace

template <class T>
bool distanceBoxBoxLocal(const Vec3<T>& h0, const Vec3<T>& h1, const Mat3<T>& r01, const Vec3<T>& t01,
                         DistanceResult<T>& local) {
  return distanceScaled(h0, h1, r01, t01, true, local) == BoxPairAnswer::Answered;
}

template <class T>
bool separatedBoxBoxLocal(const Vec3<T>& h0, const Vec3<T>& h1, const Mat3<T>& r01, const Vec3<T>& t01,
                          DistanceResult<T>& local) {
  return distanceScaled(h0, h1, r01, t01, false, local) == BoxPairAnswer::Answered;
}

template bool distanceBoxBoxLocal<float>(const Vec3<float>&, const Vec3<float>&, const Mat3<float>&, const Vec3<float>&,
                                         DistanceResult<float>&);
template bool distanceBoxBoxLocal<double>(const Vec3<double>&, const Vec3<double>&, const Mat3<double>&,
                                          const Vec3<double>&, DistanceResult<double>&);
template bool separatedBoxBoxLocal<float>(const Vec3<float>&, const Vec3<float>&, const Mat3<float>&,
                                          const Vec3<float>&, DistanceResult<float>&);
template bool separatedBoxBoxLocal<double>(const Vec3<double>&, const Vec3<double>&, const Mat3<double>&,
                                           const Vec3<double>&, DistanceResult<double>&);

}  // namespace gq::kernels
