#pragma once
// The watertight ray/triangle test (mesh/triangle.h, intersectRayTriangle<T>) on the (up to) 4 triangles of a leaf at
// once, in the mesh's own precision: float 4 lanes per SSE register, double 2 (4 per AVX2 register in the AVX2
// walk). Every lane performs the scalar test's
// IEEE operations in the same order on the same inputs, so a lane it rejects is one the scalar test rejects (or,
// with a NaN edge function from overflow, accepts with a NaN hit, which the mesh raycast rejects): no margin and no
// pre-test copy of the triangles are needed. Lanes it cannot decide exactly the same way are kept as candidates for
// the scalar test: an edge function that is exactly zero (the scalar test re-evaluates it in a wider type) and a
// non-finite hit. The triangles are read from the mesh's per-leaf vertex rows (TriangleMesh::leafVertices): one load
// a row, no transpose.
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

// A leaf's triangles as TriangleMesh::leafVertices stores them: row 3 k + a (vertex k, axis a) from rows + (3 k + a)
// stride on, lane i the leaf's triangle i (stride: the leaf's triangle count; the lanes of a 4-lane load past it hold
// the next row's values, which the caller ignores).
template <class T> struct LeafRows {
  const T* rows;
  std::uint32_t stride;
  const T* row(int vertex, int axis) const { return rows + std::size_t(3 * vertex + axis) * stride; }
};

#ifdef GQ_SSE42
// The same SSE operation on float (4 lanes) and double (2 lanes) registers, so one kernel serves both. (Unaligned
// loads: a leaf's rows start wherever its triangle count puts them.)
namespace lanes {
template <class T> struct Reg;
template <> struct Reg<float> {
  using type = __m128;
  static constexpr int kWidth = 4;
  static __m128 load(const float* p) { return _mm_loadu_ps(p); }
  static __m128 set1(float x) { return _mm_set1_ps(x); }
  static void store(float* p, __m128 x) { _mm_store_ps(p, x); }
  static int mask(__m128 x) { return _mm_movemask_ps(x); }
  static __m128 signBit() { return _mm_set1_ps(-0.0f); }
};
template <> struct Reg<double> {
  using type = __m128d;
  static constexpr int kWidth = 2;
  static __m128d load(const double* p) { return _mm_loadu_pd(p); }
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
// halves, so the same bits.
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
inline int exactLanes(const LeafRows<T>& p, const WatertightRay4<T>& r4, int lane0, T maxT,
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
inline int exactTriangleHits(const LeafRows<T>& p, const WatertightRay4<T>& r, T maxT, bool cullBackFaces,
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
    auto vertex = [&](int k) { return Vec3<T>(p.row(k, 0)[i], p.row(k, 1)[i], p.row(k, 2)[i]); };
    const Vec3<T> v0 = vertex(0), v1 = vertex(1), v2 = vertex(2);
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
