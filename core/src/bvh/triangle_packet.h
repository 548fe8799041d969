#pragma once
// Conservative SIMD pre-test of a ray against the (up to) 4 triangles of a leaf packet (bvh/bvh.h TrianglePacket4),
// in float. It only decides which triangles need the exact watertight test in T (mesh/triangle.h): a triangle that
// the exact test would hit is never rejected, so results stay exact in float and double.
//
// Math (Möller–Trumbore, unnormalized): s = o - v0, p = d x e2, q = s x e1,
//   det = e1.p, u = s.p, v = d.q, t = e2.q; hit iff u/det >= 0, v/det >= 0, (u+v)/det <= 1, 0 <= t/det <= tMax.
// Each quantity is compared with a margin that bounds (a) its float rounding, including the rounding of o, d and the
// triangle data to float, and (b) the rounding of the exact test in T. That test shears the vertices relative to the
// ray origin into 2D coordinates (their offsets across the ray, bounded by P) with an absolute error ~eps_T Qs, so its
// edge functions err by ~eps_T Qs P. With D = |d|_1, L = max(|e1|_1, |e2|_1), Q = |o|_1 + |v0|_1 + 2L (bounds the
// float data), Qs = |s|_1 + 2L + 4 eps_f Q (bounds the vertex offsets from the origin) and
// P = 3 (|s x d|_1 + 4 eps_f Qs D) / D + 4L (bounds the 2D offsets across the ray, kz being the dominant axis):
//   margin(u), margin(v) = K D (eps_f Q L + eps_T Qs P)     margin(det) = K D (eps_f L^2 + eps_T Qs P)
//   margin(t)            = K (1 + D) Q (eps_f L^2 + eps_T Qs P)
// K = kPacketMarginFactor is several times the operation count of either test. Any NaN accepts the lane.
#include <cmath>
#include <cstdint>
#include <limits>

#include "bvh/bvh.h"
#include "gq/math.h"

#ifdef GQ_SSE42
#include <smmintrin.h>
#endif

namespace gq::detail {

inline constexpr float kPacketMarginFactor = 32.0f;

// Per-ray constants of the pre-test.
struct PacketRay {
  float org[3], dir[3];
  float orgNorm1;  // |o|_1
  float dirNorm1;  // |d|_1
  float acrossScale;  // 3 / |d|_1, for P
  float epsT;      // unit roundoff of the exact test's scalar type
};

template <class T> inline PacketRay makePacketRay(const Vec3<T>& org, const Vec3<T>& dir) {
  PacketRay r;
  r.orgNorm1 = 0.0f;
  r.dirNorm1 = 0.0f;
  for (int i = 0; i < 3; ++i) {
    r.org[i] = static_cast<float>(org[i]);
    r.dir[i] = static_cast<float>(dir[i]);
    r.orgNorm1 += std::abs(r.org[i]);
    r.dirNorm1 += std::abs(r.dir[i]);
  }
  // Rounded sums: pad by a relative few ulps so the norms are upper bounds.
  r.orgNorm1 *= 1.0f + 8.0f * std::numeric_limits<float>::epsilon();
  r.dirNorm1 *= 1.0f + 8.0f * std::numeric_limits<float>::epsilon();
  r.acrossScale = 3.0f / r.dirNorm1;
  r.epsT = static_cast<float>(std::numeric_limits<T>::epsilon());
  return r;
}

// Bit i set: triangle i of the packet may be hit within [0, tMax] (tMax > 0) and must get the exact test.
// cullBackFaces drops lanes whose determinant is clearly negative (normal along the ray).
inline int packetCandidates(const TrianglePacket4& p, const PacketRay& ray, float tMax, bool cullBackFaces) {
  constexpr float kEpsF = std::numeric_limits<float>::epsilon();
  constexpr float kK = kPacketMarginFactor;
#ifdef GQ_SSE42
  const __m128 absMask = _mm_castsi128_ps(_mm_set1_epi32(0x7fffffff));
  const __m128 signMask = _mm_castsi128_ps(_mm_set1_epi32(int(0x80000000u)));
  auto abs = [&](__m128 x) { return _mm_and_ps(x, absMask); };
  auto mul = [](__m128 a, __m128 b) { return _mm_mul_ps(a, b); };
  auto add = [](__m128 a, __m128 b) { return _mm_add_ps(a, b); };
  auto sub = [](__m128 a, __m128 b) { return _mm_sub_ps(a, b); };
  const __m128 dx = _mm_set1_ps(ray.dir[0]), dy = _mm_set1_ps(ray.dir[1]), dz = _mm_set1_ps(ray.dir[2]);
  const __m128 v0x = _mm_load_ps(p.v0x), v0y = _mm_load_ps(p.v0y), v0z = _mm_load_ps(p.v0z);
  const __m128 e1x = _mm_load_ps(p.e1x), e1y = _mm_load_ps(p.e1y), e1z = _mm_load_ps(p.e1z);
  const __m128 e2x = _mm_load_ps(p.e2x), e2y = _mm_load_ps(p.e2y), e2z = _mm_load_ps(p.e2z);
  const __m128 sx = sub(_mm_set1_ps(ray.org[0]), v0x), sy = sub(_mm_set1_ps(ray.org[1]), v0y),
               sz = sub(_mm_set1_ps(ray.org[2]), v0z);
  // p = d x e2, q = s x e1
  const __m128 px = sub(mul(dy, e2z), mul(dz, e2y)), py = sub(mul(dz, e2x), mul(dx, e2z)),
               pz = sub(mul(dx, e2y), mul(dy, e2x));
  const __m128 qx = sub(mul(sy, e1z), mul(sz, e1y)), qy = sub(mul(sz, e1x), mul(sx, e1z)),
               qz = sub(mul(sx, e1y), mul(sy, e1x));
  const __m128 det = add(add(mul(e1x, px), mul(e1y, py)), mul(e1z, pz));
  const __m128 u = add(add(mul(sx, px), mul(sy, py)), mul(sz, pz));
  const __m128 v = add(add(mul(dx, qx), mul(dy, qy)), mul(dz, qz));
  const __m128 t = add(add(mul(e2x, qx), mul(e2y, qy)), mul(e2z, qz));
  // Margins (see the header comment).
  const __m128 epsF = _mm_set1_ps(kEpsF), epsT = _mm_set1_ps(ray.epsT);
  auto norm1 = [&](__m128 x, __m128 y, __m128 z) { return add(add(abs(x), abs(y)), abs(z)); };
  const __m128 len = _mm_max_ps(norm1(e1x, e1y, e1z), norm1(e2x, e2y, e2z));
  const __m128 len2 = add(len, len);
  const __m128 q = add(add(_mm_set1_ps(ray.orgNorm1), norm1(v0x, v0y, v0z)), len2);
  const __m128 qs = add(add(norm1(sx, sy, sz), len2), mul(_mm_set1_ps(4.0f * kEpsF), q));
  const __m128 sdx = sub(mul(sy, dz), mul(sz, dy)), sdy = sub(mul(sz, dx), mul(sx, dz)),
               sdz = sub(mul(sx, dy), mul(sy, dx));
  const __m128 across = add(norm1(sdx, sdy, sdz), mul(_mm_set1_ps(4.0f * kEpsF * ray.dirNorm1), qs));
  const __m128 pBound = add(mul(_mm_set1_ps(ray.acrossScale), across), add(len2, len2));
  const __m128 exact = mul(epsT, mul(qs, pBound));
  const __m128 kd = _mm_set1_ps(kK * ray.dirNorm1);
  const __m128 marginU = mul(kd, add(mul(epsF, mul(q, len)), exact));
  const __m128 sq = add(mul(epsF, mul(len, len)), exact);
  const __m128 marginDet = mul(kd, sq);
  const __m128 marginT = mul(mul(_mm_set1_ps(kK * (1.0f + ray.dirNorm1)), q), sq);
  // Fold the sign of det into u, v, t.
  const __m128 detSign = _mm_and_ps(det, signMask);
  const __m128 su = _mm_xor_ps(u, detSign), sv = _mm_xor_ps(v, detSign), st = _mm_xor_ps(t, detSign);
  const __m128 absDet = abs(det);
  const __m128 negMu = _mm_xor_ps(marginU, signMask);
  __m128 reject = _mm_or_ps(_mm_cmplt_ps(su, negMu), _mm_cmplt_ps(sv, negMu));
  reject = _mm_or_ps(reject, _mm_cmpgt_ps(add(su, sv), add(absDet, add(add(marginU, marginU), marginDet))));
  reject = _mm_or_ps(reject, _mm_cmplt_ps(st, _mm_xor_ps(marginT, signMask)));
  reject = _mm_or_ps(reject, _mm_cmpgt_ps(st, add(mul(_mm_set1_ps(tMax), add(absDet, marginDet)), marginT)));
  // Nearly parallel rays (|det| within its margin) always go to the exact test.
  reject = _mm_andnot_ps(_mm_cmple_ps(absDet, marginDet), reject);
  if (cullBackFaces) reject = _mm_or_ps(reject, _mm_cmplt_ps(det, _mm_xor_ps(marginDet, signMask)));
  return ~_mm_movemask_ps(reject) & 0xf;
#else
  int mask = 0;
  for (int i = 0; i < 4; ++i) {
    const float e1[3] = {p.e1x[i], p.e1y[i], p.e1z[i]}, e2[3] = {p.e2x[i], p.e2y[i], p.e2z[i]};
    const float s[3] = {ray.org[0] - p.v0x[i], ray.org[1] - p.v0y[i], ray.org[2] - p.v0z[i]};
    const float* d = ray.dir;
    const float pv[3] = {d[1] * e2[2] - d[2] * e2[1], d[2] * e2[0] - d[0] * e2[2], d[0] * e2[1] - d[1] * e2[0]};
    const float qv[3] = {s[1] * e1[2] - s[2] * e1[1], s[2] * e1[0] - s[0] * e1[2], s[0] * e1[1] - s[1] * e1[0]};
    const float det = e1[0] * pv[0] + e1[1] * pv[1] + e1[2] * pv[2];
    const float u = s[0] * pv[0] + s[1] * pv[1] + s[2] * pv[2];
    const float v = d[0] * qv[0] + d[1] * qv[1] + d[2] * qv[2];
    const float t = e2[0] * qv[0] + e2[1] * qv[1] + e2[2] * qv[2];
    const float len = std::max(std::abs(e1[0]) + std::abs(e1[1]) + std::abs(e1[2]),
                               std::abs(e2[0]) + std::abs(e2[1]) + std::abs(e2[2]));
    const float q = ray.orgNorm1 + std::abs(p.v0x[i]) + std::abs(p.v0y[i]) + std::abs(p.v0z[i]) + 2.0f * len;
    const float qs = std::abs(s[0]) + std::abs(s[1]) + std::abs(s[2]) + 2.0f * len + 4.0f * kEpsF * q;
    const float sd[3] = {s[1] * d[2] - s[2] * d[1], s[2] * d[0] - s[0] * d[2], s[0] * d[1] - s[1] * d[0]};
    const float across = std::abs(sd[0]) + std::abs(sd[1]) + std::abs(sd[2]) + 4.0f * kEpsF * ray.dirNorm1 * qs;
    const float pBound = ray.acrossScale * across + 4.0f * len;
    const float exact = ray.epsT * qs * pBound;
    const float sq = kEpsF * len * len + exact;
    const float marginU = kK * ray.dirNorm1 * (kEpsF * q * len + exact);
    const float marginDet = kK * ray.dirNorm1 * sq;
    const float marginT = kK * (1.0f + ray.dirNorm1) * q * sq;
    const float sign = std::signbit(det) ? -1.0f : 1.0f;
    const float su = sign * u, sv = sign * v, st = sign * t, absDet = std::abs(det);
    bool reject = su < -marginU || sv < -marginU || su + sv > absDet + 2.0f * marginU + marginDet ||
                  st < -marginT || st > tMax * (absDet + marginDet) + marginT;
    if (absDet <= marginDet) reject = false;
    if (cullBackFaces && det < -marginDet) reject = true;
    if (!reject) mask |= 1 << i;
  }
  return mask;
#endif
}

}  // namespace gq::detail
