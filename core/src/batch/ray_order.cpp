// Ray order keys and their radix sort (batch/ray_order.h).
#include "batch/ray_order.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>

#include "bvh/traverse.h"  // hasAvx2

#ifdef GQ_SSE42
#include <immintrin.h>
#endif

namespace gq::detail {

namespace {

constexpr int kBitsPerAxis = 6;
constexpr std::uint32_t kCells = 1u << kBitsPerAxis;
constexpr int kAxes = 5;  // entry point x, y, z; direction u, v

// The 6 bits of a cell index spread 5 apart (bit b at 5b): five spread indices shifted by 0..4 interleave.
constexpr std::array<std::uint32_t, kCells> spreadTable() {
  std::array<std::uint32_t, kCells> table{};
  for (std::uint32_t v = 0; v < kCells; ++v) {
    std::uint32_t s = 0;
    for (int b = 0; b < kBitsPerAxis; ++b) s |= ((v >> b) & 1u) << (kAxes * b);
    table[v] = s;
  }
  return table;
}
constexpr std::array<std::uint32_t, kCells> kSpread = spreadTable();

// x in [0, 1] to a cell index; below 0 or NaN gives 0, above 1 the last cell.
template <class T> std::uint32_t cell(T x) {
  if (!(x > T(0))) return 0;
  if (!(x < T(1))) return kCells - 1;
  return std::uint32_t(x * T(kCells));
}

}  // namespace

template <class T> RayOrderKey<T>::RayOrderKey(const Bounds3<T>& target) : lo_(target.min), hi_(target.max) {
  for (int k = 0; k < 3; ++k) {
    const T extent = hi_[k] - lo_[k];
    invExtent_[k] = extent > T(0) ? T(1) / extent : T(0);
  }
}

template <class T> std::uint32_t RayOrderKey<T>::operator()(const Vec3<T>& origin, const Vec3<T>& dir) const {
  std::uint32_t key = 0;
  (void)(*this)(origin, dir, std::numeric_limits<T>::infinity(), key);
  return key;
}

template <class T>
bool RayOrderKey<T>::operator()(const Vec3<T>& origin, const Vec3<T>& dir, T maxDist, std::uint32_t& key) const {
  // Slab parameters along dir: enter the largest per-axis near one (0 for an origin inside), exit the smallest far
  // one. An axis the ray is parallel to keeps it out when the origin is outside its slab.
  T enter = T(0);
  T exit = std::numeric_limits<T>::infinity();
  bool outside = false;
  for (int k = 0; k < 3; ++k) {
    if (dir[k] == T(0)) {
      outside |= !(origin[k] >= lo_[k] && origin[k] <= hi_[k]);
      continue;
    }
    const T inv = T(1) / dir[k];
    const T t0 = (lo_[k] - origin[k]) * inv;
    const T t1 = (hi_[k] - origin[k]) * inv;
    enter = std::max(enter, std::min(t0, t1));
    exit = std::min(exit, std::max(t0, t1));
  }
  key = 0;
  // enter * |dir| <= maxDist, squared (no root; an overflow to +inf only admits more rays).
  if (outside || !(enter <= exit) || !(enter * enter * dir.squaredNorm() <= maxDist * maxDist)) return false;
  for (int k = 0; k < 3; ++k) {
    const T entry = origin[k] + enter * dir[k];
    key |= kSpread[cell((entry - lo_[k]) * invExtent_[k])] << (kAxes - 1 - k);
  }
  // Octahedral direction: d / |d|_1 on the upper half, folded over the diagonals for z < 0; u, v in [-1, 1].
  const T l1 = std::abs(dir.x()) + std::abs(dir.y()) + std::abs(dir.z());
  const T inv1 = l1 > T(0) ? T(1) / l1 : T(0);
  T u = dir.x() * inv1;
  T v = dir.y() * inv1;
  if (dir.z() < T(0)) {
    const T fu = (T(1) - std::abs(v)) * (u < T(0) ? T(-1) : T(1));
    const T fv = (T(1) - std::abs(u)) * (v < T(0) ? T(-1) : T(1));
    u = fu;
    v = fv;
  }
  key |= kSpread[cell((u + T(1)) * T(0.5))] << 1;
  key |= kSpread[cell((v + T(1)) * T(0.5))];
  return true;
}

namespace {

std::atomic<bool> gKeysScalarOnly{false};

#ifdef GQ_SSE42
// Bits 0..5 of each lane spread 5 apart (bit b to bit 5b), as kSpread.
__attribute__((target("avx2"))) inline __m256i spread8(__m256i c) {
  __m256i s = _mm256_setzero_si256();
  for (int b = 0; b < kBitsPerAxis; ++b) {
    s = _mm256_or_si256(s, _mm256_slli_epi32(_mm256_and_si256(c, _mm256_set1_epi32(1 << b)), (kAxes - 1) * b));
  }
  return s;
}

// cell() on 8 lanes of x in [0, 1]: below 0 or NaN gives 0 (max returns its second operand for a NaN), above 1 the
// last cell.
__attribute__((target("avx2"))) inline __m256i cell8(__m256 x) {
  const __m256 scaled = _mm256_max_ps(_mm256_mul_ps(x, _mm256_set1_ps(float(kCells))), _mm256_setzero_ps());
  return _mm256_cvttps_epi32(_mm256_min_ps(scaled, _mm256_set1_ps(float(kCells) - 0.5f)));
}

// RayOrderKey::operator() for 8 rays in float, without branches. Per-axis slab parameters: an axis the ray is
// parallel to gives +-inf (or NaN for an origin on the slab's plane, which min / max drop: the running value is their
// second operand). The octahedral fold by copysign: -0 folds as a negative.
struct Keys8 {
  __m256 lo[3], hi[3], invExtent[3];
  float maxDist2;

  __attribute__((target("avx2"))) void operator()(const float (&o)[3][8], const float (&d)[3][8],
                                                  std::uint32_t* keys) const {
    const __m256 signBit = _mm256_set1_ps(-0.0f);
    __m256 org[3], dir[3];
    __m256 enter = _mm256_setzero_ps(), exit = _mm256_set1_ps(std::numeric_limits<float>::infinity());
    for (int k = 0; k < 3; ++k) {
      org[k] = _mm256_loadu_ps(o[k]);
      dir[k] = _mm256_loadu_ps(d[k]);
      const __m256 inv = _mm256_div_ps(_mm256_set1_ps(1.0f), dir[k]);
      const __m256 t0 = _mm256_mul_ps(_mm256_sub_ps(lo[k], org[k]), inv);
      const __m256 t1 = _mm256_mul_ps(_mm256_sub_ps(hi[k], org[k]), inv);
      enter = _mm256_max_ps(_mm256_min_ps(t0, t1), enter);
      exit = _mm256_min_ps(_mm256_max_ps(t0, t1), exit);
    }
    const __m256 dd = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(dir[0], dir[0]), _mm256_mul_ps(dir[1], dir[1])),
                                    _mm256_mul_ps(dir[2], dir[2]));
    const __m256 reach = _mm256_mul_ps(_mm256_mul_ps(enter, enter), dd);
    const __m256 enters = _mm256_and_ps(_mm256_cmp_ps(enter, exit, _CMP_LE_OQ),
                                        _mm256_cmp_ps(reach, _mm256_set1_ps(maxDist2), _CMP_LE_OQ));
    __m256i key = _mm256_setzero_si256();
    for (int k = 0; k < 3; ++k) {
      const __m256 entry = _mm256_add_ps(org[k], _mm256_mul_ps(enter, dir[k]));
      const __m256i c = cell8(_mm256_mul_ps(_mm256_sub_ps(entry, lo[k]), invExtent[k]));
      key = _mm256_or_si256(key, _mm256_slli_epi32(spread8(c), kAxes - 1 - k));
    }
    const __m256 l1 = _mm256_add_ps(_mm256_add_ps(_mm256_andnot_ps(signBit, dir[0]), _mm256_andnot_ps(signBit, dir[1])),
                                    _mm256_andnot_ps(signBit, dir[2]));
    const __m256 inv1 = _mm256_div_ps(_mm256_set1_ps(1.0f), l1);
    __m256 u = _mm256_mul_ps(dir[0], inv1), v = _mm256_mul_ps(dir[1], inv1);
    const __m256 one = _mm256_set1_ps(1.0f);
    const __m256 fu = _mm256_or_ps(_mm256_sub_ps(one, _mm256_andnot_ps(signBit, v)), _mm256_and_ps(signBit, u));
    const __m256 fv = _mm256_or_ps(_mm256_sub_ps(one, _mm256_andnot_ps(signBit, u)), _mm256_and_ps(signBit, v));
    const __m256 below = _mm256_cmp_ps(dir[2], _mm256_setzero_ps(), _CMP_LT_OQ);
    u = _mm256_blendv_ps(u, fu, below);
    v = _mm256_blendv_ps(v, fv, below);
    const __m256 half = _mm256_set1_ps(0.5f);
    key = _mm256_or_si256(key, _mm256_slli_epi32(spread8(cell8(_mm256_mul_ps(_mm256_add_ps(u, one), half))), 1));
    key = _mm256_or_si256(key, spread8(cell8(_mm256_mul_ps(_mm256_add_ps(v, one), half))));
    key = _mm256_blendv_epi8(_mm256_set1_epi32(int(RayOrderKey<float>::kMisses)), key, _mm256_castps_si256(enters));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(keys), key);
  }
};

// The AVX2 keys of keyRays for its first n rays (n a multiple of 8): 8 rays' coordinates gathered into float lanes.
template <class T>
__attribute__((target("avx2"))) void keyRaysAvx2(const Bounds3<T>& box, const Vec3<T>& invExtent,
                                                 const StridedArray<Vec3<T>>& origins,
                                                 const StridedArray<Vec3<T>>& dirs, std::size_t n, T maxDist,
                                                 std::uint32_t* out) {
  Keys8 keys;
  // Conversions to float of values beyond its range give +-inf (IEEE 754), which the keys treat as any far value.
  for (int k = 0; k < 3; ++k) {
    keys.lo[k] = _mm256_set1_ps(float(box.min[k]));
    keys.hi[k] = _mm256_set1_ps(float(box.max[k]));
    keys.invExtent[k] = _mm256_set1_ps(float(invExtent[k]));
  }
  const float maxDistF = float(maxDist);
  keys.maxDist2 = maxDistF * maxDistF;  // +inf for a maxDist beyond float's range
  alignas(32) float o[3][8], d[3][8];
  for (std::size_t i = 0; i + 8 <= n; i += 8) {
    for (int l = 0; l < 8; ++l) {
      const Vec3<T>& org = origins[i + std::size_t(l)];
      const Vec3<T>& dir = dirs[i + std::size_t(l)];
      for (int k = 0; k < 3; ++k) {
        o[k][l] = float(org[k]);
        d[k][l] = float(dir[k]);
      }
    }
    keys(o, d, out + i);
  }
}
#endif

}  // namespace

void setRayOrderKeysScalarOnly(bool scalarOnly) { gKeysScalarOnly.store(scalarOnly); }

bool rayOrderKeysHaveWidePath() {
#ifdef GQ_SSE42
  return hasAvx2();
#else
  return false;
#endif
}

template <class T>
void RayOrderKey<T>::keyRaysScalar(const StridedArray<Vec3<T>>& origins, const StridedArray<Vec3<T>>& dirs,
                                   std::size_t first, T maxDist, std::uint32_t* keys) const {
  for (std::size_t i = first; i < origins.count; ++i) {
    if (!(*this)(origins[i], dirs[i], maxDist, keys[i])) keys[i] = kMisses;
  }
}

template <class T>
void RayOrderKey<T>::keyRays(const StridedArray<Vec3<T>>& origins, const StridedArray<Vec3<T>>& dirs, T maxDist,
                             std::uint32_t* keys) const {
  std::size_t done = 0;
#ifdef GQ_SSE42
  if (rayOrderKeysHaveWidePath() && !gKeysScalarOnly.load(std::memory_order_relaxed)) {
    done = origins.count / 8 * 8;  // the rest by the scalar key
    keyRaysAvx2(Bounds3<T>::fromMinMax(lo_, hi_), invExtent_, origins, dirs, done, maxDist, keys);
  }
#endif
  keyRaysScalar(origins, dirs, done, maxDist, keys);
}

std::uint64_t* sortByKey(std::uint64_t* items, std::uint64_t* scratch, std::size_t n, int keyBits) {
  if (keyBits <= 0) return items;  // every key 0: already in order
  constexpr int kMaxDigitBits = 11;
  constexpr int kMaxPasses = 3;
  constexpr std::size_t kMaxDigits = std::size_t(1) << kMaxDigitBits;
  const int passes = std::min(kMaxPasses, (keyBits + kMaxDigitBits - 1) / kMaxDigitBits);
  const int digitBits = (keyBits + passes - 1) / passes;
  const std::size_t digits = std::size_t(1) << digitBits;
  auto digit = [&](std::uint64_t item, int pass) {
    return std::size_t(item >> (32 + digitBits * pass)) & (digits - 1);
  };
  std::array<std::array<std::uint32_t, kMaxDigits>, kMaxPasses> counts;
  for (int p = 0; p < passes; ++p) std::fill_n(counts[std::size_t(p)].begin(), digits, 0u);
  for (std::size_t i = 0; i < n; ++i) {
    for (int p = 0; p < passes; ++p) ++counts[std::size_t(p)][digit(items[i], p)];
  }
  std::uint64_t* from = items;
  std::uint64_t* to = scratch;
  for (int p = 0; p < passes; ++p) {
    std::uint32_t* c = counts[std::size_t(p)].data();
    if (n == 0 || c[digit(from[0], p)] == n) continue;  // one digit for every item: the pass keeps the order
    std::uint32_t sum = 0;
    for (std::size_t d = 0; d < digits; ++d) {
      const std::uint32_t count = c[d];
      c[d] = sum;
      sum += count;
    }
    for (std::size_t i = 0; i < n; ++i) to[c[digit(from[i], p)]++] = from[i];
    std::swap(from, to);
  }
  return from;
}

template class RayOrderKey<float>;
template class RayOrderKey<double>;

}  // namespace gq::detail
