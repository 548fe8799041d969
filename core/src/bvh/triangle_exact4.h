#pragma once
// The watertight ray/triangle test (mesh/triangle.h, intersectRayTriangle<T>) on the (up to) 4 triangles of a leaf at
// once, in the mesh's own precision: float 4 lanes per SSE register, double 2 (4 per AVX2 register in the AVX2
// walk). Every lane performs the scalar test's
// IEEE operations in the same order on the same inputs, so a lane it rejects is one the scalar test rejects (or,
// with a NaN edge function from overflow, accepts with a NaN hit, which the mesh raycast rejects): no margin and no
// pre-test copy of the triangles are needed. Lanes it cannot decide exactly the same way are kept as candidates for
// the scalar test: an edge function that is exactly zero (the scalar test re-evaluates it in a wider type) and a
// non-finite hit. The triangles are read from the mesh's
// per-triangle vertex copies (TriangleMesh::triangleVertices, contiguous per leaf) and transposed in registers.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

#include "gq/math.h"
#include "mesh/triangle.h"

#ifdef GQ_SSE42
#include <immintrin.h>
#endif

namespace gq::detail {

// The 4 triangles of a leaf in structure-of-arrays form: v[vertex][axis][lane].
template <class T> struct alignas(16) TriangleVertices4 {
  T v[3][3][4];
};

// Loads `count` (1..4) triangles starting at `tv` (3 vertices each, as TriangleMesh::triangleVertices stores them).
// With `fourReadable` (4 triangles are stored from tv on) the lanes past count hold the following triangles and the
// caller ignores them; otherwise they are zero.
inline void loadTriangles4(const Vec3<float>* tv, std::uint32_t count, bool fourReadable, TriangleVertices4<float>& out) {
#ifdef GQ_SSE42
  if (fourReadable) {
    // Triangle i is 9 floats: components 0-3, 4-7 and 8, each group transposed to 4 lanes.
    const float* f = tv->data();
    __m128 a0 = _mm_loadu_ps(f), a1 = _mm_loadu_ps(f + 9), a2 = _mm_loadu_ps(f + 18), a3 = _mm_loadu_ps(f + 27);
    __m128 b0 = _mm_loadu_ps(f + 4), b1 = _mm_loadu_ps(f + 13), b2 = _mm_loadu_ps(f + 22), b3 = _mm_loadu_ps(f + 31);
    _MM_TRANSPOSE4_PS(a0, a1, a2, a3);
    _MM_TRANSPOSE4_PS(b0, b1, b2, b3);
    const __m128 c01 = _mm_unpacklo_ps(_mm_load_ss(f + 8), _mm_load_ss(f + 17));
    const __m128 c23 = _mm_unpacklo_ps(_mm_load_ss(f + 26), _mm_load_ss(f + 35));
    float* o = &out.v[0][0][0];
    _mm_store_ps(o, a0); _mm_store_ps(o + 4, a1); _mm_store_ps(o + 8, a2); _mm_store_ps(o + 12, a3);
    _mm_store_ps(o + 16, b0); _mm_store_ps(o + 20, b1); _mm_store_ps(o + 24, b2); _mm_store_ps(o + 28, b3);
    _mm_store_ps(o + 32, _mm_movelh_ps(c01, c23));
    return;
  }
#else
  (void)fourReadable;
#endif
  out = TriangleVertices4<float>{};
  for (std::uint32_t i = 0; i < count; ++i)
    for (int k = 0; k < 3; ++k)
      for (int a = 0; a < 3; ++a) out.v[k][a][i] = tv[3 * i + std::uint32_t(k)][a];
}

#ifdef GQ_SSE42
// loadTriangles4 of 4 stored float triangles with 256-bit loads, for the AVX2 walk: triangle i's first 8 floats in one
// register, the 4 registers transposed two rows at a time (rows r and r + 4 share a register), the 9th floats gathered
// apart. The same values as loadTriangles4 (25 instructions instead of 37).
__attribute__((target("avx2"))) inline void loadFourTriangles4Avx2(const Vec3<float>* tv,
                                                                  TriangleVertices4<float>& out) {
  const float* f = tv->data();
  const __m256 r0 = _mm256_loadu_ps(f), r1 = _mm256_loadu_ps(f + 9), r2 = _mm256_loadu_ps(f + 18),
               r3 = _mm256_loadu_ps(f + 27);
  const __m256 lo01 = _mm256_unpacklo_ps(r0, r1), hi01 = _mm256_unpackhi_ps(r0, r1);
  const __m256 lo23 = _mm256_unpacklo_ps(r2, r3), hi23 = _mm256_unpackhi_ps(r2, r3);
  // (Casts, not a lambda: a lambda does not inherit the target attribute.)
  const __m256d l01 = _mm256_castps_pd(lo01), l23 = _mm256_castps_pd(lo23);
  const __m256d h01 = _mm256_castps_pd(hi01), h23 = _mm256_castps_pd(hi23);
  const __m256 rows04 = _mm256_castpd_ps(_mm256_unpacklo_pd(l01, l23));
  const __m256 rows15 = _mm256_castpd_ps(_mm256_unpackhi_pd(l01, l23));
  const __m256 rows26 = _mm256_castpd_ps(_mm256_unpacklo_pd(h01, h23));
  const __m256 rows37 = _mm256_castpd_ps(_mm256_unpackhi_pd(h01, h23));
  float* o = &out.v[0][0][0];  // row r (vertex r / 3, axis r % 3) at o + 4 r
  _mm_store_ps(o, _mm256_castps256_ps128(rows04));
  _mm_store_ps(o + 4, _mm256_castps256_ps128(rows15));
  _mm_store_ps(o + 8, _mm256_castps256_ps128(rows26));
  _mm_store_ps(o + 12, _mm256_castps256_ps128(rows37));
  _mm_store_ps(o + 16, _mm256_extractf128_ps(rows04, 1));
  _mm_store_ps(o + 20, _mm256_extractf128_ps(rows15, 1));
  _mm_store_ps(o + 24, _mm256_extractf128_ps(rows26, 1));
  _mm_store_ps(o + 28, _mm256_extractf128_ps(rows37, 1));
  _mm_store_ps(o + 32, _mm_setr_ps(f[8], f[17], f[26], f[35]));
}
#endif

inline void loadTriangles4(const Vec3<double>* tv, std::uint32_t count, bool fourReadable,
                           TriangleVertices4<double>& out) {
#ifdef GQ_SSE42
  if (fourReadable) {
    // Triangle i is 9 doubles; two triangles at a time, two components per load.
    const double* d = tv->data();
    double* o = &out.v[0][0][0];
    for (int pair = 0; pair < 2; ++pair) {
      const double* p = d + 18 * pair;
      double* q = o + 2 * pair;
      for (int k = 0; k < 8; k += 2) {
        const __m128d x = _mm_loadu_pd(p + k), y = _mm_loadu_pd(p + 9 + k);
        _mm_store_pd(q + 4 * k, _mm_unpacklo_pd(x, y));
        _mm_store_pd(q + 4 * (k + 1), _mm_unpackhi_pd(x, y));
      }
      _mm_store_pd(q + 32, _mm_loadh_pd(_mm_load_sd(p + 8), p + 17));
    }
    return;
  }
#else
  (void)fourReadable;
#endif
  out = TriangleVertices4<double>{};
  for (std::uint32_t i = 0; i < count; ++i)
    for (int k = 0; k < 3; ++k)
      for (int a = 0; a < 3; ++a) out.v[k][a][i] = tv[3 * i + std::uint32_t(k)][a];
}

#ifdef GQ_SSE42
// loadTriangles4 of 4 stored double triangles for the AVX2 walk: each triangle's 9 doubles as rows 0-3, 4-7 and 8;
// two 4 x 4 transposes (unpacks, then 128-bit halves exchanged) give whole rows. The same values as loadTriangles4.
__attribute__((target("avx2"))) inline void loadFourTriangles4Avx2(const Vec3<double>* tv,
                                                                  TriangleVertices4<double>& out) {
  const double* d = tv->data();
  double* o = &out.v[0][0][0];  // row r (vertex r / 3, axis r % 3) at o + 4 r
  for (int half = 0; half < 2; ++half) {  // rows 0-3 from each triangle's doubles 0-3, rows 4-7 from 4-7
    const __m256d a0 = _mm256_loadu_pd(d + 4 * half), a1 = _mm256_loadu_pd(d + 9 + 4 * half);
    const __m256d a2 = _mm256_loadu_pd(d + 18 + 4 * half), a3 = _mm256_loadu_pd(d + 27 + 4 * half);
    const __m256d lo01 = _mm256_unpacklo_pd(a0, a1), hi01 = _mm256_unpackhi_pd(a0, a1);
    const __m256d lo23 = _mm256_unpacklo_pd(a2, a3), hi23 = _mm256_unpackhi_pd(a2, a3);
    double* q = o + 16 * half;
    _mm256_storeu_pd(q, _mm256_permute2f128_pd(lo01, lo23, 0x20));
    _mm256_storeu_pd(q + 4, _mm256_permute2f128_pd(hi01, hi23, 0x20));
    _mm256_storeu_pd(q + 8, _mm256_permute2f128_pd(lo01, lo23, 0x31));
    _mm256_storeu_pd(q + 12, _mm256_permute2f128_pd(hi01, hi23, 0x31));
  }
  _mm256_storeu_pd(o + 32, _mm256_setr_pd(d[8], d[17], d[26], d[35]));
}
#endif

#ifdef GQ_SSE42
// The same SSE operation on float (4 lanes) and double (2 lanes) registers, so one kernel serves both.
namespace lanes {
template <class T> struct Reg;
template <> struct Reg<float> {
  using type = __m128;
  static constexpr int kWidth = 4;
  static __m128 load(const float* p) { return _mm_load_ps(p); }
  static __m128 set1(float x) { return _mm_set1_ps(x); }
  static void store(float* p, __m128 x) { _mm_store_ps(p, x); }
  static int mask(__m128 x) { return _mm_movemask_ps(x); }
  static __m128 signBit() { return _mm_set1_ps(-0.0f); }
};
template <> struct Reg<double> {
  using type = __m128d;
  static constexpr int kWidth = 2;
  static __m128d load(const double* p) { return _mm_load_pd(p); }
  static __m128d set1(double x) { return _mm_set1_pd(x); }
  static void store(double* p, __m128d x) { _mm_store_pd(p, x); }
  static int mask(__m128d x) { return _mm_movemask_pd(x); }
  static __m128d signBit() { return _mm_set1_pd(-0.0); }
};
inline __m128 add(__m128 a, __m128 b) { return _mm_add_ps(a, b); }
inline __m128d add(__m128d a, __m128d b) { return _mm_add_pd(a, b); }
inline __m128 sub(__m128 a, __m128 b) { return _mm_sub_ps(a, b); }
inline __m128d sub(__m128d a, __m128d b) { return _mm_sub_pd(a, b); }
inline __m128 mul(__m128 a, __m128 b) { return _mm_mul_ps(a, b); }
inline __m128d mul(__m128d a, __m128d b) { return _mm_mul_pd(a, b); }
inline __m128 div(__m128 a, __m128 b) { return _mm_div_ps(a, b); }
inline __m128d div(__m128d a, __m128d b) { return _mm_div_pd(a, b); }
inline __m128 bitOr(__m128 a, __m128 b) { return _mm_or_ps(a, b); }
inline __m128d bitOr(__m128d a, __m128d b) { return _mm_or_pd(a, b); }
inline __m128 bitAnd(__m128 a, __m128 b) { return _mm_and_ps(a, b); }
inline __m128d bitAnd(__m128d a, __m128d b) { return _mm_and_pd(a, b); }
inline __m128 andNot(__m128 a, __m128 b) { return _mm_andnot_ps(a, b); }  // ~a & b
inline __m128d andNot(__m128d a, __m128d b) { return _mm_andnot_pd(a, b); }
inline __m128 bitXor(__m128 a, __m128 b) { return _mm_xor_ps(a, b); }
inline __m128d bitXor(__m128d a, __m128d b) { return _mm_xor_pd(a, b); }
inline __m128 eq(__m128 a, __m128 b) { return _mm_cmpeq_ps(a, b); }
inline __m128d eq(__m128d a, __m128d b) { return _mm_cmpeq_pd(a, b); }
inline __m128 lt(__m128 a, __m128 b) { return _mm_cmplt_ps(a, b); }
inline __m128d lt(__m128d a, __m128d b) { return _mm_cmplt_pd(a, b); }
inline __m128 le(__m128 a, __m128 b) { return _mm_cmple_ps(a, b); }
inline __m128d le(__m128d a, __m128d b) { return _mm_cmple_pd(a, b); }

// Double on 4 lanes with AVX2, for the AVX2 walk (only on CPUs that have it): the same operations as Reg<double>'s two
// halves, so the same bits. (Unaligned loads and stores: the leaf arrays are 16-byte aligned.)
struct Reg256d {
  using type = __m256d;
  static constexpr int kWidth = 4;
  __attribute__((target("avx2"))) static __m256d load(const double* p) { return _mm256_loadu_pd(p); }
  __attribute__((target("avx2"))) static __m256d set1(double x) { return _mm256_set1_pd(x); }
  __attribute__((target("avx2"))) static void store(double* p, __m256d x) { _mm256_storeu_pd(p, x); }
  __attribute__((target("avx2"))) static int mask(__m256d x) { return _mm256_movemask_pd(x); }
  __attribute__((target("avx2"))) static __m256d signBit() { return _mm256_set1_pd(-0.0); }
};
#define GQ_AVX2 __attribute__((target("avx2")))
GQ_AVX2 inline __m256d add(__m256d a, __m256d b) { return _mm256_add_pd(a, b); }
GQ_AVX2 inline __m256d sub(__m256d a, __m256d b) { return _mm256_sub_pd(a, b); }
GQ_AVX2 inline __m256d mul(__m256d a, __m256d b) { return _mm256_mul_pd(a, b); }
GQ_AVX2 inline __m256d div(__m256d a, __m256d b) { return _mm256_div_pd(a, b); }
GQ_AVX2 inline __m256d bitOr(__m256d a, __m256d b) { return _mm256_or_pd(a, b); }
GQ_AVX2 inline __m256d bitAnd(__m256d a, __m256d b) { return _mm256_and_pd(a, b); }
GQ_AVX2 inline __m256d andNot(__m256d a, __m256d b) { return _mm256_andnot_pd(a, b); }
GQ_AVX2 inline __m256d bitXor(__m256d a, __m256d b) { return _mm256_xor_pd(a, b); }
// The SSE compares' predicates: cmpeq is EQ_OQ, cmplt LT_OS, cmple LE_OS (false on NaN, as here).
GQ_AVX2 inline __m256d eq(__m256d a, __m256d b) { return _mm256_cmp_pd(a, b, _CMP_EQ_OQ); }
GQ_AVX2 inline __m256d lt(__m256d a, __m256d b) { return _mm256_cmp_pd(a, b, _CMP_LT_OS); }
GQ_AVX2 inline __m256d le(__m256d a, __m256d b) { return _mm256_cmp_pd(a, b, _CMP_LE_OS); }
#undef GQ_AVX2
}  // namespace lanes
#endif

// Per-ray constants: the scalar test's WatertightRay<T> (permuted axes, shear, origin) and its origin on the permuted
// axes, which the wide test broadcasts from memory at a leaf (one instruction a value with AVX; registers held for the
// whole ray were stores in every ray's setup and loads at every leaf all the same).
template <class T> struct WatertightRay4 {
  WatertightRay<T> ray;
  T ox, oy, oz;  // ray.org[ray.kx], ray.org[ray.ky], ray.org[ray.kz]
};

// Forced inline (as the mesh kernel's ray constants): GCC left it out of line once the kernel had two instances.
template <class T>
[[gnu::always_inline]] inline WatertightRay4<T> makeWatertightRay4(const WatertightRay<T>& ray) {
  return WatertightRay4<T>{ray, ray.org[ray.kx], ray.org[ray.ky], ray.org[ray.kz]};
}

#ifdef GQ_SSE42
namespace watertight_sse {
// Per (kz, negative dominant component): the byte shuffle taking (x, y, z, -) to (0, v[kx], v[ky], v[kz]), and
// kx, ky, kz as makeWatertightRay picks them (kx = kz + 1 mod 3, ky = kx + 1 mod 3, swapped when negative).
struct Axes {
  alignas(16) std::int8_t shuffle[16];
  alignas(16) std::int32_t k[4];
};
constexpr Axes axes(int kz, bool negative) {
  int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
  if (negative) {
    const int t = kx;
    kx = ky;
    ky = t;
  }
  Axes a{};
  const int from[4] = {-1, kx, ky, kz};
  for (int lane = 0; lane < 4; ++lane)
    for (int b = 0; b < 4; ++b)
      a.shuffle[4 * lane + b] = from[lane] < 0 ? std::int8_t(-128) : std::int8_t(4 * from[lane] + b);
  a.k[0] = kx;
  a.k[1] = ky;
  a.k[2] = kz;
  return a;
}
inline constexpr Axes kAxes[6] = {axes(0, false), axes(0, true),  axes(1, false),
                                  axes(1, true),  axes(2, false), axes(2, true)};
}  // namespace watertight_sse

// makeWatertightRay4(makeWatertightRay(org, dir)) for float in SSE registers, bit for bit: the same dominant axis
// (x if |x| exceeds |y| and |z|, else y if |y| exceeds |z|, else z), the same swap (by the sign bit of dir[kz], which
// is dir[kz] < 0 for any direction but a zero or NaN one), and sx, sy, sz as the same correctly rounded divisions
// (one 4-lane division). o and d: x, y, z in lanes 0-2. The result is written as three rows of 16 bytes.
[[gnu::always_inline]] inline WatertightRay4<float> makeWatertightRay4Sse(__m128 o, __m128 d) {
  using Ray4 = WatertightRay4<float>;
  static_assert(std::is_standard_layout_v<Ray4> && sizeof(Ray4) == 48 && offsetof(Ray4, ray.kx) == 12 &&
                    offsetof(Ray4, ray.sx) == 24 && offsetof(Ray4, ox) == 36,
                "three 16-byte rows: org kx | ky kz sx sy | sz ox oy oz");
  const __m128 a = _mm_andnot_ps(_mm_set1_ps(-0.0f), d);
  const int gtNext = _mm_movemask_ps(_mm_cmpgt_ps(a, _mm_shuffle_ps(a, a, _MM_SHUFFLE(3, 0, 2, 1))));  // x>y y>z z>x
  const int xGtZ = _mm_movemask_ps(_mm_cmpgt_ps(a, _mm_shuffle_ps(a, a, _MM_SHUFFLE(3, 1, 0, 2)))) & 1;
  const int xWins = gtNext & xGtZ & 1, yWins = ~gtNext & (gtNext >> 1) & 1;
  const int kz = 2 - 2 * xWins - yWins;
  const int negative = (_mm_movemask_ps(d) >> kz) & 1;
  const watertight_sse::Axes& ax = watertight_sse::kAxes[2 * kz + negative];
  const __m128i shuffle = _mm_load_si128(reinterpret_cast<const __m128i*>(ax.shuffle));
  const __m128 dp = _mm_castsi128_ps(_mm_shuffle_epi8(_mm_castps_si128(d), shuffle));  // 0 dkx dky dkz
  const __m128 op = _mm_castsi128_ps(_mm_shuffle_epi8(_mm_castps_si128(o), shuffle));  // 0 okx oky okz
  // (1, dkx, dky, dkz) / dkz: sz, sx, sy in lanes 0-2.
  const __m128 s = _mm_div_ps(_mm_blend_ps(dp, _mm_set1_ps(1.0f), 1), _mm_shuffle_ps(dp, dp, _MM_SHUFFLE(3, 3, 3, 3)));
  const __m128 k = _mm_load_ps(reinterpret_cast<const float*>(ax.k));
  const __m128 row0 = _mm_insert_ps(o, k, 0x30);                       // org.x org.y org.z kx
  const __m128 row1 = _mm_shuffle_ps(k, s, _MM_SHUFFLE(2, 1, 2, 1));   // ky kz sx sy
  const __m128 row2 = _mm_blend_ps(op, s, 1);                          // sz ox oy oz
  WatertightRay4<float> r;
  std::memcpy(reinterpret_cast<char*>(&r), &row0, 16);
  std::memcpy(reinterpret_cast<char*>(&r) + 16, &row1, 16);
  std::memcpy(reinterpret_cast<char*>(&r) + 32, &row2, 16);
  return r;
}
#endif

// The hits of the lanes the wide test decides alone (bit i of `decided`): the scalar test's t, u, v and side, bit for
// bit (the same IEEE operations: 1 / det, then products). Other candidate lanes need the scalar test.
template <class T> struct TriangleHits4 {
  int decided = 0;
  alignas(16) T t[4], u[4], v[4];
  int frontMask = 0;  // bit i: lane i was hit on its front face
};

#ifdef GQ_SSE42
namespace lanes {
// The wide test for registers R, compiled for the baseline (exactLanesWith) and for AVX2 as a whole (exactLanesAvx2,
// the 256-bit double form, called only on CPUs with AVX2).
#define GQ_EXACT_LANES_NAME exactLanesWith
#define GQ_EXACT_LANES_TARGET
#include "bvh/triangle_exact4_lanes.inc"
#undef GQ_EXACT_LANES_NAME
#undef GQ_EXACT_LANES_TARGET
#define GQ_EXACT_LANES_NAME exactLanesAvx2
#define GQ_EXACT_LANES_TARGET __attribute__((target("avx2")))
#include "bvh/triangle_exact4_lanes.inc"
#undef GQ_EXACT_LANES_NAME
#undef GQ_EXACT_LANES_TARGET

// The SSE form (float 4 lanes, double 2).
template <class T>
inline int exactLanes(const TriangleVertices4<T>& p, const WatertightRay4<T>& r4, int lane0, T maxT,
                      bool cullBackFaces, TriangleHits4<T>& hits) {
  return exactLanesWith<T, Reg<T>>(p, r4, lane0, maxT, cullBackFaces, hits);
}
}  // namespace lanes
#endif

// Bit i set: the scalar watertight test of triangle i of the leaf may accept the ray within [0, maxT]. A candidate
// lane without an exactly zero edge function and with a finite hit is decided here: the scalar test accepts it with
// the hit written to `hits` (bit i of hits.decided).
// kAvx2 (callers on CPUs with AVX2): double lanes 4 to a register instead of 2.
template <class T, bool kAvx2 = false>
inline int exactTriangleHits(const TriangleVertices4<T>& p, const WatertightRay4<T>& r, T maxT, bool cullBackFaces,
                             TriangleHits4<T>& hits) {
  hits.decided = 0;
  hits.frontMask = 0;
#ifdef GQ_SSE42
  if constexpr (kAvx2 && std::is_same_v<T, double>) {
    return lanes::exactLanesAvx2<T, lanes::Reg256d>(p, r, 0, maxT, cullBackFaces, hits);
  } else {
    int mask = 0;
    for (int lane0 = 0; lane0 < 4; lane0 += lanes::Reg<T>::kWidth)
      mask |= lanes::exactLanes(p, r, lane0, maxT, cullBackFaces, hits);
    return mask;
  }
#else
  // Scalar build: the scalar test decides every lane it accepts with a finite hit.
  int mask = 0;
  for (int i = 0; i < 4; ++i) {
    const Vec3<T> v0(p.v[0][0][i], p.v[0][1][i], p.v[0][2][i]);
    const Vec3<T> v1(p.v[1][0][i], p.v[1][1][i], p.v[1][2][i]);
    const Vec3<T> v2(p.v[2][0][i], p.v[2][1][i], p.v[2][2][i]);
    TriangleRayHit<T> hit;
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

}  // namespace gq::detail
