#pragma once
// Triangle helpers shared by the triangle-mesh and heightfield kernels:
//  - the watertight ray/triangle test of Woop, Benthin and Wald (JCGT 2013): rays through shared edges and vertices
//    hit at least one of the triangles sharing them (no leaks), in float and double;
//  - the closest point on a triangle (Ericson, Real-Time Collision Detection, 5.1.5, Voronoi region test).
// These are inline templates on purpose: they run once per triangle inside the BVH/heightfield loops.
#include <cmath>
#include <cstdint>

#include "gq/math.h"

namespace gq::detail {

// Higher-precision type for the watertight fallback when an edge function evaluates to exactly zero.
template <class T> struct WiderScalar;
template <> struct WiderScalar<float> { using type = double; };
template <> struct WiderScalar<double> { using type = long double; };

// Per-ray precomputation: the ray is sheared so that it becomes the +Z axis of a 2D test (section 3 of the paper).
// The direction need not be unit length; t is measured in multiples of `dir`.
template <class T> struct WatertightRay {
  Vec3<T> org;
  int kx = 0, ky = 1, kz = 2;  // axes after the permutation; kz = dominant direction axis
  T sx = T(0), sy = T(0), sz = T(1);  // shear constants: dir[kx]/dir[kz], dir[ky]/dir[kz], 1/dir[kz]
};

// Forced inline (as the mesh kernel's ray constants): GCC left it out of line once the kernel had two instances.
template <class T>
[[gnu::always_inline]] inline WatertightRay<T> makeWatertightRay(const Vec3<T>& org, const Vec3<T>& dir) {
  // Written without branches: for rays in all directions each of these choices is a coin toss.
  const Vec3<T> a = dir.cwiseAbs();
  // kz: x if it exceeds y and z, else y if it exceeds z, else z.
  const int xWins = int(a.x() > a.y()) & int(a.x() > a.z());
  const int yWins = int(!(a.x() > a.y())) & int(a.y() > a.z());
  const int kz = 2 - 2 * xWins - yWins;
  int kx = kz + 1 - 3 * int(kz == 2);  // (kz + 1) mod 3 without a division
  int ky = kx + 1 - 3 * int(kx == 2);
  // Keep the winding: a negative dominant component mirrors the 2D frame, so swap the other two axes.
  const int swap = (kx ^ ky) & -int(dir[kz] < T(0));
  kx ^= swap;
  ky ^= swap;
  // One aggregate (no default member values stored first and overwritten).
  return WatertightRay<T>{org, kx, ky, kz, dir[kx] / dir[kz], dir[ky] / dir[kz], T(1) / dir[kz]};
}

template <class T> struct TriangleRayHit {
  T t = T(0);   // ray parameter (distance when dir is unit length)
  T u = T(0);   // weight of v1: point = (1-u-v) v0 + u v1 + v v2
  T v = T(0);   // weight of v2
  bool frontFace = true;  // dot(cross(v1-v0, v2-v0), dir) < 0
};

// Edge functions of the sheared triangle: U for edge (v1,v2), V for (v2,v0), W for (v0,v1); they are the unnormalized
// barycentric weights of v0, v1, v2.
template <class S> inline S edgeFunction(S ax, S ay, S bx, S by) { return ax * by - ay * bx; }

// Watertight ray/triangle intersection. Accepts 0 <= t <= maxT. With cullBackFaces, triangles whose normal
// cross(v1-v0, v2-v0) points along the ray are skipped. Returns false on a miss; `hit` is written only on a hit.
template <class T>
inline bool intersectRayTriangle(const WatertightRay<T>& ray, const Vec3<T>& v0, const Vec3<T>& v1, const Vec3<T>& v2,
                                 T maxT, bool cullBackFaces, TriangleRayHit<T>& hit) {
  const Vec3<T> a = v0 - ray.org, b = v1 - ray.org, c = v2 - ray.org;
  // Shear and scale so the ray runs along +Z from the origin.
  const T ax = a[ray.kx] - ray.sx * a[ray.kz], ay = a[ray.ky] - ray.sy * a[ray.kz];
  const T bx = b[ray.kx] - ray.sx * b[ray.kz], by = b[ray.ky] - ray.sy * b[ray.kz];
  const T cx = c[ray.kx] - ray.sx * c[ray.kz], cy = c[ray.ky] - ray.sy * c[ray.kz];
  T eu = edgeFunction(cx, cy, bx, by);
  T ev = edgeFunction(ax, ay, cx, cy);
  T ew = edgeFunction(bx, by, ax, ay);
  // An exact zero may be a rounding artefact on a shared edge: re-evaluate in a wider type (paper, section 4.1).
  if (eu == T(0) || ev == T(0) || ew == T(0)) {
    using W = typename WiderScalar<T>::type;
    eu = T(W(cx) * W(by) - W(cy) * W(bx));
    ev = T(W(ax) * W(cy) - W(ay) * W(cx));
    ew = T(W(bx) * W(ay) - W(by) * W(ax));
  }
  // The ray passes inside (or on the boundary) only when all three edge functions share a sign.
  const bool anyNeg = eu < T(0) || ev < T(0) || ew < T(0);
  const bool anyPos = eu > T(0) || ev > T(0) || ew > T(0);
  if (anyNeg && anyPos) return false;
  const T det = eu + ev + ew;
  if (det == T(0)) return false;  // the ray lies in the triangle's plane
  const bool front = det > T(0);  // det > 0 exactly when dot(normal, dir) < 0
  if (cullBackFaces && !front) return false;
  // Scaled hit distance tScaled = t * det; compare without dividing.
  const T az = ray.sz * a[ray.kz], bz = ray.sz * b[ray.kz], cz = ray.sz * c[ray.kz];
  const T tScaled = eu * az + ev * bz + ew * cz;
  const T sign = front ? T(1) : T(-1);
  const T absDet = det * sign;
  const T st = tScaled * sign;
  if (st < T(0) || st > maxT * absDet) return false;
  const T inv = T(1) / det;
  hit.t = tScaled * inv;
  hit.u = ev * inv;
  hit.v = ew * inv;
  hit.frontFace = front;
  return true;
}

// Closest point on triangle (a, b, c) to p, by Voronoi regions (Ericson 5.1.5). Also returns the barycentric weights
// of b and c (point = a + s*(b-a) + t*(c-a)), useful for reporting.
template <class T>
inline Vec3<T> closestPointOnTriangle(const Vec3<T>& p, const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c,
                                      T* weightB = nullptr, T* weightC = nullptr) {
  auto out = [&](T s, T t) {
    if (weightB) *weightB = s;
    if (weightC) *weightC = t;
    return Vec3<T>(a + s * (b - a) + t * (c - a));
  };
  const Vec3<T> ab = b - a, ac = c - a, ap = p - a;
  const T d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= T(0) && d2 <= T(0)) return out(T(0), T(0));  // vertex region a
  const Vec3<T> bp = p - b;
  const T d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= T(0) && d4 <= d3) return out(T(1), T(0));  // vertex region b
  const T vc = d1 * d4 - d3 * d2;
  if (vc <= T(0) && d1 >= T(0) && d3 <= T(0)) return out(d1 / (d1 - d3), T(0));  // edge ab
  const Vec3<T> cp = p - c;
  const T d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= T(0) && d5 <= d6) return out(T(0), T(1));  // vertex region c
  const T vb = d5 * d2 - d1 * d6;
  if (vb <= T(0) && d2 >= T(0) && d6 <= T(0)) return out(T(0), d2 / (d2 - d6));  // edge ac
  const T va = d3 * d6 - d5 * d4;
  if (va <= T(0) && (d4 - d3) >= T(0) && (d5 - d6) >= T(0)) {  // edge bc
    const T w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return out(T(1) - w, w);
  }
  // Face region; a degenerate (zero-area) triangle cannot reach here since one of the tests above holds.
  const T denom = T(1) / (va + vb + vc);
  return out(vb * denom, vc * denom);
}

}  // namespace gq::detail
