#pragma once
// Independent long-double reference for sweep tests: every swept/target shape is a "core" (point, segment or
// polytope) plus a margin (radius). The exact distance of two cores is 0 when one contains a vertex of the other or
// their boundaries meet, else the minimum over vertex-vertex, vertex-edge, vertex-triangle and edge-edge pairs.
// Moving core A by t*dir, d(t) = coreDistance - margins is convex in t, so the exact time of impact is the first
// root, found by bisection.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <vector>

#include "gq/cooking.h"
#include "gq/geometry.h"
#include "gq/transform.h"

namespace sweeptest {

using L = long double;
using VL = Eigen::Matrix<L, 3, 1>;

template <class T> VL toL(const gq::Vec3<T>& v) { return v.template cast<L>(); }

struct Core {
  std::vector<VL> v;
  std::vector<std::array<int, 2>> edges;
  std::vector<std::array<int, 3>> tris;  // outward winding (polytopes only)
  L margin = 0;
  Core moved(const VL& d) const {
    Core c = *this;
    for (auto& p : c.v) p += d;
    return c;
  }
};

template <class T> VL applyL(const gq::Transform<T>& pose, const VL& x) {
  const Eigen::Quaternion<L> q = pose.q.template cast<L>().normalized();
  return q * x + toL(pose.p);
}

inline L pointSegment(const VL& x, const VL& a, const VL& b) {
  const VL d = b - a;
  const L dd = d.squaredNorm();
  const L t = dd > 0 ? std::clamp((x - a).dot(d) / dd, L(0), L(1)) : L(0);
  return (a + t * d - x).norm();
}

// Barycentric region test on the projection, else the nearest edge.
inline L pointTriangle(const VL& x, const VL& a, const VL& b, const VL& c) {
  const VL n = (b - a).cross(c - a);
  const L nn = n.squaredNorm();
  const VL p = x - n * (n.dot(x - a) / nn);
  if (n.dot((b - p).cross(c - p)) >= 0 && n.dot((c - p).cross(a - p)) >= 0 && n.dot((a - p).cross(b - p)) >= 0)
    return std::abs(n.dot(x - a)) / std::sqrt(nn);
  return std::min({pointSegment(x, a, b), pointSegment(x, b, c), pointSegment(x, c, a)});
}

inline L segmentSegment(const VL& p0, const VL& q0, const VL& p1, const VL& q1) {
  const VL d0 = q0 - p0, d1 = q1 - p1, r = p0 - p1;
  const L a = d0.dot(d0), b = d0.dot(d1), e = d1.dot(d1), c = d0.dot(r), f = d1.dot(r);
  const L det = a * e - b * b;
  if (det > L(1e-15) * a * e) {
    const L s = (b * f - c * e) / det, t = (a * f - b * c) / det;
    if (s >= 0 && s <= 1 && t >= 0 && t <= 1) return (p0 + s * d0 - p1 - t * d1).norm();
  }
  return std::min({pointSegment(p0, p1, q1), pointSegment(q0, p1, q1), pointSegment(p1, p0, q0), pointSegment(q1, p0, q0)});
}

// x inside (or on) polytope P: behind every face plane.
inline bool insidePolytope(const VL& x, const Core& P) {
  if (P.tris.size() < 4) return false;  // a triangle (or less) has no interior
  for (const auto& t : P.tris) {
    const VL n = (P.v[t[1]] - P.v[t[0]]).cross(P.v[t[2]] - P.v[t[0]]);
    if (n.dot(x - P.v[t[0]]) > 0) return false;
  }
  return true;
}

// Segment crossing a triangle (boundary contact of a segment core with a polytope or triangle).
inline bool segmentCrossesTriangle(const VL& p, const VL& q, const VL& a, const VL& b, const VL& c) {
  const VL n = (b - a).cross(c - a);
  const L dp = n.dot(p - a), dq = n.dot(q - a);
  if ((dp > 0 && dq > 0) || (dp < 0 && dq < 0) || dp == dq) return false;
  const VL x = p + (q - p) * (dp / (dp - dq));
  return n.dot((b - x).cross(c - x)) >= 0 && n.dot((c - x).cross(a - x)) >= 0 && n.dot((a - x).cross(b - x)) >= 0;
}

inline L coreDistance(const Core& A, const Core& B) {
  for (const auto& x : A.v) if (insidePolytope(x, B)) return 0;
  for (const auto& x : B.v) if (insidePolytope(x, A)) return 0;
  for (const auto& e : A.edges)
    for (const auto& t : B.tris) if (segmentCrossesTriangle(A.v[e[0]], A.v[e[1]], B.v[t[0]], B.v[t[1]], B.v[t[2]])) return 0;
  for (const auto& e : B.edges)
    for (const auto& t : A.tris) if (segmentCrossesTriangle(B.v[e[0]], B.v[e[1]], A.v[t[0]], A.v[t[1]], A.v[t[2]])) return 0;
  L best = std::numeric_limits<L>::infinity();
  for (const auto& a : A.v) for (const auto& b : B.v) best = std::min(best, (a - b).norm());
  for (const auto& a : A.v) for (const auto& e : B.edges) best = std::min(best, pointSegment(a, B.v[e[0]], B.v[e[1]]));
  for (const auto& b : B.v) for (const auto& e : A.edges) best = std::min(best, pointSegment(b, A.v[e[0]], A.v[e[1]]));
  for (const auto& a : A.v) for (const auto& t : B.tris) best = std::min(best, pointTriangle(a, B.v[t[0]], B.v[t[1]], B.v[t[2]]));
  for (const auto& b : B.v) for (const auto& t : A.tris) best = std::min(best, pointTriangle(b, A.v[t[0]], A.v[t[1]], A.v[t[2]]));
  for (const auto& ea : A.edges)
    for (const auto& eb : B.edges) best = std::min(best, segmentSegment(A.v[ea[0]], A.v[ea[1]], B.v[eb[0]], B.v[eb[1]]));
  return best;
}

// Signed distance of the full shapes (margins subtracted); <= 0 means touching or overlapping.
inline L shapeDistance(const Core& A, const Core& B) { return coreDistance(A, B) - A.margin - B.margin; }

inline void edgesFromTriangles(Core& c) {
  std::set<std::pair<int, int>> e;
  for (const auto& t : c.tris)
    for (int k = 0; k < 3; ++k) e.insert(std::minmax(t[k], t[(k + 1) % 3]));
  for (const auto& p : e) c.edges.push_back({p.first, p.second});
}

// Outward triangles of the convex hull of points in general position (brute force; coplanar points skipped).
inline std::vector<std::array<int, 3>> hullTriangles(const std::vector<VL>& pts) {
  std::vector<std::array<int, 3>> tris;
  const int n = int(pts.size());
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      for (int k = j + 1; k < n; ++k) {
        const VL nrm = (pts[j] - pts[i]).cross(pts[k] - pts[i]);
        int above = 0, below = 0;
        for (int m = 0; m < n; ++m) {
          if (m == i || m == j || m == k) continue;
          const L s = nrm.dot(pts[m] - pts[i]);
          above += s > 0;
          below += s < 0;
        }
        if (above && below) continue;
        tris.push_back(above ? std::array<int, 3>{i, k, j} : std::array<int, 3>{i, j, k});
      }
  return tris;
}

template <class T> Core coreOf(const gq::Geometry<T>& g, const gq::Transform<T>& pose) {
  Core c;
  std::vector<VL> local;
  if (const auto* s = g.template getIf<gq::SphereGeometry<T>>()) {
    local = {VL::Zero()};
    c.margin = s->radius;
  } else if (const auto* s = g.template getIf<gq::CapsuleGeometry<T>>()) {
    local = {VL(-L(s->halfHeight), 0, 0), VL(L(s->halfHeight), 0, 0)};
    c.edges = {{0, 1}};
    c.margin = s->radius;
  } else if (const auto* b = g.template getIf<gq::BoxGeometry<T>>()) {
    for (int i = 0; i < 8; ++i)
      local.push_back(VL((i & 1) ? L(b->halfExtents.x()) : -L(b->halfExtents.x()),
                         (i & 2) ? L(b->halfExtents.y()) : -L(b->halfExtents.y()),
                         (i & 4) ? L(b->halfExtents.z()) : -L(b->halfExtents.z())));
  } else if (const auto* h = g.template getIf<gq::ConvexMeshGeometry<T>>()) {
    for (const auto& v : h->mesh->vertices) local.push_back(toL(v));  // unit scale in these tests
  }
  for (const auto& p : local) c.v.push_back(applyL(pose, p));
  if (g.template getIf<gq::BoxGeometry<T>>()) {
    // Box faces given explicitly (their four corners are coplanar: a brute-force hull would drop faces on rounding).
    for (int axis = 0; axis < 3; ++axis)
      for (int side = 0; side < 2; ++side) {
        const int b = 1 << ((axis + 1) % 3), e = 1 << ((axis + 2) % 3), base = side << axis;
        const int q[4] = {base, base | b, base | b | e, base | e};
        for (const std::array<int, 3> t : {std::array<int, 3>{q[0], q[1], q[2]}, std::array<int, 3>{q[0], q[2], q[3]}}) {
          const VL n = (c.v[t[1]] - c.v[t[0]]).cross(c.v[t[2]] - c.v[t[0]]);
          const bool outward = n.dot(c.v[t[0]] - applyL(pose, VL::Zero())) > 0;
          c.tris.push_back(outward ? t : std::array<int, 3>{t[0], t[2], t[1]});
        }
      }
    edgesFromTriangles(c);
  } else if (c.v.size() > 3) {
    c.tris = hullTriangles(c.v);
    edgesFromTriangles(c);
  }
  return c;
}

inline Core triangleCore(const VL& a, const VL& b, const VL& c) {
  Core t;
  t.v = {a, b, c};
  t.edges = {{0, 1}, {1, 2}, {2, 0}};
  t.tris = {{0, 1, 2}};
  return t;
}

// Smallest value of the convex d(t) = shapeDistance(A + t dir, B) on [lo, hi] by golden-section search; stops early
// once a value <= 0 is seen (the shapes meet). Returns the smallest value found and its parameter.
inline std::pair<L, L> minimumAlong(const Core& A, const Core& B, const VL& dir, L lo, L hi, int iterations) {
  auto d = [&](L t) { return shapeDistance(A.moved(t * dir), B); };
  const L g = (std::sqrt(L(5)) - 1) / 2;
  L a = lo, b = hi, x1 = b - g * (b - a), x2 = a + g * (b - a), f1 = d(x1), f2 = d(x2);
  for (int it = 0; it < iterations && f1 > 0 && f2 > 0; ++it) {
    if (f1 < f2) { b = x2; x2 = x1; f2 = f1; x1 = b - g * (b - a); f1 = d(x1); }
    else { a = x1; x1 = x2; f1 = f2; x2 = a + g * (b - a); f2 = d(x2); }
  }
  return f1 < f2 ? std::pair<L, L>{f1, x1} : std::pair<L, L>{f2, x2};
}

// Exact time of impact of A moving along dir against B in [0, maxDist]: the first root of the convex d(t), by
// bisection to `resolution`; returns 0 for an initial overlap and -1 on a miss.
inline L exactToi(const Core& A, const Core& B, const VL& dir, L maxDist, L resolution) {
  auto d = [&](L t) { return shapeDistance(A.moved(t * dir), B); };
  if (d(0) <= 0) return 0;
  L hi = maxDist;
  if (d(maxDist) > 0) {
    const auto [fmin, tmin] = minimumAlong(A, B, dir, L(0), maxDist, 60);
    if (fmin > 0) return -1;
    hi = tmin;
  }
  L lo = 0;
  while (hi - lo > resolution) {
    const L mid = (lo + hi) / 2;
    (d(mid) > 0 ? lo : hi) = mid;
  }
  return hi;
}

}  // namespace sweeptest
