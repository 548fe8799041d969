// Exact primitive-triangle kernels (see triangle_tests.h).
#include "mesh_pairs/triangle_tests.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/unit_vector.h"
#include "mesh/triangle.h"
#include "shapes/segment.h"

namespace gq::detail {
namespace {

// Whether x, a point of the triangle's plane, lies inside or on the triangle (edge functions share the sign of n).
template <class T> bool planePointInTriangle(const Vec3<T>& x, const Triangle<T>& tri, const Vec3<T>& n) {
  for (int i = 0; i < 3; ++i) {
    const Vec3<T>& a = tri.verts[i];
    const Vec3<T>& b = tri.verts[(i + 1) % 3];
    if (n.dot((b - a).cross(x - a)) < T(0)) return false;
  }
  return true;
}

// Projection interval of the triangle on `axis`.
template <class T> void project(const Triangle<T>& tri, const Vec3<T>& axis, T& lo, T& hi) {
  lo = hi = axis.dot(tri.verts[0]);
  for (int i = 1; i < 3; ++i) {
    const T s = axis.dot(tri.verts[i]);
    lo = std::min(lo, s);
    hi = std::max(hi, s);
  }
}

template <class T> bool separatesTriangles(const Vec3<T>& axis, const Triangle<T>& a, const Triangle<T>& b) {
  T loA, hiA, loB, hiB;
  project(a, axis, loA, hiA);
  project(b, axis, loB, hiB);
  return hiA < loB || hiB < loA;
}

}  // namespace

template <class T>
SegmentTriangleClosest<T> closestSegmentTriangle(const Vec3<T>& p, const Vec3<T>& q, const Triangle<T>& tri) {
  const Vec3<T>& a = tri.verts[0];
  const Vec3<T> n = (tri.verts[1] - a).cross(tri.verts[2] - a);
  const T dp = n.dot(p - a), dq = n.dot(q - a);
  // The segment meets the plane at p + t (q - p), t = dp / (dp - dq), when dp and dq differ in sign.
  if ((dp <= T(0) && dq >= T(0)) || (dp >= T(0) && dq <= T(0))) {
    if (dp != dq) {
      const Vec3<T> x = p + (dp / (dp - dq)) * (q - p);
      if (planePointInTriangle(x, tri, n)) return {T(0), x, x};
    }
  }
  SegmentTriangleClosest<T> best;
  best.distSq = std::numeric_limits<T>::infinity();
  auto offer = [&](const Vec3<T>& onSeg, const Vec3<T>& onTri) {
    const T d2 = (onSeg - onTri).squaredNorm();
    if (d2 < best.distSq) best = {d2, onSeg, onTri};
  };
  offer(p, closestPointOnTriangle(p, tri.verts[0], tri.verts[1], tri.verts[2]));
  offer(q, closestPointOnTriangle(q, tri.verts[0], tri.verts[1], tri.verts[2]));
  for (int i = 0; i < 3; ++i) {
    const SegmentClosest<T> c = closestSegmentSegment(p, q, tri.verts[i], tri.verts[(i + 1) % 3]);
    offer(c.c0, c.c1);
  }
  return best;
}

template <class T>
SegmentTriangleExit<T> segmentTriangleExit(const Vec3<T>& p, const Vec3<T>& q, const Triangle<T>& tri, const Vec3<T>* hint) {
  SegmentTriangleExit<T> best;
  best.exit = std::numeric_limits<T>::infinity();
  // Moving the segment by t along u clears the triangle once t >= max(tri . u) - min(seg . u).
  const auto consider = [&](const Vec3<T>& u) {
    T lo, hi;
    project(tri, u, lo, hi);
    const T pu = p.dot(u), qu = q.dot(u);
    const T alongPlus = hi - std::min(pu, qu), alongMinus = std::max(pu, qu) - lo;
    if (alongPlus < best.exit) best = {u, alongPlus};
    if (alongMinus < best.exit) best = {Vec3<T>(-u), alongMinus};
  };
  Vec3<T> u;
  if (hint) consider(*hint);
  const Vec3<T> e[3] = {tri.verts[1] - tri.verts[0], tri.verts[2] - tri.verts[1], tri.verts[0] - tri.verts[2]};
  if (tryUnit(Vec3<T>(e[0].cross(e[1])), u)) consider(u);
  const Vec3<T> s = q - p;
  for (const Vec3<T>& edge : e)
    if (tryUnit(Vec3<T>(s.cross(edge)), u)) consider(u);
  return best;
}

template <class T> bool overlapSphereTriangle(const Vec3<T>& center, T radius, const Triangle<T>& tri) {
  const Vec3<T> c = closestPointOnTriangle(center, tri.verts[0], tri.verts[1], tri.verts[2]);
  return (c - center).squaredNorm() <= radius * radius;
}

template <class T> bool overlapCapsuleTriangle(const Vec3<T>& p, const Vec3<T>& q, T radius, const Triangle<T>& tri) {
  return closestSegmentTriangle(p, q, tri).distSq <= radius * radius;
}

template <class T> bool overlapBoxTriangle(const Vec3<T>& h, const Triangle<T>& tri) {
  const Vec3<T>* v = tri.verts;
  // Box face normals: the triangle's extent along each axis against [-h, h].
  for (int k = 0; k < 3; ++k) {
    const T lo = std::min({v[0][k], v[1][k], v[2][k]}), hi = std::max({v[0][k], v[1][k], v[2][k]});
    if (lo > h[k] || hi < -h[k]) return false;
  }
  // Triangle normal: the plane's offset against the box's projected radius h . |n|.
  const Vec3<T> n = (v[1] - v[0]).cross(v[2] - v[0]);
  if (std::abs(n.dot(v[0])) > h.dot(n.cwiseAbs())) return false;
  // Box axis x triangle edge.
  for (int j = 0; j < 3; ++j) {
    const Vec3<T> f = v[(j + 1) % 3] - v[j];
    for (int k = 0; k < 3; ++k) {
      const Vec3<T> axis = Vec3<T>::Unit(k).cross(f);
      const T p0 = axis.dot(v[0]), p1 = axis.dot(v[1]), p2 = axis.dot(v[2]);
      const T r = h.dot(axis.cwiseAbs());
      if (std::min({p0, p1, p2}) > r || std::max({p0, p1, p2}) < -r) return false;
    }
  }
  return true;
}

template <class T> bool overlapTriangleTriangle(const Triangle<T>& a, const Triangle<T>& b) {
  const Vec3<T> ea[3] = {a.verts[1] - a.verts[0], a.verts[2] - a.verts[1], a.verts[0] - a.verts[2]};
  const Vec3<T> eb[3] = {b.verts[1] - b.verts[0], b.verts[2] - b.verts[1], b.verts[0] - b.verts[2]};
  const Vec3<T> na = ea[0].cross(ea[1]), nb = eb[0].cross(eb[1]);
  if (separatesTriangles(na, a, b) || separatesTriangles(nb, a, b)) return false;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (separatesTriangles(Vec3<T>(ea[i].cross(eb[j])), a, b)) return false;
  for (int i = 0; i < 3; ++i) {
    if (separatesTriangles(Vec3<T>(na.cross(ea[i])), a, b)) return false;
    if (separatesTriangles(Vec3<T>(nb.cross(eb[i])), a, b)) return false;
  }
  return true;
}

template <class T> TrianglePairClosest<T> closestTriangleTriangle(const Triangle<T>& a, const Triangle<T>& b) {
  TrianglePairClosest<T> best;
  best.distSq = std::numeric_limits<T>::infinity();
  for (int i = 0; i < 3 && best.distSq > T(0); ++i) {
    const SegmentTriangleClosest<T> ca = closestSegmentTriangle(a.verts[i], a.verts[(i + 1) % 3], b);
    if (ca.distSq < best.distSq) best = {ca.distSq, ca.onSegment, ca.onTriangle};
    const SegmentTriangleClosest<T> cb = closestSegmentTriangle(b.verts[i], b.verts[(i + 1) % 3], a);
    if (cb.distSq < best.distSq) best = {cb.distSq, cb.onTriangle, cb.onSegment};
  }
  return best;
}

template SegmentTriangleClosest<float> closestSegmentTriangle(const Vec3<float>&, const Vec3<float>&, const Triangle<float>&);
template SegmentTriangleExit<float> segmentTriangleExit(const Vec3<float>&, const Vec3<float>&, const Triangle<float>&,
                                                         const Vec3<float>*);
template bool overlapSphereTriangle(const Vec3<float>&, float, const Triangle<float>&);
template bool overlapCapsuleTriangle(const Vec3<float>&, const Vec3<float>&, float, const Triangle<float>&);
template bool overlapBoxTriangle(const Vec3<float>&, const Triangle<float>&);
template bool overlapTriangleTriangle(const Triangle<float>&, const Triangle<float>&);
template TrianglePairClosest<float> closestTriangleTriangle(const Triangle<float>&, const Triangle<float>&);

template SegmentTriangleClosest<double> closestSegmentTriangle(const Vec3<double>&, const Vec3<double>&, const Triangle<double>&);
template SegmentTriangleExit<double> segmentTriangleExit(const Vec3<double>&, const Vec3<double>&, const Triangle<double>&,
                                                          const Vec3<double>*);
template bool overlapSphereTriangle(const Vec3<double>&, double, const Triangle<double>&);
template bool overlapCapsuleTriangle(const Vec3<double>&, const Vec3<double>&, double, const Triangle<double>&);
template bool overlapBoxTriangle(const Vec3<double>&, const Triangle<double>&);
template bool overlapTriangleTriangle(const Triangle<double>&, const Triangle<double>&);
template TrianglePairClosest<double> closestTriangleTriangle(const Triangle<double>&, const Triangle<double>&);

}  // namespace gq::detail
