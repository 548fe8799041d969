// Ray order keys and their radix sort (batch/ray_order.h).
#include "batch/ray_order.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace gq::detail {

namespace {

constexpr int kBitsPerAxis = 5;
constexpr std::uint32_t kCells = 1u << kBitsPerAxis;
constexpr int kAxes = 6;  // closest point x, y, z; direction x, y, z

// The 5 bits of a cell index spread 6 apart (bit b at 6b): six spread indices shifted by 0..5 interleave.
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

// x in [0, 1] to a cell index: below 0 or NaN the first cell, from 1 up the last (max(0, NaN) is 0).
template <class T> std::uint32_t cell(T x) {
  return std::uint32_t(std::min(std::max(T(0), x * T(kCells)), T(kCells - 1)));
}

}  // namespace

template <class T>
RayOrderKey<T>::RayOrderKey(const Bounds3<T>& target)
    : lo_(target.min), centre_((target.min + target.max) * T(0.5)),
      radius_(T(0.5) * (target.max - target.min).norm()) {
  for (int k = 0; k < 3; ++k) {
    const T extent = target.max[k] - target.min[k];
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
  // u = dir / |dir|; the line's closest point to the centre c is origin + s u, s = (c - origin) . u, at the
  // squared distance |c - origin|^2 - s^2. The ray meets the box's bounding sphere (radius r) within maxDist when
  // that distance is at most r and s lies in [-r, maxDist + r]. A NaN anywhere fails a comparison: no key.
  const T invLength = T(1) / std::sqrt(dir.squaredNorm());
  const Vec3<T> u = dir * invLength;
  const Vec3<T> w = centre_ - origin;
  const T s = w.dot(u);
  const T r2 = radius_ * radius_;
  key = 0;
  if (!(w.squaredNorm() - s * s <= r2) || !(s >= -radius_) || !(s <= maxDist + radius_)) return false;
  const Vec3<T> closest = origin + s * u;
  for (int k = 0; k < 3; ++k) {
    key |= kSpread[cell((closest[k] - lo_[k]) * invExtent_[k])] << (kAxes - 1 - k);
    key |= kSpread[cell((u[k] + T(1)) * T(0.5))] << (2 - k);
  }
  return true;
}

std::uint64_t* sortByKey(std::uint64_t* items, std::uint64_t* scratch, std::size_t n, int keyBits) {
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
