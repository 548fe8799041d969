#pragma once
// The watertight ray/triangle test (mesh/triangle.h, intersectRayTriangle<T>) on the (up to) 4 triangles of a leaf at
// once, in the mesh's own precision: float 4 lanes per SSE register, double 2. Every lane performs the scalar test's
// IEEE operations in the same order on the same inputs, so a lane it rejects is one the scalar test rejects (or,
// with a NaN edge function from overflow, accepts with a NaN hit, which the mesh raycast rejects): no margin and no
// pre-test copy of the triangles are needed. Lanes it cannot decide exactly the same way are kept as candidates for
// the scalar test: an edge function that is exactly zero (the scalar test re-evaluates it in a wider type) and a
// non-finite hit. The triangles are read from the mesh's
// per-triangle vertex copies (TriangleMesh::triangleVertices, contiguous per leaf) and transposed in registers.
#include <cmath>
#include <cstdint>
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

// Per-ray constants: the scalar test's WatertightRay<T> (permuted axes, shear, origin), and its origin and shear on
// the permuted axes broadcast to the lanes once per ray.
template <class T> struct WatertightRay4 {
  WatertightRay<T> ray;
#ifdef GQ_SSE42
  typename lanes::Reg<T>::type ox, oy, oz, sx, sy, sz;
#endif
};

template <class T> inline WatertightRay4<T> makeWatertightRay4(const WatertightRay<T>& ray) {
  WatertightRay4<T> r;
  r.ray = ray;
#ifdef GQ_SSE42
  using R = lanes::Reg<T>;
  r.ox = R::set1(ray.org[ray.kx]);
  r.oy = R::set1(ray.org[ray.ky]);
  r.oz = R::set1(ray.org[ray.kz]);
  r.sx = R::set1(ray.sx);
  r.sy = R::set1(ray.sy);
  r.sz = R::set1(ray.sz);
#endif
  return r;
}

// The hits of the lanes the wide test decides alone (bit i of `decided`): the scalar test's t, u, v and side, bit for
// bit (the same IEEE operations: 1 / det, then products). Other candidate lanes need the scalar test.
template <class T> struct TriangleHits4 {
  int decided = 0;
  alignas(16) T t[4], u[4], v[4];
  int frontMask = 0;  // bit i: lane i was hit on its front face
};

#ifdef GQ_SSE42
namespace lanes {
// Lanes [lane0, lane0 + width) of the wide test: returns their candidate bits (shifted to lane0) and adds the decided
// and front-face bits to `hits`.
// With R = Reg256d (256-bit vectors) rayLanes and exactLanes are instantiated only inside the AVX2 walk, which GCC
// inlines whole (flatten): their vectors never cross a call between AVX and non-AVX code, which the ABI warning is
// about. Clang compiles every function for its own target whatever it is inlined into and rejects 256-bit vectors in
// these generic functions, so under clang the AVX2 walk tests double leaves as two SSE halves (the same bits).
#if defined(__clang__)
inline constexpr bool kAvx2DoubleLeaves = false;
#else
inline constexpr bool kAvx2DoubleLeaves = true;
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"
#endif
// The ray's origin and shear on the permuted axes in registers of R: the per-ray broadcasts, or (other widths)
// broadcast here from the scalar constants.
template <class R> struct RayLanes {
  typename R::type ox, oy, oz, sx, sy, sz;
};
// (Written to `out`, not returned: a 256-bit vector returned by a function compiled without AVX changes the ABI.)
template <class R, class T> inline void rayLanes(const WatertightRay4<T>& r, RayLanes<R>& out) {
  if constexpr (std::is_same_v<R, Reg<T>>) {
    out = RayLanes<R>{r.ox, r.oy, r.oz, r.sx, r.sy, r.sz};
  } else {
    const WatertightRay<T>& ray = r.ray;
    out = RayLanes<R>{R::set1(ray.org[ray.kx]), R::set1(ray.org[ray.ky]), R::set1(ray.org[ray.kz]),
                      R::set1(ray.sx), R::set1(ray.sy), R::set1(ray.sz)};
  }
}

template <class T, class R = Reg<T>>
inline int exactLanes(const TriangleVertices4<T>& p, const WatertightRay4<T>& r4, int lane0, T maxT,
                      bool cullBackFaces, TriangleHits4<T>& hits) {
  using V = typename R::type;
  const WatertightRay<T>& ray = r4.ray;
  RayLanes<R> r;
  rayLanes<R>(r4, r);
  const V zero = R::set1(T(0));
  auto at = [&](int vertex, int axis) { return &p.v[vertex][axis][lane0]; };  // loaded by R::load
  // a = v0 - org, b = v1 - org, c = v2 - org on the permuted axes, then the shear. The sheared x and y are computed
  // negated, nax = (ox - v0x) + sx * akz = -((v0x - ox) - sx * akz) (rounding is symmetric), so the vertex is the
  // subtraction's second operand (read from memory on x86); the edge functions below multiply them in pairs, so they
  // are the scalar test's bit for bit but for the sign of an exact zero (which goes to the scalar test).
  const V akz = sub(R::load(at(0, ray.kz)), r.oz), bkz = sub(R::load(at(1, ray.kz)), r.oz);
  const V ckz = sub(R::load(at(2, ray.kz)), r.oz);
  const V nax = add(sub(r.ox, R::load(at(0, ray.kx))), mul(r.sx, akz));
  const V nay = add(sub(r.oy, R::load(at(0, ray.ky))), mul(r.sy, akz));
  const V nbx = add(sub(r.ox, R::load(at(1, ray.kx))), mul(r.sx, bkz));
  const V nby = add(sub(r.oy, R::load(at(1, ray.ky))), mul(r.sy, bkz));
  const V ncx = add(sub(r.ox, R::load(at(2, ray.kx))), mul(r.sx, ckz));
  const V ncy = add(sub(r.oy, R::load(at(2, ray.ky))), mul(r.sy, ckz));
  // edgeFunction(cx, cy, bx, by), edgeFunction(ax, ay, cx, cy), edgeFunction(bx, by, ax, ay).
  const V eu = sub(mul(ncx, nby), mul(ncy, nbx));
  const V ev = sub(mul(nax, ncy), mul(nay, ncx));
  const V ew = sub(mul(nbx, nay), mul(nby, nax));
  const V anyZero = bitOr(bitOr(eq(eu, zero), eq(ev, zero)), eq(ew, zero));
  // Edge functions of both signs (the scalar test's anyNeg && anyPos on lanes without a zero one): sign bits that
  // differ. Only sign bits are read from here on (movemask), so masks of all bits and of the sign bit mix freely. A
  // NaN edge function (overflow) may land either way: its lane's hit is NaN, which the mesh raycast rejects.
  V reject = bitOr(bitXor(eu, ev), bitXor(eu, ew));
  const V det = add(add(eu, ev), ew);
  reject = bitOr(reject, eq(det, zero));
  const V front = lt(zero, det);
  if (cullBackFaces) reject = bitOr(reject, le(det, zero));  // !(det > 0)
  const V tScaled = add(add(mul(eu, mul(r.sz, akz)), mul(ev, mul(r.sz, bkz))),
                                 mul(ew, mul(r.sz, ckz)));
  // sign = det > 0 ? 1 : -1; multiplying by -1 only flips the sign bit, as the xor below does.
  const V flip = andNot(front, R::signBit());
  const V absDet = bitXor(det, flip), st = bitXor(tScaled, flip);
  const V limit = mul(R::set1(maxT), absDet);
  reject = bitOr(reject, bitOr(lt(st, zero), lt(limit, st)));
  // An exactly zero edge function: the scalar test re-evaluates it in a wider type, so it decides.
  const int zeroEdge = R::mask(anyZero);
  const int full = (1 << R::kWidth) - 1;
  const int candidates = ~R::mask(reject) & full;
  // Decided: no zero edge function and t, u, v finite (the mesh raycast requires a finite hit). The scalar test then
  // rejects exactly what `reject` holds (on a NaN comparison it accepts, and so does this test; a NaN edge function or
  // det gives a NaN t, never decided), so a candidate is its hit.
  int decided = candidates & ~zeroEdge;
  if (decided) {
    const V inv = div(R::set1(T(1)), det);
    const V t = mul(tScaled, inv), u = mul(ev, inv), v = mul(ew, inv);
    const V big = R::set1(std::numeric_limits<T>::max());
    const V sign = R::signBit();
    const V finite = bitAnd(bitAnd(le(andNot(sign, t), big), le(andNot(sign, u), big)), le(andNot(sign, v), big));
    decided &= R::mask(finite);
    R::store(hits.t + lane0, t);
    R::store(hits.u + lane0, u);
    R::store(hits.v + lane0, v);
    hits.frontMask |= (R::mask(front) & decided) << lane0;
  }
  hits.decided |= decided << lane0;
  return (candidates | zeroEdge) << lane0;
}
#if !defined(__clang__)
#pragma GCC diagnostic pop
#endif
}  // namespace lanes
#endif

// Bit i set: the scalar watertight test of triangle i of the leaf may accept the ray within [0, maxT]. A candidate
// lane without an exactly zero edge function and with a finite hit is decided here: the scalar test accepts it with
// the hit written to `hits` (bit i of hits.decided).
// kAvx2 (callers on CPUs with AVX2): double lanes 4 to a register instead of 2 (GCC builds, see kAvx2DoubleLeaves).
template <class T, bool kAvx2 = false>
inline int exactTriangleHits(const TriangleVertices4<T>& p, const WatertightRay4<T>& r, T maxT, bool cullBackFaces,
                             TriangleHits4<T>& hits) {
  hits.decided = 0;
  hits.frontMask = 0;
#ifdef GQ_SSE42
  if constexpr (kAvx2 && lanes::kAvx2DoubleLeaves && std::is_same_v<T, double>) {
    return lanes::exactLanes<T, lanes::Reg256d>(p, r, 0, maxT, cullBackFaces, hits);
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
