// Exact distances between convex hulls of point sets (long double): brute force over feature pairs for the
// separation, SAT over face normals and edge-pair cross products for overlap and penetration depth.
#include <algorithm>
#include <cmath>
#include <limits>

#include "exact.h"

namespace gq::suites {
namespace {

constexpr Ld kInf = std::numeric_limits<Ld>::infinity();
// Below this fraction of the extent a hull or Minkowski difference counts as flat (no interior): its depth is 0.
constexpr Ld kFlatFraction = 1e-14L;
// A cross product shorter than this fraction of the product of its factors' lengths gives no axis.
constexpr Ld kAxisFraction = 1e-12L;

Ld pointSegmentDistance(const V3& p, const V3& a, const V3& b) {
  const V3 ab = b - a;
  const Ld len2 = ab.squaredNorm();
  const Ld t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, Ld(0), Ld(1)) : Ld(0);
  return (a + t * ab - p).norm();
}

// Largest distance of the difference vectors {a_i - a_0} U {b_j - b_0} from the best plane through them,
// relative to their extent: how far the Minkowski difference is from being flat.
bool differenceIsSolid(const std::vector<V3>& a, const std::vector<V3>& b) {
  std::vector<V3> d;
  for (const V3& p : a) d.push_back(p - a[0]);
  for (const V3& p : b) d.push_back(p - b[0]);
  V3 e1 = V3::Zero();
  for (const V3& v : d) if (v.squaredNorm() > e1.squaredNorm()) e1 = v;
  const Ld extent = e1.norm();
  if (extent == 0) return false;
  e1 /= extent;
  V3 e2 = V3::Zero();
  for (const V3& v : d) {
    const V3 perp = v - v.dot(e1) * e1;
    if (perp.squaredNorm() > e2.squaredNorm()) e2 = perp;
  }
  if (e2.norm() <= kFlatFraction * extent) return false;
  const V3 n = e1.cross(e2).normalized();
  Ld thickness = 0;
  for (const V3& v : d) thickness = std::max(thickness, std::abs(n.dot(v)));
  return thickness > kFlatFraction * extent;
}

// Gap between the projections of the two sets on unit axis n (negative: overlap along n).
Ld projectionGap(const std::vector<V3>& a, const std::vector<V3>& b, const V3& n) {
  Ld minA = kInf, maxA = -kInf, minB = kInf, maxB = -kInf;
  for (const V3& p : a) { const Ld s = n.dot(p); minA = std::min(minA, s); maxA = std::max(maxA, s); }
  for (const V3& p : b) { const Ld s = n.dot(p); minB = std::min(minB, s); maxB = std::max(maxB, s); }
  return std::max(minB - maxA, minA - maxB);
}

// Largest gap over all SAT axes: > 0 separates; otherwise minus the penetration depth.
Ld largestSatGap(const std::vector<V3>& a, const std::vector<V3>& b) {
  std::vector<V3> axes;
  addTriangleNormals(a, axes);
  addTriangleNormals(b, axes);
  addEdgePairAxes(a, b, axes);
  Ld best = -kInf;
  for (const V3& n : axes) best = std::max(best, projectionGap(a, b, n));
  return best;
}

// Distance from point p to the hull of `pts` restricted to its points, segments and triangles.
Ld pointToFeatures(const V3& p, const std::vector<V3>& pts) {
  Ld best = kInf;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    best = std::min(best, (p - pts[i]).norm());
    for (std::size_t j = i + 1; j < pts.size(); ++j) {
      best = std::min(best, pointSegmentDistance(p, pts[i], pts[j]));
      for (std::size_t k = j + 1; k < pts.size(); ++k)
        best = std::min(best, pointTriangleDistance(p, pts[i], pts[j], pts[k]));
    }
  }
  return best;
}

}  // namespace

void addTriangleNormals(const std::vector<V3>& pts, std::vector<V3>& axes) {
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (std::size_t j = i + 1; j < pts.size(); ++j)
      for (std::size_t k = j + 1; k < pts.size(); ++k) {
        const V3 e0 = pts[j] - pts[i], e1 = pts[k] - pts[i];
        const V3 n = e0.cross(e1);
        if (n.norm() > kAxisFraction * e0.norm() * e1.norm()) axes.push_back(n.normalized());
      }
}

void addEdgePairAxes(const std::vector<V3>& a, const std::vector<V3>& b, std::vector<V3>& axes) {
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = i + 1; j < a.size(); ++j) {
      const V3 ea = a[j] - a[i];
      for (std::size_t k = 0; k < b.size(); ++k)
        for (std::size_t l = k + 1; l < b.size(); ++l) {
          const V3 eb = b[l] - b[k];
          const V3 n = ea.cross(eb);
          if (n.norm() > kAxisFraction * ea.norm() * eb.norm()) axes.push_back(n.normalized());
        }
    }
}

Ld pointTriangleDistance(const V3& p, const V3& a, const V3& b, const V3& c) {
  const V3 n = (b - a).cross(c - a);
  const Ld edges = std::max({(b - a).squaredNorm(), (c - a).squaredNorm(), (c - b).squaredNorm()});
  const Ld nn = n.squaredNorm();
  if (nn > kAxisFraction * kAxisFraction * edges * edges) {
    // Inside the prism over the triangle: the distance is the height above its plane.
    const bool inside = (b - a).cross(p - a).dot(n) >= 0 && (c - b).cross(p - b).dot(n) >= 0 &&
                        (a - c).cross(p - c).dot(n) >= 0;
    if (inside) return std::abs(n.dot(p - a)) / std::sqrt(nn);
  }
  return std::min({pointSegmentDistance(p, a, b), pointSegmentDistance(p, b, c), pointSegmentDistance(p, c, a)});
}

Ld segmentSegmentDistance(const V3& p0, const V3& p1, const V3& q0, const V3& q1) {
  // Closest parameters of the two supporting lines, clamped (Ericson, Real-Time Collision Detection 5.1.9);
  // the endpoint distances cover the parallel and degenerate cases.
  const V3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const Ld a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  Ld best = std::min({pointSegmentDistance(p0, q0, q1), pointSegmentDistance(p1, q0, q1),
                      pointSegmentDistance(q0, p0, p1), pointSegmentDistance(q1, p0, p1)});
  if (a == 0 || e == 0) return best;
  const Ld b = d1.dot(d2), c = d1.dot(r), denom = a * e - b * b;
  if (denom <= kAxisFraction * kAxisFraction * a * e) return best;
  const Ld s = (b * f - c * e) / denom, t = (a * f - b * c) / denom;
  if (s >= 0 && s <= 1 && t >= 0 && t <= 1) best = std::min(best, ((p0 + s * d1) - (q0 + t * d2)).norm());
  return best;
}

Ld hullDistance(const std::vector<V3>& a, const std::vector<V3>& b) {
  Ld best = kInf;
  for (const V3& p : a) best = std::min(best, pointToFeatures(p, b));
  for (const V3& p : b) best = std::min(best, pointToFeatures(p, a));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = i + 1; j < a.size(); ++j)
      for (std::size_t k = 0; k < b.size(); ++k)
        for (std::size_t l = k + 1; l < b.size(); ++l)
          best = std::min(best, segmentSegmentDistance(a[i], a[j], b[k], b[l]));
  return best;
}

Ld hullSignedDistance(const std::vector<V3>& a, const std::vector<V3>& b) {
  if (!differenceIsSolid(a, b)) return hullDistance(a, b);  // a flat difference has depth 0 when touching
  const Ld gap = largestSatGap(a, b);
  return gap > 0 ? hullDistance(a, b) : gap;
}

Ld signedDistance(const Core& a, const Core& b) {
  return hullSignedDistance(a.points, b.points) - a.radius - b.radius;
}

Ld signedDistance(const Core& a, const HalfSpace& plane) {
  Ld lowest = kInf;
  for (const V3& p : a.points) lowest = std::min(lowest, plane.normal.dot(p - plane.origin));
  return lowest - a.radius;
}

Ld pointMeshDistance(const V3& p, const TriangleSoup& mesh) {
  Ld best = kInf;
  for (const auto& t : mesh.triangles)
    best = std::min(best, pointTriangleDistance(p, mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]));
  return best;
}

}  // namespace gq::suites
