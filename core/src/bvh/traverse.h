#pragma once
// BVH traversal kernels: front-to-back ray traversal with early-out at the current closest distance, and a
// best-first closest-point traversal. They take the leaf handler as a callable, so they are inline templates.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

#include "bvh/bvh.h"
#include "gq/math.h"

#ifdef GQ_SSE42
#include <immintrin.h>
#endif

namespace gq::detail {

// Depth-first stack bound: the build's depth limit (bvh/build.h, BvhBuildSettings: 32 SAH levels + at most 28 median
// levels, each node's first split of its range halving it) times the 7 siblings an 8-wide node leaves behind, plus
// slack (which also holds the 8 entries Bvh8LanesAvx2::sortHits and pushLanes write past the top).
inline constexpr int kBvhStackSize = 512;

// The ray in the BVH's float frame, with the padding that keeps the float slab test conservative for the T-precision
// ray that the triangles are tested against. W: the width of the nodes it walks (the plane offsets depend on it).
template <int W> struct BvhRay {
  // x, y, z in lanes 0-2 of each array (lane 3: unused), so the SSE setup stores each with one instruction.
  // The origin the near planes' slab distances are taken from, and the one for the far planes. A float origin is
  // exact and both are it; a double origin that float does not hold lies between two floats, and each side takes the
  // one that moves its distances the conservative way (the near ones earlier, the far ones later: by the sign of the
  // direction, the float above or below the origin), so no padding for the origin's rounding is added per node.
  alignas(16) float org[4];
  alignas(16) float farOrg[4];
  // -1 / dir: a slab distance is (org - plane) * negInvDir, the same float as (plane - org) / dir's product form
  // (both negations are exact), with the plane as the subtraction's second operand, which x86 reads from memory.
  alignas(16) float negInvDir[4];
  // negInvDir times (1 - kRelPad) and (1 + kRelPad): the near and far slab distances come out padded from their one
  // product (no multiply between the slab test's min/max and its compare). A positive near (far) distance shrinks
  // (grows) by the pad, as when the padding scaled the test's [tNear, tFar]; negative ones never decide an entry
  // (tNear is at least 0, and a negative far distance rejects either way).
  alignas(16) float nearInv[4];
  alignas(16) float farInv[4];
  // Per axis, the byte offset in a node of the child bounds the ray enters (near) and leaves (far) by: the min
  // plane when the direction is positive, the max plane otherwise. Slab tests then need no min/max per axis. (In
  // bytes, so a node test adds them without a scaling per walk restart.)
  std::uint32_t nearOffset[3], farOffset[3];
  // Nonzero when a slab distance can be NaN: a direction component clamped below kTinyDir (an infinite inverse: 0 *
  // inf on a plane through the origin) or an origin beyond float's range (inf - inf). Otherwise the AVX2 walk may take
  // the node test's max and min in fewer steps (intersectLanes8).
  std::uint32_t mayGiveNaN;
  // Relative padding on [tNear, tFar] covering the rounding of the slab arithmetic and of the float direction.
  static constexpr float kRelPad = 16.0f * std::numeric_limits<float>::epsilon();
};

// The plane offsets of BvhRay for the 8 sign patterns of the direction (bit i: negative along axis i): near planes
// x, y, z, then far planes x, y, z. Planes minX, minY, minZ, maxX, maxY, maxZ of a node hold W floats each.
template <int W> struct BvhPlaneOffsets {
  std::uint32_t bytes[8][6];
  constexpr BvhPlaneOffsets() : bytes() {
    constexpr std::uint32_t kPlaneBytes = W * sizeof(float);
    for (std::uint32_t signs = 0; signs < 8; ++signs)
      for (std::uint32_t i = 0; i < 3; ++i) {
        const std::uint32_t minPlane = kPlaneBytes * i, maxPlane = kPlaneBytes * (3 + i);
        const bool negative = ((signs >> i) & 1u) != 0;
        bytes[signs][i] = negative ? maxPlane : minPlane;
        bytes[signs][3 + i] = negative ? minPlane : maxPlane;
      }
  }
};
template <int W> inline constexpr BvhPlaneOffsets<W> kBvhPlaneOffsets{};

#ifdef GQ_SSE42
// The float x, y, z of a T vector in lanes 0-2 (lane 3: 0).
template <class T> inline __m128 floatLanes(const Vec3<T>& v) {
  if constexpr (std::is_same_v<T, float>) {
    return _mm_setr_ps(v[0], v[1], v[2], 0.0f);
  } else {
    return _mm_movelh_ps(_mm_cvtpd_ps(_mm_loadu_pd(v.data())), _mm_cvtpd_ps(_mm_set_sd(v[2])));
  }
}
#endif

// The least float at or above a T distance: the walk's float tMax for a T bound. A float rounded below t is not +inf
// or -0 (t > f), so the next float up is one unit of its bit pattern away: +1 for a positive f (FLT_MAX's next is
// +inf), -1 for a negative one (-inf's next is -FLT_MAX): std::nextafter's value without a library call per hit.
template <class T> inline float floatCeil(T t) {
  const float f = static_cast<float>(t);
  if (!(T(f) < t)) return f;
  std::uint32_t bits;
  std::memcpy(&bits, &f, sizeof bits);
  bits += std::signbit(f) ? 0xffffffffu : 1u;
  float up;
  std::memcpy(&up, &bits, sizeof up);
  return up;
}

// The floats next to a T value below and above it (both the value when float holds it; NaN stays NaN, values beyond
// float's range give +-FLT_MAX and +-inf): floatCeil, and the floor as its mirror (negation is exact and rounding to
// nearest symmetric).
template <class T> inline void floatsAround(T x, float& below, float& above) {
  below = -floatCeil(-x);
  above = floatCeil(x);
}

namespace bvh_ray {
// Direction components this small would give infinite inverses: they are clamped, but for an exact zero (below).
inline constexpr float kTinyDir = 1e-20f;
inline constexpr float kInf = std::numeric_limits<float>::infinity();

// An exactly zero component (bit i of zeroAxes): with an infinite inverse the axis admits the ray iff its origin is
// within the slab, faces included. A slab distance is then -inf or +inf, or NaN (0 * inf) when the origin is on that
// plane, which the node tests ignore (NaN-first min/max order): the face is entered. The near and far origins (on
// the conservative sides of an inexact one) are within the float slab whenever the T origin is within the T box, the
// planes being rounded outward. (Clamped, a ray lying in the plane of the face its clamp's sign points at would exit
// it at 0.)
// signBits: bit i, the sign bit of component i.
template <int W> inline void setZeroAxesInverse(BvhRay<W>& r, int signBits, int zeroAxes) {
  for (int i = 0; i < 3; ++i)
    if ((zeroAxes >> i) & 1) r.negInvDir[i] = (signBits >> i) & 1 ? kInf : -kInf;
}

// The near and far plane offsets of a direction whose sign bits are `negative`.
template <int W> inline void setPlaneOffsets(BvhRay<W>& r, int negative) {
  std::memcpy(r.nearOffset, &kBvhPlaneOffsets<W>.bytes[negative][0], sizeof(r.nearOffset));
  std::memcpy(r.farOffset, &kBvhPlaneOffsets<W>.bytes[negative][3], sizeof(r.farOffset));
}
}  // namespace bvh_ray

// The BVH ray of a T ray, one axis at a time: the portable form, which makeBvhRay is where SSE4.2 is not compiled in.
// The SSE form computes the same constants bit for bit (lanes 0-2; BvhSlab compares them).
template <int W, class T> inline BvhRay<W> makeBvhRayScalar(const Vec3<T>& org, const Vec3<T>& dir) {
  using namespace bvh_ray;
  BvhRay<W> r;
  const int zeroAxes = int(dir[0] == T(0)) | int(dir[1] == T(0)) << 1 | int(dir[2] == T(0)) << 2;
  int negative = 0;     // bit i: dir[i] < 0, the index of the plane offsets in kBvhPlaneOffsets
  int clampedAxes = 0;  // bit i: |dir[i]| in float below kTinyDir (zero included)
  for (int i = 0; i < 3; ++i) {
    float d = static_cast<float>(dir[i]);
    clampedAxes |= int(std::abs(d) < kTinyDir) << i;
    if (std::abs(d) < kTinyDir) d = std::signbit(d) ? -kTinyDir : kTinyDir;
    r.negInvDir[i] = -1.0f / d;
    negative |= int(r.negInvDir[i] > 0.0f) << i;
    // A positive direction enters by its min planes and leaves by its max planes; the entry distance
    // (min - org) / dir falls as the origin rises, so the float above the origin gives the earlier entry and the
    // float below it the later exit; a negative direction the reverse.
    float below, above;
    floatsAround(org[i], below, above);
    r.org[i] = std::signbit(d) ? below : above;
    r.farOrg[i] = std::signbit(d) ? above : below;
  }
  r.negInvDir[3] = 1.0f;
  r.org[3] = r.farOrg[3] = 0.0f;
  r.mayGiveNaN = std::uint32_t(clampedAxes);
  for (int i = 0; i < 3; ++i) r.mayGiveNaN |= std::uint32_t(!std::isfinite(r.org[i]) || !std::isfinite(r.farOrg[i]));
  if (zeroAxes != 0) [[unlikely]] {
    setZeroAxesInverse(r, int(std::signbit(dir[0])) | int(std::signbit(dir[1])) << 1 | int(std::signbit(dir[2])) << 2,
                       zeroAxes);
  }
  // A clamped axis leaves the slab no sooner than the ray does along it, or never: the clamp's exit distance,
  // |gap| / kTinyDir, can come before the ray's own, so the far inverse is infinite there (far distances +inf inside
  // the slab, -inf past its far plane, NaN on it, which the tests ignore; the far origin is inside the float slab
  // whenever the T origin is inside the T box, rounding being monotonic and the planes rounded outward). The clamped
  // near distance comes no later than the ray's own entry: conservative as it is.
  for (int i = 0; i < 4; ++i) {
    r.nearInv[i] = r.negInvDir[i] * (1.0f - BvhRay<W>::kRelPad);
    // Times inf: inf with negInvDir's sign (never 0).
    r.farInv[i] = r.negInvDir[i] * (i < 3 && ((clampedAxes >> i) & 1) ? kInf : 1.0f + BvhRay<W>::kRelPad);
  }
  setPlaneOffsets(r, negative);
  return r;
}

#ifdef GQ_SSE42
namespace bvh_ray {
// The direction's part of makeBvhRayScalar on 3 lanes at once (d: the float direction in lanes 0-2, zeroAxes: its
// components exactly zero in T): the same conversions, the same clamp (the sign bit kept, -0 included) and the same
// correctly rounded divisions, so the constants are the loop's bit for bit. The sign bits of the clamped direction
// are the direction's, and the loop's `negInvDir > 0` (-1 / x flips the sign; it is 0 only for an infinite x, a
// direction overflowing float, whose slab values are 0 or NaN with either plane order).
template <int W> [[gnu::always_inline]] inline void setDirection(BvhRay<W>& r, __m128 d, int zeroAxes) {
  const __m128 signBit = _mm_set1_ps(-0.0f), tiny = _mm_set1_ps(kTinyDir);
  const __m128 small = _mm_cmplt_ps(_mm_andnot_ps(signBit, d), tiny);
  const __m128 clamped = _mm_blendv_ps(d, _mm_or_ps(_mm_and_ps(d, signBit), tiny), small);
  __m128 negInv = _mm_div_ps(_mm_set1_ps(-1.0f), clamped);
  _mm_store_ps(r.negInvDir, negInv);
  if (zeroAxes != 0) [[unlikely]] {
    setZeroAxesInverse(r, _mm_movemask_ps(d), zeroAxes);  // a T zero's sign is its float's (conversion keeps it)
    negInv = _mm_load_ps(r.negInvDir);
  }
  // The loop's near and far inverses (the fourth lane, from floatLanes' 0 clamped to kTinyDir, is never read).
  const __m128 farScale = _mm_blendv_ps(_mm_set1_ps(1.0f + BvhRay<W>::kRelPad), _mm_set1_ps(kInf), small);
  _mm_store_ps(r.nearInv, _mm_mul_ps(negInv, _mm_set1_ps(1.0f - BvhRay<W>::kRelPad)));
  _mm_store_ps(r.farInv, _mm_mul_ps(negInv, farScale));
  setPlaneOffsets(r, _mm_movemask_ps(clamped) & 7);
  r.mayGiveNaN = std::uint32_t(_mm_movemask_ps(small) & 7);
}

// Bits 0-2: the lanes of o that are not finite.
inline std::uint32_t nonFiniteLanes(__m128 o) {
  return std::uint32_t(_mm_movemask_ps(_mm_cmpunord_ps(o, _mm_sub_ps(o, o))) & 7);  // inf - inf is NaN
}
}  // namespace bvh_ray

// makeBvhRay of a float ray given as lanes (x, y, z in lanes 0-2, lane 3 0).
template <int W> [[gnu::always_inline]] inline BvhRay<W> makeBvhRayLanes(__m128 o, __m128 d) {
  BvhRay<W> r;
  _mm_store_ps(r.org, o);
  _mm_store_ps(r.farOrg, o);
  bvh_ray::setDirection(r, d, _mm_movemask_ps(_mm_cmpeq_ps(d, _mm_setzero_ps())) & 7);
  r.mayGiveNaN |= bvh_ray::nonFiniteLanes(o);
  return r;
}

// makeBvhRayScalar on 3 lanes at once, bit for bit (BvhSlab compares them).
// Forced inline (as the mesh kernel's ray constants): GCC left it out of line once the kernel had two instances.
template <int W, class T>
[[gnu::always_inline]] inline BvhRay<W> makeBvhRay(const Vec3<T>& org, const Vec3<T>& dir) {
  if constexpr (std::is_same_v<T, float>) {
    return makeBvhRayLanes<W>(floatLanes(org), floatLanes(dir));
  } else {
    BvhRay<W> r;
    const __m128 d = floatLanes(dir);
    // Axes whose component is exactly zero (T's own compare: a double too small for float is not zero).
    const int zeroAxes =
        _mm_movemask_pd(_mm_cmpeq_pd(_mm_loadu_pd(dir.data()), _mm_setzero_pd())) | int(dir[2] == 0.0) << 2;
    bvh_ray::setDirection(r, d, zeroAxes);
    // floatsAround on 3 lanes: the rounded float's bit pattern moved one unit towards the double where it passed it
    // (towards -inf: -1 on a positive float, +1 on a negative one; a double rounded to -0 is negative, to +0 positive).
    const __m128 o = floatLanes(org);
    const __m128d lo = _mm_loadu_pd(org.data()), hi = _mm_set_sd(org[2]);
    const __m128d backLo = _mm_cvtps_pd(o), backHi = _mm_cvtps_pd(_mm_movehl_ps(o, o));
    auto lanes3 = [](__m128d a, __m128d b) {  // the 64-bit masks' low halves as 32-bit lanes 0-2
      return _mm_castps_si128(_mm_shuffle_ps(_mm_castpd_ps(a), _mm_castpd_ps(b), _MM_SHUFFLE(2, 0, 2, 0)));
    };
    const __m128i roundedUp = lanes3(_mm_cmpgt_pd(backLo, lo), _mm_cmpgt_pd(backHi, hi));
    const __m128i roundedDown = lanes3(_mm_cmplt_pd(backLo, lo), _mm_cmplt_pd(backHi, hi));
    const __m128i bits = _mm_castps_si128(o);
    const __m128i up1 = _mm_or_si128(_mm_add_epi32(_mm_srai_epi32(bits, 31), _mm_srai_epi32(bits, 31)),
                                     _mm_set1_epi32(1));  // +1 on a positive float, -1 on a negative one
    const __m128 below = _mm_castsi128_ps(_mm_sub_epi32(bits, _mm_and_si128(roundedUp, up1)));
    const __m128 above = _mm_castsi128_ps(_mm_add_epi32(bits, _mm_and_si128(roundedDown, up1)));
    // The scalar loop's choice by the sign bit (the clamped direction's is the direction's).
    _mm_store_ps(r.org, _mm_blendv_ps(above, below, d));
    _mm_store_ps(r.farOrg, _mm_blendv_ps(below, above, d));
    r.mayGiveNaN |= bvh_ray::nonFiniteLanes(below) | bvh_ray::nonFiniteLanes(above);
    return r;
  }
}
#else
// Forced inline (as the mesh kernel's ray constants): GCC left it out of line once the kernel had two instances.
template <int W, class T>
[[gnu::always_inline]] inline BvhRay<W> makeBvhRay(const Vec3<T>& org, const Vec3<T>& dir) {
  return makeBvhRayScalar<W>(org, dir);
}
#endif

#ifdef GQ_SSE42
// The SSE node test's ray constants: org, farOrg, nearInv and farInv broadcast to 4 lanes once per walk, so a node
// test loads them instead of splatting them, and the plane offsets. (The AVX2 test broadcasts from BvhRay as it
// loads: holding 8-lane copies in the walk was measured 68 instructions more per bunny ray, spilled around the leaf
// tests.)
struct BvhRaySse {
  __m128 org[3], farOrg[3], nearInv[3], farInv[3];
  std::uint32_t nearOffset[3], farOffset[3];
};

template <int W> inline BvhRaySse broadcastSse(const BvhRay<W>& ray) {
  BvhRaySse r;
  for (int i = 0; i < 3; ++i) {
    r.org[i] = _mm_set1_ps(ray.org[i]);
    r.nearInv[i] = _mm_set1_ps(ray.nearInv[i]);
    r.farInv[i] = _mm_set1_ps(ray.farInv[i]);
    r.farOrg[i] = _mm_set1_ps(ray.farOrg[i]);
    r.nearOffset[i] = ray.nearOffset[i];
    r.farOffset[i] = ray.farOffset[i];
  }
  return r;
}

// Lanes [lane0, lane0 + 4) of a node's slab test (SSE): the 4-bit hit mask, entry distances stored to tNear + lane0.
// The plane `byteOffset` bytes past `base` (BvhRay's near and far offsets).
inline const float* planeAt(const float* base, std::uint32_t byteOffset) {
  return reinterpret_cast<const float*>(reinterpret_cast<const char*>(base) + byteOffset);
}

template <bool kFarOrigin, int W>
inline int intersectLanes4(const BvhNode<W>& node, const BvhRaySse& ray, int lane0, float tMax, float* tNear) {
  // With a positive (negative) inverse the min (max) plane gives the smaller slab distance, and rounding keeps that
  // order, so the near/far planes picked once per ray give the same distances as min/max of both planes.
  const float* base = node.minX + lane0;
  const __m128* farOrg = kFarOrigin ? ray.farOrg : ray.org;
  auto slab = [&](std::uint32_t offset, const __m128& origin, const __m128& inv) {
    return _mm_mul_ps(_mm_sub_ps(origin, _mm_load_ps(planeAt(base, offset))), inv);
  };
  const __m128 nearX = slab(ray.nearOffset[0], ray.org[0], ray.nearInv[0]);
  const __m128 nearY = slab(ray.nearOffset[1], ray.org[1], ray.nearInv[1]);
  const __m128 nearZ = slab(ray.nearOffset[2], ray.org[2], ray.nearInv[2]);
  const __m128 farX = slab(ray.farOffset[0], farOrg[0], ray.farInv[0]);
  const __m128 farY = slab(ray.farOffset[1], farOrg[1], ray.farInv[1]);
  const __m128 farZ = slab(ray.farOffset[2], farOrg[2], ray.farInv[2]);
  // NaN-first order (maxps / minps return their second operand when either is NaN): an axis whose distance is NaN
  // (an origin on the plane of an axis the ray is parallel to, see makeBvhRay) is ignored.
  const __m128 tn = _mm_max_ps(nearX, _mm_max_ps(nearY, _mm_max_ps(nearZ, _mm_setzero_ps())));
  const __m128 tf =
      _mm_min_ps(farX, _mm_min_ps(farY, _mm_min_ps(farZ, _mm_set1_ps(tMax * (1.0f + BvhRay<W>::kRelPad)))));
  _mm_store_ps(tNear + lane0, tn);
  return _mm_movemask_ps(_mm_cmple_ps(tn, tf));  // empty lanes: see emptyBvhLaneBox
}

// The 8-lane slab test with AVX2: the operations of intersectLanes4 on 8 lanes at once, so both give the same
// masks and entry distances bit for bit (no FMA: a fused multiply-add would round differently).
// (A helper function, not a lambda: a lambda does not inherit the target attribute.)
__attribute__((target("avx2"))) inline __m256 slab8(const float* plane, const float& origin, const float& inv) {
  return _mm256_mul_ps(_mm256_sub_ps(_mm256_broadcast_ss(&origin), _mm256_load_ps(plane)), _mm256_broadcast_ss(&inv));
}

// kNaNFirst: the max and min NaN-first, as intersectLanes4, for any ray. Otherwise, for rays none of whose slab
// distances can be NaN (BvhRay::mayGiveNaN zero), the same max and min in two steps, not a chain of three: max and min
// of non-NaN values are exact, so the masks and entry distances are the same, and the node test is on the walk's
// critical path (measured about 1 % off a bunny ray). (Two levels cannot take both operands of one max NaN-first: a ray
// parallel to two axes with its origin on a box's plane would then enter boxes beside it.)
template <bool kFarOrigin, bool kNaNFirst>
__attribute__((target("avx2"))) inline int intersectLanes8(const Bvh8Node& node, const BvhRay<8>& ray, float tMax,
                                                            float* tNear) {
  const float* base = node.minX;
  const float* farOrg = kFarOrigin ? ray.farOrg : ray.org;
  const __m256 nearX = slab8(planeAt(base, ray.nearOffset[0]), ray.org[0], ray.nearInv[0]);
  const __m256 nearY = slab8(planeAt(base, ray.nearOffset[1]), ray.org[1], ray.nearInv[1]);
  const __m256 nearZ = slab8(planeAt(base, ray.nearOffset[2]), ray.org[2], ray.nearInv[2]);
  const __m256 farX = slab8(planeAt(base, ray.farOffset[0]), farOrg[0], ray.farInv[0]);
  const __m256 farY = slab8(planeAt(base, ray.farOffset[1]), farOrg[1], ray.farInv[1]);
  const __m256 farZ = slab8(planeAt(base, ray.farOffset[2]), farOrg[2], ray.farInv[2]);
  const __m256 zero = _mm256_setzero_ps(), bound = _mm256_set1_ps(tMax * (1.0f + BvhRay<8>::kRelPad));
  const __m256 tn = kNaNFirst ? _mm256_max_ps(nearX, _mm256_max_ps(nearY, _mm256_max_ps(nearZ, zero)))
                              : _mm256_max_ps(_mm256_max_ps(nearX, nearY), _mm256_max_ps(nearZ, zero));
  const __m256 tf = kNaNFirst ? _mm256_min_ps(farX, _mm256_min_ps(farY, _mm256_min_ps(farZ, bound)))
                              : _mm256_min_ps(_mm256_min_ps(farX, farY), _mm256_min_ps(farZ, bound));
  _mm256_store_ps(tNear, tn);
  return _mm256_movemask_ps(_mm256_cmp_ps(tn, tf, _CMP_LE_OQ));
}
#endif

// The order in which the ray walk takes a node's 3 or more hit children: by entry distance, whose bits order as
// integers (it is never negative), with the low 3 bits replaced by the lane so that every key is distinct and the
// order is the same however the keys are sorted. (Only the walk's speed depends on the order.)
inline std::uint32_t bvhSortKey(float tNear, int lane) {
  std::uint32_t bits;
  std::memcpy(&bits, &tNear, sizeof bits);
  return (bits & ~7u) | std::uint32_t(lane);
}

// An entry of the ray walk's stack: a node or leaf reference and the distance at which the ray enters its box.
struct BvhWalkEntry {
  std::uint32_t ref;
  float tNear;
};

// Node tests for the walk below: the hit mask of a node's children for t in [0, tMax] and their entry distances in
// tNear. Empty lanes are rejected by their boxes (emptyBvhLaneBox), but for rays whose float slab distances are all
// NaN, which the walk handles. kFarOrigin: the far planes' distances are taken from BvhRay::farOrg (double rays);
// false for rays whose origin is exactly the float one (float queries: both origins are it), which keeps one origin
// in registers.
// Lanes::Ray is the ray as the node test reads it, made by Lanes::prepare once per walk.
template <int W> struct BvhLanesScalar {
  static constexpr int kWidth = W;
  static constexpr bool kSortsHits = false;  // the walk insertion-sorts 3 or more hit children
  static constexpr bool kAvx2 = false;       // the walk's leaf code may use AVX2 (Bvh8LanesAvx2)
  using Ray = BvhRay<W>;
  static const Ray& prepare(const BvhRay<W>& ray) { return ray; }
  template <bool kFarOrigin> static int test(const BvhNode<W>& node, const Ray& ray, float tMax, float* tNear) {
    const float* lo[3] = {node.minX, node.minY, node.minZ};
    const float* hi[3] = {node.maxX, node.maxY, node.maxZ};
    int mask = 0;
    for (int i = 0; i < W; ++i) {
      float tn = 0.0f, tf = tMax * (1.0f + BvhRay<W>::kRelPad);
      for (int a = 0; a < 3; ++a) {
        // The near and far planes by the direction's sign, as the SIMD tests' plane offsets; a NaN distance (see
        // makeBvhRay) leaves tn and tf as they are (std::max / std::min keep their first operand then).
        const bool negative = ray.negInvDir[a] > 0.0f;
        const float nearPlane = negative ? hi[a][i] : lo[a][i], farPlane = negative ? lo[a][i] : hi[a][i];
        tn = std::max(tn, (ray.org[a] - nearPlane) * ray.nearInv[a]);
        tf = std::min(tf, ((kFarOrigin ? ray.farOrg[a] : ray.org[a]) - farPlane) * ray.farInv[a]);
      }
      tNear[i] = tn;
      if (tn <= tf) mask |= 1 << i;
    }
    return mask;
  }
};

#ifdef GQ_SSE42
// 8-wide nodes on the SSE4.2 baseline: two 4-lane halves.
struct Bvh8LanesSse {
  static constexpr int kWidth = 8;
  static constexpr bool kSortsHits = false;
  static constexpr bool kAvx2 = false;
  using Ray = BvhRaySse;
  static Ray prepare(const BvhRay<8>& ray) { return broadcastSse(ray); }
  template <bool kFarOrigin> static int test(const Bvh8Node& node, const Ray& ray, float tMax, float* tNear) {
    return intersectLanes4<kFarOrigin>(node, ray, 0, tMax, tNear) |
           intersectLanes4<kFarOrigin>(node, ray, 4, tMax, tNear) << 4;
  }
};

// One layer of a sorting network: each lane meets the lane `partner` holds; the lanes set in kMaxLanes keep the
// larger key, the others the smaller.
template <int kMaxLanes> __attribute__((target("avx2"))) inline __m256i sortLayer(__m256i v, __m256i partner) {
  return _mm256_blend_epi32(_mm256_min_epi32(v, partner), _mm256_max_epi32(v, partner), kMaxLanes);
}

// For each 8-bit mask, its set lanes in increasing order, 4 bits each (lowest first).
struct BvhLaneLists {
  std::uint32_t lanes[256];
  constexpr BvhLaneLists() : lanes() {
    for (std::uint32_t m = 0; m < 256; ++m) {
      std::uint32_t list = 0, n = 0;
      for (std::uint32_t lane = 0; lane < 8; ++lane)
        if ((m >> lane) & 1u) list |= lane << (4 * n++);
      lanes[m] = list;
    }
  }
};
inline constexpr BvhLaneLists kBvhLaneLists{};

// 8-wide nodes with AVX2 (only on CPUs that have it: callers check hasAvx2()).
// kNaNFirst: see intersectLanes8 (Bvh8LanesAvx2 for any ray, Bvh8LanesAvx2NaNFree for rays whose mayGiveNaN is 0).
template <bool kNaNFirst> struct Bvh8LanesAvx2For {
  static constexpr int kWidth = 8;
  static constexpr bool kSortsHits = true;  // sortHits below
  static constexpr bool kAvx2 = true;
  using Ray = BvhRay<8>;
  static const Ray& prepare(const BvhRay<8>& ray) { return ray; }
  template <bool kFarOrigin>
  __attribute__((target("avx2"))) static int test(const Bvh8Node& node, const Ray& ray, float tMax, float* tNear) {
    return intersectLanes8<kFarOrigin, kNaNFirst>(node, ray, tMax, tNear);
  }

  // A node's hit children (`mask`, 3 or more lanes) in entry order, by a sorting network on one register: returns
  // the nearest and stores the others at `stack`, farthest first (the nearest of them last, popped first), advancing
  // `top` by their count. Writes 8 entries from `stack` on (the stack bound leaves that room). Keys: bvhSortKey,
  // missed lanes last.
  __attribute__((target("avx2"))) static BvhWalkEntry sortHits(const Bvh8Node& node, const float* tNear, int mask,
                                                              BvhWalkEntry* stack, int& top) {
    const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    const __m256i laneBit = _mm256_sllv_epi32(_mm256_set1_epi32(1), lane);
    const __m256i hit = _mm256_cmpeq_epi32(_mm256_and_si256(_mm256_set1_epi32(mask), laneBit), laneBit);
    const __m256i tBits = _mm256_castps_si256(_mm256_load_ps(tNear));
    __m256i k = _mm256_or_si256(_mm256_andnot_si256(_mm256_set1_epi32(7), tBits), lane);
    k = _mm256_blendv_epi8(_mm256_set1_epi32(0x7fffffff), k, hit);
    // Comparators (i, j), i < j, i takes the minimum: (0,2)(1,3)(4,6)(5,7) (0,4)(1,5)(2,6)(3,7) (0,1)(2,3)(4,5)(6,7)
    // (2,4)(3,5) (1,4)(3,6) (1,2)(3,4)(5,6), the 19-comparator network for 8 keys.
    k = sortLayer<0xcc>(k, _mm256_shuffle_epi32(k, _MM_SHUFFLE(1, 0, 3, 2)));
    k = sortLayer<0xf0>(k, _mm256_permute2x128_si256(k, k, 1));
    k = sortLayer<0xaa>(k, _mm256_shuffle_epi32(k, _MM_SHUFFLE(2, 3, 0, 1)));
    // Lane 0 holds the least key from here on: the nearest child is taken now, so the walk's next node waits on 3
    // layers, not 6 (the others only need to be on the stack by the next pop).
    const int nearest = _mm_cvtsi128_si32(_mm256_castsi256_si128(k)) & 7;
    k = sortLayer<0x30>(k, _mm256_permute4x64_epi64(k, _MM_SHUFFLE(3, 1, 2, 0)));
    k = sortLayer<0x50>(k, _mm256_permutevar8x32_epi32(k, _mm256_setr_epi32(0, 4, 2, 6, 1, 5, 3, 7)));
    k = sortLayer<0x54>(k, _mm256_permutevar8x32_epi32(k, _mm256_setr_epi32(0, 2, 1, 4, 3, 6, 5, 7)));
    // Entry j of the stack takes sorted key count - 1 - j (the farthest first).
    const int count = __builtin_popcount(unsigned(mask));
    const __m256i reversed = _mm256_permutevar8x32_epi32(k, _mm256_sub_epi32(_mm256_set1_epi32(count - 1), lane));
    storeEntries(node, tNear, _mm256_and_si256(reversed, _mm256_set1_epi32(7)), stack);
    top += count - 1;
    return BvhWalkEntry{node.child[nearest], tNear[nearest]};
  }

  // The lanes of `mask` pushed in lane order without a loop: their references and entry distances gathered by one
  // permutation each (lane lists from kBvhLaneLists) and written as 8 entries by two 32-byte stores from `stack` on
  // (the stack bound leaves that room).
  __attribute__((target("avx2"))) static void pushLanes(const Bvh8Node& node, const float* tNear, int mask,
                                                        BvhWalkEntry* stack) {
    const __m256i shifts = _mm256_setr_epi32(0, 4, 8, 12, 16, 20, 24, 28);
    const __m256i lanes = _mm256_and_si256(
        _mm256_srlv_epi32(_mm256_set1_epi32(int(kBvhLaneLists.lanes[mask])), shifts), _mm256_set1_epi32(7));
    storeEntries(node, tNear, lanes, stack);
  }

 private:
  // Stack entries j = 0..7 from lane `lanes[j]` of the node: its reference and entry distance, written by two 32-byte
  // stores.
  __attribute__((target("avx2"))) static void storeEntries(const Bvh8Node& node, const float* tNear, __m256i lanes,
                                                           BvhWalkEntry* stack) {
    const __m256i refs = _mm256_permutevar8x32_epi32(_mm256_load_si256(reinterpret_cast<const __m256i*>(node.child)),
                                                     lanes);
    const __m256i dists = _mm256_permutevar8x32_epi32(_mm256_castps_si256(_mm256_load_ps(tNear)), lanes);
    const __m256i lo = _mm256_unpacklo_epi32(refs, dists), hi = _mm256_unpackhi_epi32(refs, dists);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(stack), _mm256_permute2x128_si256(lo, hi, 0x20));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(stack + 4), _mm256_permute2x128_si256(lo, hi, 0x31));
  }
};

using Bvh8LanesAvx2 = Bvh8LanesAvx2For<true>;
using Bvh8LanesAvx2NaNFree = Bvh8LanesAvx2For<false>;

// Whether this CPU runs AVX2 code (checked once).
inline bool hasAvx2() {
  static const bool yes = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") != 0;
  }();
  return yes;
}
using Bvh8LanesBaseline = Bvh8LanesSse;
#else
using Bvh8LanesBaseline = BvhLanesScalar<8>;
#endif

// One inner node of the ray walk: tests its children for t in [0, tMax], continues `e` with one of those the ray
// enters (the nearest when ordered) and pushes the others on the stack. False when the ray enters none (e unchanged).
// Ordered: the other children pushed farthest first; unordered: as found (see walkRayLeaves).
template <bool kOrdered, bool kFarOrigin, class Lanes>
[[gnu::always_inline]] inline bool descendNode(const Bvh<Lanes::kWidth>& bvh, const typename Lanes::Ray& lanesRay,
                                               float tMax, BvhWalkEntry& e, BvhWalkEntry* stack, int& top) {
  constexpr int W = Lanes::kWidth;
  using Node = BvhNode<W>;
  using Entry = BvhWalkEntry;
  const Node& node = bvh.nodes[e.ref];
  alignas(32) float tn[W];
  int mask = Lanes::template test<kFarOrigin>(node, lanesRay, tMax, tn);
  if (mask == 0) return false;
  int i = __builtin_ctz(unsigned(mask));
  mask &= mask - 1;
  if (mask == 0) {  // one child entered: no stack traffic
    e = Entry{node.child[i], tn[i]};
    return true;
  }
  if (!kOrdered) {
    e = Entry{node.child[i], tn[i]};
    if constexpr (Lanes::kSortsHits) {
      Lanes::pushLanes(node, tn, mask, stack + top);
      top += __builtin_popcount(unsigned(mask));
    } else {
      do {
        i = __builtin_ctz(unsigned(mask));
        mask &= mask - 1;
        stack[top++] = Entry{node.child[i], tn[i]};
      } while (mask);
    }
    return true;
  }
  const int j = __builtin_ctz(unsigned(mask));
  if ((mask & (mask - 1)) == 0) {  // two children entered (the common case): push the farther one
    // Without a branch: which child is nearer is a coin toss for rays in all directions (a branch on it was
    // mispredicted about half the time). Both references are loaded before the compare, so the next node's address
    // waits on the compare alone.
    const std::uint32_t refI = node.child[i], refJ = node.child[j];
    const std::uint32_t swap = 0u - std::uint32_t(tn[j] < tn[i]);
    const std::uint32_t nearRef = refI ^ ((refI ^ refJ) & swap), farRef = refI ^ refJ ^ nearRef;
    const int nearLane = i ^ ((i ^ j) & int(swap)), farLane = i ^ j ^ nearLane;
    stack[top++] = Entry{farRef, tn[farLane]};
    // Its node is fetched while the nearer subtree is walked (measured 1 % off the walk on the bunny).
    if (!(farRef & Node::kLeafBit)) __builtin_prefetch(&bvh.nodes[farRef]);
    e = Entry{nearRef, tn[nearLane]};
    return true;
  }
  if constexpr (Lanes::kSortsHits) {
    e = Lanes::sortHits(node, tn, mask | 1 << i, stack + top, top);
    return true;
  }
  // Push the hit children sorted by bvhSortKey (insertion sort on the stack, nearest on top): the order of
  // Bvh8LanesAvx2::sortHits, so both walks visit the same nodes in the same order.
  const int base = top;
  std::uint32_t keys[W];  // keys[k - base]: the key of stack[k]
  keys[0] = bvhSortKey(tn[i], i);
  stack[top++] = Entry{node.child[i], tn[i]};
  while (mask) {
    i = __builtin_ctz(unsigned(mask));
    mask &= mask - 1;
    const Entry c{node.child[i], tn[i]};
    const std::uint32_t key = bvhSortKey(tn[i], i);
    int k = top++;
    while (k > base && keys[k - 1 - base] < key) {
      stack[k] = stack[k - 1];
      keys[k - base] = keys[k - 1 - base];
      --k;
    }
    stack[k] = c;
    keys[k - base] = key;
  }
  e = stack[--top];
  return true;
}

// Walks the leaves whose boxes the ray enters within [0, tMax]. Ordered: nearest child first, and entries whose entry
// distance passed tMax (lowered by the leaf handler since they were pushed) are dropped. Unordered: the children are
// pushed as found (no compare per node, but on closed meshes the nearest child is likelier to hold a first hit).
// leaf(ref) returns true to end the walk.
template <bool kOrdered, bool kFarOrigin, class Lanes, class LeafFn>
inline void walkRayLeaves(const Bvh<Lanes::kWidth>& bvh, const BvhRay<Lanes::kWidth>& ray, float& tMax,
                          LeafFn&& leaf) {
  using Node = BvhNode<Lanes::kWidth>;
  using Entry = BvhWalkEntry;
  if (bvh.rootChild == Node::kEmpty) return;
  const auto& lanesRay = Lanes::prepare(ray);  // a reference to `ray`, or a copy the node test reads faster
  Entry stack[kBvhStackSize];
  int top = 0;
  stack[top++] = {bvh.rootChild, 0.0f};
  while (top > 0) {
    Entry e = stack[--top];
    if (kOrdered && e.tNear > tMax) continue;  // a closer hit was found since this entry was pushed
    // Descend through inner nodes (kEmpty has the leaf bit: an empty lane entered, see emptyBvhLaneBox, ends there).
    bool missed = false;
    while (!(e.ref & Node::kLeafBit)) {
      if (!descendNode<kOrdered, kFarOrigin, Lanes>(bvh, lanesRay, tMax, e, stack, top)) {
        missed = true;
        break;
      }
    }
    if (missed || e.ref == Node::kEmpty) continue;
    if (leaf(e.ref)) return;
  }
}

// Best-first traversal for nearest-primitive queries. `childLowerBound(node, lane)` returns a lower bound of the
// squared distance to anything inside that child (or +inf); `leaf(first, count)` tests primitives and may lower
// bestSq (owned by the caller).
template <int W, class T, class BoundFn, class LeafFn>
inline void traverseNearest(const Bvh<W>& bvh, T& bestSq, BoundFn&& childLowerBound, LeafFn&& leaf) {
  using Node = BvhNode<W>;
  struct Entry { std::uint32_t ref; T lower; };
  Entry stack[kBvhStackSize];
  int top = 0;
  if (bvh.rootChild == Node::kEmpty) return;
  stack[top++] = {bvh.rootChild, T(0)};
  while (top > 0) {
    const Entry e = stack[--top];
    if (e.lower > bestSq) continue;
    if (Node::isLeaf(e.ref)) {
      leaf(Node::leafFirst(e.ref), Node::leafCount(e.ref));
      continue;
    }
    const Node& node = bvh.nodes[e.ref];
    Entry hit[W];
    int n = 0;
    for (int i = 0; i < W; ++i) {
      if (node.child[i] == Node::kEmpty) continue;
      const T lb = childLowerBound(node, i);
      if (lb > bestSq) continue;
      Entry c{node.child[i], lb};
      int j = n++;
      while (j > 0 && hit[j - 1].lower < c.lower) { hit[j] = hit[j - 1]; --j; }
      hit[j] = c;
    }
    for (int i = 0; i < n; ++i) stack[top++] = hit[i];  // nearest pushed last, popped first
  }
}

}  // namespace gq::detail
