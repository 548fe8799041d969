// The contact set of two boxes (gq/contacts.h generateContacts; contact_features.h), one compact path worked in
// box 0's frame (box 1's axes R and centre t there):
//  1. Separating axes over the 15 axes (overlap/box_box_sat.h leastOverlap): the depth and normal of penetrating
//     boxes (the exact minimum, or a face axis within the coincidence tolerance of it) and the face or edge pair
//     that carries them; a separating axis whose gap exceeds the threshold ends the query (an
//     exact cull). Boxes apart within the threshold take the exact signed distance from the caller.
//  2. Reference face: box 1's face most aligned with the normal, or box 0's when better aligned (box 1's wins when it
//     is the separating axis's own face); incident face: the other box's face most opposed to it. When both are
//     within kFaceAlignmentCos of the normal, the incident rectangle is clipped to the reference one
//     (Sutherland-Hodgman on 4 sides, clipToRectangle); no point is deeper than the exact separation.
//  3. The exact point (the separating axis's witness, or the distance's) joins unless a clipped point carries the
//     exact separation; the points are reduced to maxContacts (reduceContactPoints).
// The same rules as the other polytope pairs of contact_set.cpp, in ~10 KB of code per scalar type, small enough to
// stay in the instruction cache across a pile's pair loop (docs/bullet.md gives the measured misses).
#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "contacts/contact_features.h"
#include "overlap/box_box_sat.h"

namespace gq::detail {
namespace {

// At most 8 clipped corners and the exact point.
constexpr int kMaxBoxCandidates = 9;

template <class T> struct BoxFrame {
  BoxPair<T> s;  // box 1 in box 0's frame
  Mat3<T> r0;    // box 0's rotation: world = r0 x + p0
  Vec3<T> p0;
  T ma, mb, threshold, tolerance;
  int maxContacts;
};

template <class T>
BoxFrame<T> boxFrame(const BoxGeometry<T>& box0, const Transform<T>& pose0, const BoxGeometry<T>& box1,
                     const Transform<T>& pose1, const BoxContactSettings<T>& settings) {
  BoxFrame<T> f{boxPair(box0, pose0, box1, pose1), pose0.q.toRotationMatrix(), pose0.p, settings.margin0,
                settings.margin1, settings.threshold, settings.tolerance, settings.maxContacts};
  return f;
}

// Points gathered before the reduction: world positions on box 1, separations along `normal` (world).
template <class T> struct BoxCandidates {
  Vec3<T> points[kMaxBoxCandidates];
  T separations[kMaxBoxCandidates];
  int count = 0;
  Vec3<T> normal;
};

template <class T> T signOf(T x) { return x >= T(0) ? T(1) : T(-1); }

// A box face (box 0's frame): centre, in-plane unit axes u, w with half extents hu, hw, outward unit normal.
template <class T> struct BoxFace {
  Vec3<T> centre, u, w, normal;
  T hu, hw;
};

// The face of the box (centre c, axes the columns of m, half extents h) with outward normal sign * m.col(k).
template <class T> BoxFace<T> boxFace(const Vec3<T>& c, const Mat3<T>& m, const Vec3<T>& h, int k, T sign) {
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  return BoxFace<T>{c + m.col(k) * (sign * h[k]), m.col(i), m.col(j), m.col(k) * sign, h[i], h[j]};
}

// The face of that box whose outward normal is the most aligned with unit `dir`; `alignment` gets the cosine.
template <class T> BoxFace<T> alignedFace(const Vec3<T>& c, const Mat3<T>& m, const Vec3<T>& h, const Vec3<T>& dir,
                                          T& alignment) {
  const Vec3<T> local = m.transpose() * dir;
  int k = 0;
  local.cwiseAbs().maxCoeff(&k);
  alignment = std::abs(local[k]);
  return boxFace(c, m, h, k, signOf(local[k]));
}

// Step 2: the incident face clipped to the reference face along `n` (unit, box 0's frame, from box 1 towards box 0),
// points with separation <= threshold appended to `out` (world). Returns the smallest separation added (+max: none).
template <class T> T clippedBoxContacts(const BoxFrame<T>& f, const Vec3<T>& n, T exact, BoxCandidates<T>& out) {
  constexpr T slack = std::is_same_v<T, float> ? T(1e-5) : T(1e-9);
  T align0, align1;
  const BoxFace<T> face0 = alignedFace(Vec3<T>::Zero().eval(), Mat3<T>::Identity().eval(), f.s.a, Vec3<T>(-n), align0);
  const BoxFace<T> face1 = alignedFace(f.s.t, f.s.r, f.s.b, n, align1);
  T deepest = std::numeric_limits<T>::max();
  if (align0 < T(kFaceAlignmentCos) || align1 < T(kFaceAlignmentCos)) return deepest;
  const bool referenceIs1 = align1 >= T(1) - slack || !(align0 > align1);
  const BoxFace<T>& ref = referenceIs1 ? face1 : face0;
  const BoxFace<T>& inc = referenceIs1 ? face0 : face1;
  FacePoint<T> bufferA[8], bufferB[8];
  const Vec3<T> d = inc.centre - ref.centre;
  const Vec3<T> x(d.dot(ref.u), d.dot(ref.w), d.dot(ref.normal));
  const Vec3<T> du(inc.u.dot(ref.u) * inc.hu, inc.u.dot(ref.w) * inc.hu, inc.u.dot(ref.normal) * inc.hu);
  const Vec3<T> dw(inc.w.dot(ref.u) * inc.hw, inc.w.dot(ref.w) * inc.hw, inc.w.dot(ref.normal) * inc.hw);
  const T cu[4] = {-1, 1, 1, -1}, cw[4] = {-1, -1, 1, 1};
  for (int c = 0; c < 4; ++c)
    for (int k = 0; k < 3; ++k) bufferA[c].c[k] = x[k] + du[k] * cu[c] + dw[k] * cw[c];
  FacePoint<T>* in = nullptr;
  const int count = clipToRectangle(bufferA, bufferB, 4, 8, ref.hu, ref.hw, in);
  const Vec3<T> n1 = referenceIs1 ? ref.normal : Vec3<T>(-ref.normal);  // from box 1 towards box 0
  for (int i = 0; i < count; ++i) {
    const T h = in[i].c[2];
    const T s = std::max(h - f.ma - f.mb, exact);
    if (s > f.threshold) continue;
    const Vec3<T> p = ref.centre + ref.u * in[i].c[0] + ref.w * in[i].c[1];
    // On box 1's (rounded) surface: box 1's face plane + mb, or box 1's clipped point + mb along n1.
    const Vec3<T> q = referenceIs1 ? Vec3<T>(p + n1 * (h - f.ma - s)) : Vec3<T>(p + ref.normal * h + n1 * f.mb);
    out.points[out.count] = f.r0 * q + f.p0;
    out.separations[out.count++] = s;
    deepest = std::min(deepest, s);
  }
  if (deepest < std::numeric_limits<T>::max()) out.normal = f.r0 * n1;  // the set's normal is the face's
  return deepest;
}

// The witness on box 1 (box 0's frame) of a penetrating pair's separating axis: box 1's deepest vertex under box 0's
// face, box 0's deepest vertex brought back to box 1's face, or the closest points of the two edges.
template <class T> [[gnu::cold, gnu::noinline]] Vec3<T> satWitness(const BoxPair<T>& s, const LeastOverlap<T>& sat) {
  const Vec3<T>& u = sat.towardsBox1;
  const Vec3<T> l = s.r.transpose() * u;
  Vec3<T> corner0, corner1 = s.t;  // box 0's vertex farthest along u, box 1's farthest against it
  for (int k = 0; k < 3; ++k) {
    corner0[k] = signOf(u[k]) * s.a[k];
    corner1 -= s.r.col(k) * (signOf(l[k]) * s.b[k]);
  }
  if (sat.code < 3) return corner1;
  if (sat.code < 6) return corner0 - u * sat.depth;
  const int i = (sat.code - 6) / 3, j = (sat.code - 6) % 3;
  // Edges: box 0's along e_i through corner0 with x_i = 0, box 1's along r_j through corner1 with its r_j part removed.
  corner0[i] = T(0);
  const Vec3<T> dir = s.r.col(j);
  const Vec3<T> q = corner1 + dir * (signOf(l[j]) * s.b[j]);
  const Vec3<T> w = corner0 - q;
  // Closest points of the edges corner0 + x e_i (|x| <= a_i) and q + y dir (|y| <= b_j): x of the lines' closest
  // points, clamped, then box 1's point closest to it.
  const T c = dir[i], denom = T(1) - c * c;
  const T x = denom > T(0) ? std::clamp((c * dir.dot(w) - w[i]) / denom, -s.a[i], s.a[i]) : T(0);
  const T y = std::clamp(dir.dot(w) + x * c, -s.b[j], s.b[j]);
  return q + dir * y;
}

// Step 3: the candidates reduced to maxContacts, written to `out`.
template <class T> void writeSet(const BoxFrame<T>& f, const BoxCandidates<T>& c, ContactSet<T>& out) {
  int keep[kMaxBoxCandidates];
  const int kept = reduceContactPoints(c.points, c.separations, c.count, c.normal, f.maxContacts, keep);
  out.normal = kept > 0 ? c.normal : Vec3<T>::Zero();
  out.count = std::uint32_t(kept);
  for (int k = 0; k < kept; ++k) out.points[k] = {c.points[keep[k]], c.separations[keep[k]]};
}

}  // namespace

template <class T>
bool boxContactsPenetrating(const BoxGeometry<T>& box0, const Transform<T>& pose0, const BoxGeometry<T>& box1,
                            const Transform<T>& pose1, const BoxContactSettings<T>& settings, ContactSet<T>& out) {
  const BoxFrame<T> f = boxFrame(box0, pose0, box1, pose1, settings);
  // An edge axis must beat the best face axis by the coincidence tolerance: an edge parallel to the other box's face
  // has an edge axis along that face's normal with the same depth, and rounding must not pick it (its witness would
  // be the far edge's closest point). The set's depth can so exceed the exact minimum by at most that tolerance.
  const LeastOverlap<T> sat = leastOverlap(f.s, f.tolerance);
  if (sat.separated) {
    if (sat.gap - f.ma - f.mb <= f.threshold) return false;
    out.normal = Vec3<T>::Zero();
    out.count = 0;
    return true;
  }
  const T exact = -sat.depth - f.ma - f.mb;
  const Vec3<T> n = -sat.towardsBox1;
  BoxCandidates<T> c;
  c.normal = f.r0 * n;
  if (clippedBoxContacts(f, n, exact, c) > exact + f.tolerance) {
    const Vec3<T> witness = satWitness(f.s, sat) + n * f.mb;
    c.points[c.count] = f.r0 * witness + f.p0;
    c.separations[c.count++] = exact;
  }
  writeSet(f, c, out);
  return true;
}

template <class T>
void boxContactsApart(const BoxGeometry<T>& box0, const Transform<T>& pose0, const BoxGeometry<T>& box1,
                      const Transform<T>& pose1, const BoxContactSettings<T>& settings, const DistanceResult<T>& d,
                      ContactSet<T>& out) {
  const BoxFrame<T> f = boxFrame(box0, pose0, box1, pose1, settings);
  const T exact = d.distance - f.ma - f.mb;
  const Vec3<T> normal = -d.normal;  // d.normal runs from box 0 to box 1
  BoxCandidates<T> c;
  if (exact <= f.threshold && isFinite(normal) && normal.squaredNorm() >= T(0.5)) {
    c.normal = normal;
    if (clippedBoxContacts(f, Vec3<T>(f.r0.transpose() * normal), exact, c) > exact + f.tolerance) {
      c.points[c.count] = d.point1 + normal * f.mb;
      c.separations[c.count++] = exact;
    }
  }
  writeSet(f, c, out);
}

#define GQ_INSTANTIATE(T)                                                                                          \
  template bool boxContactsPenetrating<T>(const BoxGeometry<T>&, const Transform<T>&, const BoxGeometry<T>&,      \
                                          const Transform<T>&, const BoxContactSettings<T>&, ContactSet<T>&);     \
  template void boxContactsApart<T>(const BoxGeometry<T>&, const Transform<T>&, const BoxGeometry<T>&,            \
                                    const Transform<T>&, const BoxContactSettings<T>&, const DistanceResult<T>&, \
                                    ContactSet<T>&);
GQ_INSTANTIATE(float)
GQ_INSTANTIATE(double)
#undef GQ_INSTANTIATE

}  // namespace gq::detail
