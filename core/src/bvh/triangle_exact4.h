#pragma once
// The float watertight ray/triangle test (mesh/triangle.h, intersectRayTriangle<float>) on the 4 triangles of a leaf
// at once (bvh/bvh.h TriangleVertices4). Every lane performs the scalar test's IEEE operations in the same order on
// the same float inputs, so a lane it rejects is one the scalar test rejects: no margin is needed, unlike the
// conservative pre-test of double meshes (bvh/triangle_packet.h). Lanes it cannot decide exactly the same way are
// kept as candidates for the scalar test: an edge function that is exactly zero (the scalar test re-evaluates it in
// double) and any NaN (every comparison fails, so nothing rejects the lane). Accepted lanes get the scalar test,
// which computes the hit.
#include <cmath>
#include <cstdint>
#include <limits>

#include "bvh/bvh.h"
#include "mesh/triangle.h"

#ifdef GQ_SSE42
#include <smmintrin.h>
#endif

namespace gq::detail {

// Per-ray constants: the scalar test's WatertightRay<float> (permuted axes, shear, origin), and its origin and shear on
// the permuted axes broadcast to 4 lanes once per ray.
struct WatertightRay4 {
  WatertightRay<float> ray;
#ifdef GQ_SSE42
  __m128 ox, oy, oz, sx, sy, sz;
#endif
};

inline WatertightRay4 makeWatertightRay4(const WatertightRay<float>& ray) {
  WatertightRay4 r;
  r.ray = ray;
#ifdef GQ_SSE42
  r.ox = _mm_set1_ps(ray.org[ray.kx]);
  r.oy = _mm_set1_ps(ray.org[ray.ky]);
  r.oz = _mm_set1_ps(ray.org[ray.kz]);
  r.sx = _mm_set1_ps(ray.sx);
  r.sy = _mm_set1_ps(ray.sy);
  r.sz = _mm_set1_ps(ray.sz);
#endif
  return r;
}

// The hits of the lanes the 4-wide test decides alone (bit i of `decided`): the scalar test's t, u, v and side, bit
// for bit (the same IEEE operations: 1 / det, then products). Other candidate lanes need the scalar test.
struct TriangleHits4 {
  int decided = 0;
  alignas(16) float t[4], u[4], v[4];
  int frontMask = 0;  // bit i: lane i was hit on its front face
};

// Bit i set: the scalar watertight test of triangle i of the packet may accept the ray within [0, maxT]. A candidate
// lane without an exactly zero edge function and with a finite hit is decided here: the scalar test accepts it with
// the hit written to `hits` (bit i of hits.decided).
inline int exactTriangleHits(const TriangleVertices4& p, const WatertightRay4& r, float maxT, bool cullBackFaces,
                             TriangleHits4& hits) {
#ifdef GQ_SSE42
  const WatertightRay<float>& ray = r.ray;
  const __m128 zero = _mm_setzero_ps();
  // a = v0 - org, b = v1 - org, c = v2 - org on the permuted axes, then the shear.
  const __m128 akz = _mm_sub_ps(_mm_load_ps(p.v[0][ray.kz]), r.oz);
  const __m128 bkz = _mm_sub_ps(_mm_load_ps(p.v[1][ray.kz]), r.oz);
  const __m128 ckz = _mm_sub_ps(_mm_load_ps(p.v[2][ray.kz]), r.oz);
  const __m128 ax = _mm_sub_ps(_mm_sub_ps(_mm_load_ps(p.v[0][ray.kx]), r.ox), _mm_mul_ps(r.sx, akz));
  const __m128 ay = _mm_sub_ps(_mm_sub_ps(_mm_load_ps(p.v[0][ray.ky]), r.oy), _mm_mul_ps(r.sy, akz));
  const __m128 bx = _mm_sub_ps(_mm_sub_ps(_mm_load_ps(p.v[1][ray.kx]), r.ox), _mm_mul_ps(r.sx, bkz));
  const __m128 by = _mm_sub_ps(_mm_sub_ps(_mm_load_ps(p.v[1][ray.ky]), r.oy), _mm_mul_ps(r.sy, bkz));
  const __m128 cx = _mm_sub_ps(_mm_sub_ps(_mm_load_ps(p.v[2][ray.kx]), r.ox), _mm_mul_ps(r.sx, ckz));
  const __m128 cy = _mm_sub_ps(_mm_sub_ps(_mm_load_ps(p.v[2][ray.ky]), r.oy), _mm_mul_ps(r.sy, ckz));
  // edgeFunction(cx, cy, bx, by), edgeFunction(ax, ay, cx, cy), edgeFunction(bx, by, ax, ay).
  const __m128 eu = _mm_sub_ps(_mm_mul_ps(cx, by), _mm_mul_ps(cy, bx));
  const __m128 ev = _mm_sub_ps(_mm_mul_ps(ax, cy), _mm_mul_ps(ay, cx));
  const __m128 ew = _mm_sub_ps(_mm_mul_ps(bx, ay), _mm_mul_ps(by, ax));
  const __m128 anyZero =
      _mm_or_ps(_mm_or_ps(_mm_cmpeq_ps(eu, zero), _mm_cmpeq_ps(ev, zero)), _mm_cmpeq_ps(ew, zero));
  const __m128 anyNeg = _mm_or_ps(_mm_or_ps(_mm_cmplt_ps(eu, zero), _mm_cmplt_ps(ev, zero)), _mm_cmplt_ps(ew, zero));
  const __m128 anyPos = _mm_or_ps(_mm_or_ps(_mm_cmpgt_ps(eu, zero), _mm_cmpgt_ps(ev, zero)), _mm_cmpgt_ps(ew, zero));
  __m128 reject = _mm_and_ps(anyNeg, anyPos);
  const __m128 det = _mm_add_ps(_mm_add_ps(eu, ev), ew);
  reject = _mm_or_ps(reject, _mm_cmpeq_ps(det, zero));
  const __m128 front = _mm_cmpgt_ps(det, zero);
  if (cullBackFaces) reject = _mm_or_ps(reject, _mm_cmple_ps(det, zero));  // !(det > 0)
  const __m128 euAz = _mm_mul_ps(eu, _mm_mul_ps(r.sz, akz)), evBz = _mm_mul_ps(ev, _mm_mul_ps(r.sz, bkz));
  const __m128 tScaled = _mm_add_ps(_mm_add_ps(euAz, evBz), _mm_mul_ps(ew, _mm_mul_ps(r.sz, ckz)));
  // sign = det > 0 ? 1 : -1; multiplying by -1 only flips the sign bit, as the xor below does.
  const __m128 flip = _mm_andnot_ps(front, _mm_set1_ps(-0.0f));
  const __m128 absDet = _mm_xor_ps(det, flip), st = _mm_xor_ps(tScaled, flip);
  const __m128 inRange = _mm_and_ps(_mm_cmpge_ps(st, zero), _mm_cmple_ps(st, _mm_mul_ps(_mm_set1_ps(maxT), absDet)));
  reject = _mm_or_ps(reject, _mm_cmplt_ps(st, zero));
  reject = _mm_or_ps(reject, _mm_cmpgt_ps(st, _mm_mul_ps(_mm_set1_ps(maxT), absDet)));
  // An exactly zero edge function: the scalar test re-evaluates it in double, so it decides.
  reject = _mm_andnot_ps(anyZero, reject);
  const int candidates = ~_mm_movemask_ps(reject) & 0xf;
  // Decided: no zero edge function, both range comparisons true (so nothing is NaN), and t, u, v finite (the mesh
  // raycast requires a finite hit).
  __m128 sure = _mm_andnot_ps(anyZero, _mm_andnot_ps(reject, inRange));
  int decided = _mm_movemask_ps(sure) & candidates;
  if (decided) {
    const __m128 inv = _mm_div_ps(_mm_set1_ps(1.0f), det);
    const __m128 t = _mm_mul_ps(tScaled, inv), u = _mm_mul_ps(ev, inv), v = _mm_mul_ps(ew, inv);
    const __m128 absMask = _mm_castsi128_ps(_mm_set1_epi32(0x7fffffff));
    const __m128 big = _mm_set1_ps(std::numeric_limits<float>::max());
    const __m128 finite = _mm_and_ps(_mm_and_ps(_mm_cmple_ps(_mm_and_ps(t, absMask), big),
                                                _mm_cmple_ps(_mm_and_ps(u, absMask), big)),
                                     _mm_cmple_ps(_mm_and_ps(v, absMask), big));
    decided &= _mm_movemask_ps(finite);
    _mm_store_ps(hits.t, t);
    _mm_store_ps(hits.u, u);
    _mm_store_ps(hits.v, v);
    hits.frontMask = _mm_movemask_ps(front);
  }
  hits.decided = decided;
  return candidates;
#else
  // Scalar build: the scalar test decides every lane it accepts with a finite hit.
  hits.decided = 0;
  hits.frontMask = 0;
  int mask = 0;
  for (int i = 0; i < 4; ++i) {
    const Vec3<float> v0(p.v[0][0][i], p.v[0][1][i], p.v[0][2][i]);
    const Vec3<float> v1(p.v[1][0][i], p.v[1][1][i], p.v[1][2][i]);
    const Vec3<float> v2(p.v[2][0][i], p.v[2][1][i], p.v[2][2][i]);
    TriangleRayHit<float> hit;
    if (!intersectRayTriangle(r.ray, v0, v1, v2, maxT, cullBackFaces, hit)) continue;
    mask |= 1 << i;
    if (std::isfinite(hit.t) && std::isfinite(hit.u) && std::isfinite(hit.v)) {
      hits.decided |= 1 << i;
      hits.t[i] = hit.t;
      hits.u[i] = hit.u;
      hits.v[i] = hit.v;
      hits.frontMask |= int(hit.frontFace) << i;
    }
  }
  return mask;
#endif
}

// Bit i set: the scalar watertight test of triangle i of the packet may accept the ray within [0, maxT].
inline int exactTriangleCandidates(const TriangleVertices4& p, const WatertightRay4& r, float maxT,
                                   bool cullBackFaces) {
  TriangleHits4 hits;
  return exactTriangleHits(p, r, maxT, cullBackFaces, hits);
}

}  // namespace gq::detail
