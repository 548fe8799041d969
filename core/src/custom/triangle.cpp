// The solid triangle abc (flat, both faces).
// Support: the vertex farthest along d. Raycast: Moeller-Trumbore (the barycentric weights u, v of b and c and the
// ray parameter t by Cramer's rule), accepted from either side with the normal against the ray; a ray in the
// triangle's plane (det = 0 and the origin in the plane) clips the triangle's three edge half-planes instead and
// enters through an edge, whose outward normal in the plane is the hit normal. A ray starting on the triangle hits
// at distance 0 (the solid-shape rule: normal -dir).
#include <algorithm>
#include <cmath>
#include <limits>

#include "custom/ray_interval.h"
#include "gq/custom_shapes.h"
#include "gq/tolerances.h"

namespace gq {

template <class T> Bounds3<T> TriangleCallbacks<T>::localBounds() const {
  Bounds3<T> b;
  for (const Vec3<T>& v : v_) b.include(v);
  return b;
}

template <class T> Vec3<T> TriangleCallbacks<T>::support(const Vec3<T>& dir) const {
  const T d0 = v_[0].dot(dir), d1 = v_[1].dot(dir), d2 = v_[2].dot(dir);
  if (d0 >= d1 && d0 >= d2) return v_[0];
  return d1 >= d2 ? v_[1] : v_[2];
}

namespace {

// The coplanar ray: the edge half-planes m_i . (x - v_i) <= 0, m_i = e_i x n the outward edge normals.
template <class T>
bool coplanarRaycast(const Vec3<T> (&v)[3], const Vec3<T>& n, const Vec3<T>& o, const Vec3<T>& d, T maxDist,
                     HitFlags flags, RaycastHit<T>& hit) {
  detail::RayInterval<T> r;
  Vec3<T> outward[3];
  constexpr T inf = std::numeric_limits<T>::infinity();
  for (int i = 0; i < 3; ++i) {
    outward[i] = (v[(i + 1) % 3] - v[i]).cross(n);
    const T height = outward[i].dot(o - v[i]), rate = outward[i].dot(d);
    if (rate == T(0)) {
      if (height > T(0)) return false;
    } else if (rate > T(0)) {
      r.clip(-inf, -height / rate, i);  // leaves through edge i
    } else {
      r.clip(-height / rate, inf, i);  // enters through edge i
    }
  }
  const auto normalAt = [&](int edge, const Vec3<T>&) { return Vec3<T>(outward[edge].normalized()); };
  return detail::writeIntervalHit(r, o, d, maxDist, flags, normalAt, hit);
}

}  // namespace

template <class T>
bool TriangleCallbacks<T>::raycast(const Vec3<T>& origin, const Vec3<T>& unitDir, T maxDist, HitFlags flags,
                                   RaycastHit<T>& hit) const {
  const Vec3<T> e1 = v_[1] - v_[0], e2 = v_[2] - v_[0];
  const Vec3<T> s = origin - v_[0];
  const Vec3<T> p = unitDir.cross(e2);
  const T det = e1.dot(p);
  if (det == T(0)) {
    const Vec3<T> n = e1.cross(e2);
    if (n.dot(s) != T(0) || n == Vec3<T>::Zero()) return false;  // parallel off the plane, or no plane
    return coplanarRaycast(v_, n, origin, unitDir, maxDist, flags, hit);
  }
  const T inv = T(1) / det;
  const T u = s.dot(p) * inv;
  if (u < T(0) || u > T(1)) return false;
  const Vec3<T> q = s.cross(e1);
  const T v = unitDir.dot(q) * inv;
  if (v < T(0) || u + v > T(1)) return false;
  const T t = e2.dot(q) * inv;
  if (t < T(0) || t > maxDist) return false;
  if (t == T(0)) {  // the origin on the triangle
    hit.distance = T(0);
    hit.position = origin;
    hit.normal = -unitDir;
    hit.flags = HitFlag::Position | HitFlag::Normal;
    return true;
  }
  hit.distance = t;
  hit.flags = HitFlags();
  if (flags.has(HitFlag::Position)) {
    hit.position = origin + t * unitDir;
    hit.flags |= HitFlag::Position;
  }
  if (flags.has(HitFlag::Normal)) {
    const Vec3<T> n = e1.cross(e2).normalized();
    hit.normal = n.dot(unitDir) > T(0) ? Vec3<T>(-n) : n;
    hit.flags |= HitFlag::Normal;
  }
  if (flags.has(HitFlag::UV)) {
    hit.u = u;
    hit.v = v;
    hit.flags |= HitFlag::UV;
  }
  return true;
}

template <class T> Status makeTriangle(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c, CustomGeometry<T>& out) {
  if (!(isFinite(a) && isFinite(b) && isFinite(c))) return Status::invalid("triangle vertices must be finite");
  // The rule of mesh cooking (a mesh would drop this triangle): doubled area <= kDegenerateTriangleArea * (longest
  // edge)^2, in double, the edges first divided by their largest component (the ratio does not change, and huge
  // double edges do not overflow).
  Vec3<double> e[3] = {(b - a).template cast<double>(), (c - a).template cast<double>(), (c - b).template cast<double>()};
  const double scale = std::max({e[0].cwiseAbs().maxCoeff(), e[1].cwiseAbs().maxCoeff(), e[2].cwiseAbs().maxCoeff()});
  if (!(scale > 0.0)) return Status::degenerate("triangle has coincident vertices (no area)");
  for (Vec3<double>& edge : e) edge /= scale;
  const double longestSq = std::max({e[0].squaredNorm(), e[1].squaredNorm(), e[2].squaredNorm()});
  if (!(e[0].cross(e[1]).norm() > tol::kDegenerateTriangleArea * longestSq))
    return Status::degenerate("triangle vertices are collinear (no area)");
  out = CustomGeometry<T>(std::make_shared<TriangleCallbacks<T>>(a, b, c));
  return {};
}

template class TriangleCallbacks<float>;
template class TriangleCallbacks<double>;
template Status makeTriangle<float>(const Vec3<float>&, const Vec3<float>&, const Vec3<float>&, CustomGeometry<float>&);
template Status makeTriangle<double>(const Vec3<double>&, const Vec3<double>&, const Vec3<double>&,
                                     CustomGeometry<double>&);

}  // namespace gq
