#include "exact_reference.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gq::fcltest {
namespace {

using L = long double;
using V = Eigen::Matrix<L, 3, 1>;

struct World {  // a shape's frame in long double
  Eigen::Matrix<L, 3, 3> r;
  V t;
  V apply(const ::fcl::Vector3d& p) const { return r * p.cast<L>() + t; }
};
World worldOf(const ::fcl::Transform3d& tf) { return {tf.linear().cast<L>(), tf.translation().cast<L>()}; }

// max over the shape of n.x (world frame, n unit).
L supportExtent(const TestShape& s, const World& w, const V& n) {
  const V c = w.t, axis = w.r.col(2);
  const L an = axis.dot(n), radial = std::sqrt(std::max<L>(0, 1 - an * an));
  switch (s.kind) {
    case Kind::Sphere: return c.dot(n) + L(s.size.x());
    case Kind::Capsule: return c.dot(n) + L(s.size.y()) / 2 * std::fabs(an) + L(s.size.x());
    case Kind::Cylinder: return c.dot(n) + L(s.size.y()) / 2 * std::fabs(an) + L(s.size.x()) * radial;
    case Kind::Cone: {
      const L h = L(s.size.y()) / 2;
      return std::max(c.dot(n) + h * an, c.dot(n) - h * an + L(s.size.x()) * radial);
    }
    case Kind::Ellipsoid: {
      const V local = w.r.transpose() * n;
      return c.dot(n) + V(local.x() * L(s.size.x()), local.y() * L(s.size.y()), local.z() * L(s.size.z())).norm();
    }
    default: {
      L best = -std::numeric_limits<L>::infinity();
      for (const auto& p : s.vertices) best = std::max(best, w.apply(p).dot(n));
      return best;
    }
  }
}

bool isPolytope(Kind k) { return k == Kind::Box || k == Kind::Convex || k == Kind::TriangleP || k == Kind::Mesh; }

// Closest points between segments [p0,p1] and [q0,q1] (clamped parametric solution).
L segmentSegmentDistance(const V& p0, const V& p1, const V& q0, const V& q1) {
  const V d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const L a = d1.dot(d1), e = d2.dot(d2), f = d2.dot(r);
  L s = 0, t = 0;
  if (a <= 0 && e <= 0) return r.norm();
  if (a <= 0) t = std::clamp(f / e, L(0), L(1));
  else {
    const L c = d1.dot(r);
    if (e <= 0) s = std::clamp(-c / a, L(0), L(1));
    else {
      const L b = d1.dot(d2), denom = a * e - b * b;
      s = denom > 0 ? std::clamp((b * f - c * e) / denom, L(0), L(1)) : 0;
      t = (b * s + f) / e;
      if (t < 0) t = 0, s = std::clamp(-c / a, L(0), L(1));
      else if (t > 1) t = 1, s = std::clamp((b - c) / a, L(0), L(1));
    }
  }
  return ((p0 + s * d1) - (q0 + t * d2)).norm();
}

// Ericson's closest point on triangle abc to p (Voronoi regions).
V closestOnTriangle(const V& p, const V& a, const V& b, const V& c) {
  const V ab = b - a, ac = c - a, ap = p - a;
  const L d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const V bp = p - b;
  const L d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const L vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const V cp = p - c;
  const L d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const L vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const L va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const L denom = 1 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

struct Poly {  // world-space polytope: vertices, triangular/quad faces, edges
  std::vector<V> v;
  std::vector<std::vector<int>> f;
};

Poly boxPoly(const TestShape& s, const World& w) {
  Poly p;
  for (const auto& q : s.vertices) p.v.push_back(w.apply(q));
  // corners i: bit0 = +x, bit1 = +y, bit2 = +z
  p.f = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};
  return p;
}

Poly polyOf(const TestShape& s, const World& w) {
  if (s.kind == Kind::Box) return boxPoly(s, w);
  Poly p;
  for (const auto& q : s.vertices) p.v.push_back(w.apply(q));
  p.f = s.faces;
  return p;
}

V faceNormal(const Poly& p, const std::vector<int>& f) {
  return (p.v[f[1]] - p.v[f[0]]).cross(p.v[f[2]] - p.v[f[0]]);
}

void project(const std::vector<V>& pts, const V& axis, L& lo, L& hi) {
  lo = std::numeric_limits<L>::infinity(), hi = -lo;
  for (const V& q : pts) lo = std::min(lo, q.dot(axis)), hi = std::max(hi, q.dot(axis));
}

// SAT between two convex vertex sets with the given faces (edges taken from the faces).
bool satIntersect(const std::vector<V>& av, const std::vector<std::vector<int>>& af, const std::vector<V>& bv,
                  const std::vector<std::vector<int>>& bf) {
  std::vector<V> axes, ea, eb;
  const auto collect = [&](const std::vector<V>& v, const std::vector<std::vector<int>>& faces, std::vector<V>& edges) {
    for (const auto& f : faces) {
      axes.push_back((v[f[1]] - v[f[0]]).cross(v[f[2]] - v[f[0]]));
      for (std::size_t i = 0; i < f.size(); ++i) edges.push_back(v[f[(i + 1) % f.size()]] - v[f[i]]);
    }
  };
  collect(av, af, ea);
  collect(bv, bf, eb);
  for (const V& x : ea)
    for (const V& y : eb) axes.push_back(x.cross(y));
  for (const V& axis : axes) {
    if (axis.squaredNorm() < L(1e-24)) continue;
    L alo, ahi, blo, bhi;
    project(av, axis, alo, ahi);
    project(bv, axis, blo, bhi);
    if (ahi < blo || bhi < alo) return false;
  }
  return true;
}

// A mesh is a surface: it touches a convex set iff one of its triangles does.
bool polytopesIntersect(const TestShape& a, const World& wa, const TestShape& b, const World& wb) {
  const Poly pa = polyOf(a, wa), pb = polyOf(b, wb);
  const auto pieces = [](const TestShape& s, const Poly& p) {
    std::vector<Poly> out;
    if (s.kind != Kind::Mesh) return std::vector<Poly>{p};
    for (const auto& f : p.f) out.push_back(Poly{{p.v[f[0]], p.v[f[1]], p.v[f[2]]}, {{0, 1, 2}}});
    return out;
  };
  for (const Poly& x : pieces(a, pa))
    for (const Poly& y : pieces(b, pb))
      if (satIntersect(x.v, x.f, y.v, y.f)) return true;
  return false;
}

// Distance from a point to a polytope (0 inside a solid one); meshes and triangles are surfaces.
L pointPolytopeDistance(const V& p, const TestShape& s, const World& w) {
  const Poly poly = polyOf(s, w);
  if (s.kind == Kind::Box) {
    const V local = w.r.transpose() * (p - w.t);
    const V h = (s.size / 2).cast<L>();
    return (local - local.cwiseMax(-h).cwiseMin(h)).norm();
  }
  if (s.kind == Kind::Convex) {
    bool inside = true;
    for (const auto& f : poly.f) inside = inside && faceNormal(poly, f).dot(p - poly.v[f[0]]) <= 0;
    if (inside) return 0;
  }
  L best = std::numeric_limits<L>::infinity();
  for (const auto& f : poly.f) best = std::min(best, (p - closestOnTriangle(p, poly.v[f[0]], poly.v[f[1]], poly.v[f[2]])).norm());
  return best;
}

ExactAnswer planeAnswer(const TestShape& plane, const World& wp, const TestShape& s, const World& ws) {
  const V n = (wp.r * plane.planeNormal.cast<L>()).normalized();
  const L d = L(plane.planeOffset) + n.dot(wp.t);  // world plane n.x = d
  const L hi = supportExtent(s, ws, n), lo = -supportExtent(s, ws, -n);
  ExactAnswer e;
  e.known = e.distanceKnown = true;
  if (plane.kind == Kind::Halfspace) {
    e.distance = lo - d;
    // A mesh is a surface, but a half-space is solid: any vertex below counts.
  } else {
    e.distance = std::max(lo - d, d - hi);
  }
  e.colliding = e.distance <= 0;
  return e;
}

}  // namespace

bool exactDepth(const TestShape& a, const ::fcl::Transform3d& pa, const TestShape& b, const ::fcl::Transform3d& pb,
                long double& depth) {
  const World wa = worldOf(pa), wb = worldOf(pb);
  const auto round = [](Kind k) { return k == Kind::Sphere || k == Kind::Capsule; };
  if (round(a.kind) && round(b.kind)) {
    const ExactAnswer e = exactAnswer(a, pa, b, pb);
    depth = -e.distance;
    return e.colliding;
  }
  const auto solidPolytope = [](Kind k) { return k == Kind::Box || k == Kind::Convex; };
  if (!solidPolytope(a.kind) || !solidPolytope(b.kind)) return false;
  const Poly x = polyOf(a, wa), y = polyOf(b, wb);
  std::vector<V> axes, ex, ey;
  for (const auto& f : x.f) {
    axes.push_back(faceNormal(x, f));
    for (std::size_t i = 0; i < f.size(); ++i) ex.push_back(x.v[f[(i + 1) % f.size()]] - x.v[f[i]]);
  }
  for (const auto& f : y.f) {
    axes.push_back(faceNormal(y, f));
    for (std::size_t i = 0; i < f.size(); ++i) ey.push_back(y.v[f[(i + 1) % f.size()]] - y.v[f[i]]);
  }
  for (const V& p : ex)
    for (const V& q : ey) axes.push_back(p.cross(q));
  depth = std::numeric_limits<L>::infinity();
  for (V axis : axes) {
    const L len = axis.norm();
    if (len < L(1e-12)) continue;
    axis /= len;
    L alo, ahi, blo, bhi;
    project(x.v, axis, alo, ahi);
    project(y.v, axis, blo, bhi);
    const L overlap = std::min(ahi - blo, bhi - alo);
    if (overlap < 0) return false;
    depth = std::min(depth, overlap);
  }
  return true;
}

void exactSphereTriangleContact(const TestShape& sphere, const ::fcl::Transform3d& ps, const TestShape& mesh,
                                const ::fcl::Transform3d& pm, int triangle, ::fcl::Vector3d& nearest,
                                long double& depth) {
  const World w = worldOf(pm);
  const std::vector<int>& f = mesh.faces.at(std::size_t(triangle));
  const V c = ps.translation().cast<L>();
  const V q = closestOnTriangle(c, w.apply(mesh.vertices[f[0]]), w.apply(mesh.vertices[f[1]]), w.apply(mesh.vertices[f[2]]));
  nearest = q.cast<double>();
  depth = L(sphere.size[0]) - (c - q).norm();
}

long double certifiedGap(const TestShape& a, const ::fcl::Transform3d& pa, const TestShape& b, const ::fcl::Transform3d& pb,
                         const ::fcl::Vector3d& direction) {
  const V n = direction.cast<L>().normalized();
  return -supportExtent(b, worldOf(pb), -n) - supportExtent(a, worldOf(pa), n);
}

ExactAnswer exactAnswer(const TestShape& a, const ::fcl::Transform3d& pa, const TestShape& b, const ::fcl::Transform3d& pb) {
  const World wa = worldOf(pa), wb = worldOf(pb);
  if (isPlaneLike(a.kind) && isPlaneLike(b.kind)) return {};
  if (isPlaneLike(a.kind)) return planeAnswer(a, wa, b, wb);
  if (isPlaneLike(b.kind)) return planeAnswer(b, wb, a, wa);
  const auto core = [](const TestShape& s, const World& w, V& p0, V& p1, L& r) {  // sphere/capsule as swept segment
    const L h = s.kind == Kind::Capsule ? L(s.size.y()) / 2 : 0;
    p0 = w.t + h * w.r.col(2), p1 = w.t - h * w.r.col(2), r = L(s.size.x());
  };
  const bool roundA = a.kind == Kind::Sphere || a.kind == Kind::Capsule;
  const bool roundB = b.kind == Kind::Sphere || b.kind == Kind::Capsule;
  ExactAnswer e;
  if (roundA && roundB) {
    V a0, a1, b0, b1;
    L ra, rb;
    core(a, wa, a0, a1, ra);
    core(b, wb, b0, b1, rb);
    e.known = e.distanceKnown = true;
    e.distance = segmentSegmentDistance(a0, a1, b0, b1) - ra - rb;
    e.colliding = e.distance <= 0;
    return e;
  }
  const bool sphereA = a.kind == Kind::Sphere, sphereB = b.kind == Kind::Sphere;
  if ((sphereA && isPolytope(b.kind)) || (sphereB && isPolytope(a.kind))) {
    const TestShape& sphere = sphereA ? a : b;
    const TestShape& poly = sphereA ? b : a;
    const World& ws = sphereA ? wa : wb;
    const L d = pointPolytopeDistance(ws.t, poly, sphereA ? wb : wa) - L(sphere.size.x());
    e.known = true;
    e.colliding = d <= 0;
    e.distanceKnown = d > 0;  // outside: exact separation
    e.distance = d;
    return e;
  }
  if (isPolytope(a.kind) && isPolytope(b.kind)) {
    e.known = true;
    e.colliding = polytopesIntersect(a, wa, b, wb);
    return e;
  }
  return e;
}

}  // namespace gq::fcltest
