#pragma once
// The float watertight ray/triangle test (mesh/triangle.h, intersectRayTriangle<float>) on the 4 triangles of a leaf
// at once (bvh/bvh.h TriangleVertices4). Every lane performs the scalar test's IEEE operations in the same order on
// the same float inputs, so a lane it rejects is one the scalar test rejects: no margin is needed, unlike the
// conservative pre-test of double meshes (bvh/triangle_packet.h). Lanes it cannot decide exactly the same way are
// kept as candidates for the scalar test: an edge function that is exactly zero (the scalar test re-evaluates it in
// double) and any NaN (every comparison fails, so nothing rejects the lane). Accepted lanes get the scalar test,
// which computes the hit.
#include <cstdint>

#include "bvh/bvh.h"
#include "mesh/triangle.h"

#ifdef GQ_SSE42
#include <smmintrin.h>
#endif

namespace gq::detail {

// Per-ray constants: the scalar test's WatertightRay<float> (permuted axes, shear, origin).
struct WatertightRay4 {
  WatertightRay<float> ray;
};

inline WatertightRay4 makeWatertightRay4(const WatertightRay<float>& ray) { return WatertightRay4{ray}; }

// Bit i set: the scalar watertight test of triangle i of the packet may accept the ray within [0, maxT].
inline int exactTriangleCandidates(const TriangleVertices4& p, const WatertightRay4& r, float maxT, bool cullBackFaces) {
  const WatertightRay<float>& ray = r.ray;
#ifdef GQ_SSE42
  const __m128 zero = _mm_setzero_ps();
  const __m128 ox = _mm_set1_ps(ray.org[ray.kx]), oy = _mm_set1_ps(ray.org[ray.ky]), oz = _mm_set1_ps(ray.org[ray.kz]);
  const __m128 sx = _mm_set1_ps(ray.sx), sy = _mm_set1_ps(ray.sy), sz = _mm_set1_ps(ray.sz);
  // a = v0 - org, b = v1 - org, c = v2 - org on the permuted axes, then the shear.
  const __m128 akz = _mm_sub_ps(_mm_load_ps(p.v[0][ray.kz]), oz);
  const __m128 bkz = _mm_sub_ps(_mm_load_ps(p.v[1][ray.kz]), oz);
  const __m128 ckz = _mm_sub_ps(_mm_load_ps(p.v[2][ray.kz]), oz);
  const __m128 ax = _mm_sub_ps(_mm_sub_ps(_mm_load_ps(p.v[0][ray.kx]), ox), _mm_mul_ps(sx, akz));
  const __m128 ay = _mm_sub_ps(_mm_sub_ps(_mm_load_ps(p.v[0][ray.ky]), oy), _mm_mul_ps(sy, akz));
  const __m128 bx = _mm_sub_ps(_mm_sub_ps(_mm_load_ps(p.v[1][ray.kx]), ox), _mm_mul_ps(sx, bkz));
  const __m128 by = _mm_sub_ps(_mm_sub_ps(_mm_load_ps(p.v[1][ray.ky]), oy), _mm_mul_ps(sy, bkz));
  const __m128 cx = _mm_sub_ps(_mm_sub_ps(_mm_load_ps(p.v[2][ray.kx]), ox), _mm_mul_ps(sx, ckz));
  const __m128 cy = _mm_sub_ps(_mm_sub_ps(_mm_load_ps(p.v[2][ray.ky]), oy), _mm_mul_ps(sy, ckz));
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
  if (cullBackFaces) reject = _mm_or_ps(reject, _mm_cmple_ps(det, zero));  // !(det > 0)
  const __m128 tScaled = _mm_add_ps(_mm_add_ps(_mm_mul_ps(eu, _mm_mul_ps(sz, akz)), _mm_mul_ps(ev, _mm_mul_ps(sz, bkz))),
                                    _mm_mul_ps(ew, _mm_mul_ps(sz, ckz)));
  // sign = det > 0 ? 1 : -1; multiplying by -1 only flips the sign bit, as the xor below does.
  const __m128 flip = _mm_andnot_ps(_mm_cmpgt_ps(det, zero), _mm_set1_ps(-0.0f));
  const __m128 absDet = _mm_xor_ps(det, flip), st = _mm_xor_ps(tScaled, flip);
  reject = _mm_or_ps(reject, _mm_cmplt_ps(st, zero));
  reject = _mm_or_ps(reject, _mm_cmpgt_ps(st, _mm_mul_ps(_mm_set1_ps(maxT), absDet)));
  // An exactly zero edge function: the scalar test re-evaluates it in double, so it decides.
  reject = _mm_andnot_ps(anyZero, reject);
  return ~_mm_movemask_ps(reject) & 0xf;
#else
  int mask = 0;
  for (int i = 0; i < 4; ++i) {
    const Vec3<float> v0(p.v[0][0][i], p.v[0][1][i], p.v[0][2][i]);
    const Vec3<float> v1(p.v[1][0][i], p.v[1][1][i], p.v[1][2][i]);
    const Vec3<float> v2(p.v[2][0][i], p.v[2][1][i], p.v[2][2][i]);
    TriangleRayHit<float> hit;
    if (intersectRayTriangle(ray, v0, v1, v2, maxT, cullBackFaces, hit)) mask |= 1 << i;
  }
  return mask;
#endif
}

}  // namespace gq::detail
