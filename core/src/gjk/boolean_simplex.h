#pragma once
// Direction-only simplex step for the boolean GJK (Muratori's formulation): instead of the closest point of the
// simplex to the origin (signed volumes with divisions, simplex.cpp), only the Voronoi region of the newest point's
// features that holds the origin is found, by sign tests, and the next search direction is the perpendicular from
// that feature towards the origin. Enough to find a separating axis or an enclosing tetrahedron; it gives no
// distance, so a run that can conclude neither (shapes within their margins, degenerate simplices) falls back to
// the full GJK.
//
// The newest point is always the last one (points[size - 1]).
#include "gjk/gjk.h"

namespace gq::detail {

// Steps of the direction-only loop before gjkOverlap hands an undecided pair to the full GJK.
inline constexpr std::uint32_t kGjkBooleanFastIterations = 32;

template <class T> struct BooleanStep {
  Vec3<T> dir = Vec3<T>::Zero();  // next search direction (towards the origin); zero: undecided, fall back
  bool enclosed = false;          // the tetrahedron contains the origin strictly
};

namespace boolean_simplex {

template <class T> T triple(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) { return a.dot(b.cross(c)); }

// Segment (b, a), a newest: the origin projects inside it, or a alone is nearest.
template <class T> BooleanStep<T> segment(GjkSimplex<T>& s, const SupportPoint<T>& b, const SupportPoint<T>& a) {
  const Vec3<T> ab = b.w - a.w, ao = -a.w;
  BooleanStep<T> r;
  if (ab.dot(ao) > T(0)) {
    s.points[0] = b;
    s.points[1] = a;
    s.size = 2;
    r.dir = ab.cross(ao).cross(ab);
  } else {
    s.points[0] = a;
    s.size = 1;
    r.dir = ao;
  }
  return r;
}

// Triangle (c, b, a), a newest.
template <class T>
BooleanStep<T> triangle(GjkSimplex<T>& s, const SupportPoint<T>& c, const SupportPoint<T>& b, const SupportPoint<T>& a) {
  const Vec3<T> ab = b.w - a.w, ac = c.w - a.w, ao = -a.w;
  const Vec3<T> n = ab.cross(ac);
  if (n.cross(ac).dot(ao) > T(0)) {  // beyond edge a-c
    if (ac.dot(ao) > T(0)) {
      BooleanStep<T> r;
      s.points[0] = c;
      s.points[1] = a;
      s.size = 2;
      r.dir = ac.cross(ao).cross(ac);
      return r;
    }
    return segment(s, b, a);
  }
  if (ab.cross(n).dot(ao) > T(0)) return segment(s, b, a);  // beyond edge a-b
  BooleanStep<T> r;
  s.points[0] = c;
  s.points[1] = b;
  s.points[2] = a;
  s.size = 3;
  r.dir = n.dot(ao) > T(0) ? n : Vec3<T>(-n);
  return r;
}

}  // namespace boolean_simplex

// One step on s (2 to 4 points, newest last): reduces s and returns the next direction, or `enclosed`.
template <class T> BooleanStep<T> booleanStep(GjkSimplex<T>& s) {
  using namespace boolean_simplex;
  // The sub-cases read their points through references into s while compacting it: every write goes to an index
  // no larger than that of any point still to be read (checked case by case), so nothing is read after overwritten.
  const std::array<SupportPoint<T>, 4>& p = s.points;
  if (s.size == 2) return segment(s, p[0], p[1]);
  if (s.size == 3) return triangle(s, p[0], p[1], p[2]);
  // Tetrahedron (d, c, b, a), a = p[3] newest: barycentric signed volumes of the origin (as in simplex.cpp).
  const Vec3<T>&d = p[0].w, &c = p[1].w, &b = p[2].w, &a = p[3].w;
  const T det = triple<T>(c - d, b - d, a - d);
  const T scale = std::max({(c - d).squaredNorm(), (b - d).squaredNorm(), (a - d).squaredNorm()});
  // Flat tetrahedron: no sign is trustworthy.
  if (!(std::abs(det) > T(16) * std::numeric_limits<T>::epsilon() * scale * std::sqrt(scale))) return BooleanStep<T>{};
  const T ld = triple<T>(c, b, a) / det, lc = triple<T>(d, a, b) / det, lb = triple<T>(d, c, a) / det;
  const T la = T(1) - ld - lc - lb;
  if (ld > T(0) && lc > T(0) && lb > T(0) && la > T(0)) {
    BooleanStep<T> r;
    r.enclosed = true;
    return r;
  }
  // Outside the face opposite a non-positive weight; faces through a only (the old face d-c-b had the origin on
  // a's side when a was found, so a weight <= 0 there is rounding: undecided).
  if (!(ld > T(0))) return triangle(s, p[1], p[2], p[3]);  // face c-b-a
  if (!(lc > T(0))) return triangle(s, p[0], p[2], p[3]);  // face d-b-a
  if (!(lb > T(0))) return triangle(s, p[0], p[1], p[3]);  // face d-c-a
  return BooleanStep<T>{};
}

}  // namespace gq::detail
