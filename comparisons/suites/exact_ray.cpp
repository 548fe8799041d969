// Exact ray hits (long double): quadratic roots for spheres and capsules, slab clipping against every face plane
// of a polytope, and brute force over all triangles of a mesh.
#include <algorithm>
#include <cmath>
#include <limits>

#include "exact.h"

namespace gq::suites {
namespace {

constexpr Ld kInf = std::numeric_limits<Ld>::infinity();
// A point within this fraction of the hull extent of a candidate plane still counts as on its inner side.
constexpr Ld kPlaneFraction = 1e-15L;

// Smallest t >= 0 with |o + t d - c| = r, for an origin outside the sphere (|d| = 1).
std::optional<Ld> raySphereEntry(const V3& o, const V3& d, const V3& c, Ld r) {
  const V3 m = o - c;
  const Ld b = m.dot(d), cc = m.squaredNorm() - r * r;
  const Ld disc = b * b - cc;
  if (disc < 0) return std::nullopt;
  const Ld t = -b - std::sqrt(disc);
  if (t < 0) return std::nullopt;
  return t;
}

// Entry of the ray into the infinite cylinder of radius r around segment ab, kept if its foot lies on the segment.
std::optional<Ld> rayCylinderEntry(const V3& o, const V3& d, const V3& a, const V3& b, Ld r) {
  const V3 axis = (b - a).normalized();
  const V3 m = o - a;
  const V3 dp = d - d.dot(axis) * axis, mp = m - m.dot(axis) * axis;
  const Ld qa = dp.squaredNorm(), qb = mp.dot(dp), qc = mp.squaredNorm() - r * r;
  if (qa == 0) return std::nullopt;  // parallel to the axis: the caps decide
  const Ld disc = qb * qb - qa * qc;
  if (disc < 0) return std::nullopt;
  const Ld t = (-qb - std::sqrt(disc)) / qa;
  if (t < 0) return std::nullopt;
  const Ld s = (m + t * d).dot(axis);
  if (s < 0 || s > (b - a).norm()) return std::nullopt;
  return t;
}

Ld pointSegmentDistance(const V3& p, const V3& a, const V3& b) {
  const V3 ab = b - a;
  const Ld len2 = ab.squaredNorm();
  const Ld t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, Ld(0), Ld(1)) : Ld(0);
  return (a + t * ab - p).norm();
}

std::optional<Ld> rayRounded(const Core& core, const V3& o, const V3& d) {
  const V3& a = core.points[0];
  const V3& b = core.points.size() > 1 ? core.points[1] : core.points[0];
  if (pointSegmentDistance(o, a, b) <= core.radius) return Ld(0);
  Ld best = kInf;
  for (const V3& c : {a, b})
    if (auto t = raySphereEntry(o, d, c, core.radius)) best = std::min(best, *t);
  if ((b - a).squaredNorm() > 0)
    if (auto t = rayCylinderEntry(o, d, a, b, core.radius)) best = std::min(best, *t);
  if (best == kInf) return std::nullopt;
  return best;
}

// Slab clipping against every supporting plane through three hull points.
std::optional<Ld> rayPolytope(const std::vector<V3>& pts, const V3& o, const V3& d, Ld maxDist) {
  Ld extent = 0;
  for (const V3& p : pts) extent = std::max(extent, (p - pts[0]).norm());
  Ld enter = 0, exit = maxDist;
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (std::size_t j = i + 1; j < pts.size(); ++j)
      for (std::size_t k = j + 1; k < pts.size(); ++k) {
        V3 n = (pts[j] - pts[i]).cross(pts[k] - pts[i]);
        if (n.norm() <= kPlaneFraction * extent * extent) continue;
        n.normalize();
        Ld lo = kInf, hi = -kInf;
        for (const V3& p : pts) { lo = std::min(lo, n.dot(p - pts[i])); hi = std::max(hi, n.dot(p - pts[i])); }
        if (hi > kPlaneFraction * extent) {
          if (lo < -kPlaneFraction * extent) continue;  // not a supporting plane
          n = -n;  // every point lies on the +n side: face the normal outwards
        }
        const Ld height = n.dot(o - pts[i]), rate = n.dot(d);
        if (rate == 0) {
          if (height > 0) return std::nullopt;
          continue;
        }
        const Ld t = -height / rate;
        if (rate < 0) enter = std::max(enter, t);
        else exit = std::min(exit, t);
        if (enter > exit) return std::nullopt;
      }
  return enter;
}

}  // namespace

std::optional<Ld> rayHit(const Core& core, const V3& origin, const V3& dir, Ld maxDist) {
  std::optional<Ld> t = core.radius > 0 ? rayRounded(core, origin, dir) : rayPolytope(core.points, origin, dir, maxDist);
  if (t && *t > maxDist) return std::nullopt;
  return t;
}

std::optional<Ld> rayHit(const HalfSpace& plane, const V3& origin, const V3& dir, Ld maxDist) {
  // A single-sided quad including its boundary: an origin behind it never hits; one on it hits at 0.
  const Ld height = plane.normal.dot(origin - plane.origin), rate = plane.normal.dot(dir);
  if (height < 0) return std::nullopt;
  if (height == 0) return Ld(0);
  if (rate >= 0) return std::nullopt;
  const Ld t = -height / rate;
  if (t > maxDist) return std::nullopt;
  return t;
}

std::optional<Ld> rayHit(const TriangleSoup& mesh, const V3& origin, const V3& dir, Ld maxDist) {
  // Moller-Trumbore in long double with closed barycentric bounds (edges and vertices count as hits).
  Ld best = kInf;
  for (const auto& tri : mesh.triangles) {
    const V3& a = mesh.vertices[tri[0]];
    const V3 e1 = mesh.vertices[tri[1]] - a, e2 = mesh.vertices[tri[2]] - a;
    if (!mesh.doubleSided && e1.cross(e2).dot(dir) >= 0) continue;  // back face (or edge-on): culled
    const V3 p = dir.cross(e2);
    const Ld det = e1.dot(p);
    if (det == 0) continue;
    const V3 s = origin - a;
    const Ld u = s.dot(p) / det;
    if (u < 0 || u > 1) continue;
    const V3 q = s.cross(e1);
    const Ld v = dir.dot(q) / det;
    if (v < 0 || u + v > 1) continue;
    const Ld t = e2.dot(q) / det;
    if (t >= 0 && t <= maxDist) best = std::min(best, t);
  }
  if (best == kInf) return std::nullopt;
  return best;
}

}  // namespace gq::suites
