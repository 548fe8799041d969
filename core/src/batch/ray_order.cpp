// Ray order keys and their radix sort (batch/ray_order.h).
#include "batch/ray_order.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

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
