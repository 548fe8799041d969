#pragma once
// Decodes libFuzzer bytes into scalars, poses, geometries and query parameters. Scalars come either from a table
// of hostile values (NaN, +-Inf, +-0, denormals, 1e+-30, the type's limits) or from raw bits, so every
// target sees both special values and arbitrary floats. Running out of bytes yields zeros (the decoder never fails).
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "gq/contacts.h"
#include "gq/cooking.h"
#include "gq/custom_shapes.h"
#include "gq/mesh_query.h"
#include "gq/query.h"

namespace gq::fuzz {

class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : p_(data), end_(data + size) {}
  bool empty() const { return p_ == end_; }
  std::uint8_t byte() { return p_ < end_ ? *p_++ : 0; }
  std::uint32_t u32() {
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v = (v << 8) | byte();
    return v;
  }
  bool flag() { return (byte() & 1) != 0; }
  std::size_t small(std::size_t n) { return byte() % n; }  // in [0, n)

  // A scalar: selector byte < kSpecial picks a hostile value, < 128 a small "nice" value (k/16 - 4), else raw bits.
  template <class T> T scalar() {
    const std::uint8_t sel = byte();
    static constexpr int kSpecial = 20;
    if (sel < kSpecial) return special<T>(sel);
    if (sel < 128) return T(int(byte()) - 128) / T(16);
    using Bits = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;
    Bits bits = 0;
    for (std::size_t i = 0; i < sizeof(T); ++i) bits = (bits << 8) | byte();
    T v;
    std::memcpy(&v, &bits, sizeof(T));
    return v;
  }
  template <class T> Vec3<T> vec() {
    const T x = scalar<T>(), y = scalar<T>(), z = scalar<T>();
    return Vec3<T>(x, y, z);
  }
  // Mostly a normalized quaternion (so queries run past validation); sometimes the raw coefficients.
  template <class T> Quat<T> quat() {
    const bool raw = byte() < 32;
    const T w = scalar<T>(), x = scalar<T>(), y = scalar<T>(), z = scalar<T>();
    Quat<T> q(w, x, y, z);
    if (raw) return q;
    const T n = q.norm();
    if (std::isfinite(n) && n > T(0)) return Quat<T>(q.coeffs() / n);
    return Quat<T>::Identity();
  }
  template <class T> Transform<T> pose() {
    const Vec3<T> p = vec<T>();
    return Transform<T>(p, quat<T>());
  }
  // Mostly unit (normalized when finite and non-zero), sometimes raw.
  template <class T> Vec3<T> direction() {
    const bool raw = byte() < 32;
    Vec3<T> d = vec<T>();
    if (raw) return d;
    const T n = d.norm();
    return std::isfinite(n) && n > T(0) ? Vec3<T>(d / n) : Vec3<T>::UnitX();
  }

 private:
  template <class T> static T special(int i) {
    using L = std::numeric_limits<T>;
    const T table[] = {L::quiet_NaN(), L::infinity(), -L::infinity(), T(0), -T(0), L::denorm_min(), -L::denorm_min(),
                       L::min(), T(1e-30), T(-1e-30), T(1e30), T(-1e30), L::max(), L::lowest(), L::epsilon(),
                       T(1e-6), T(1e6), T(1), T(-1), T(0.5)};
    return table[i];
  }
  const std::uint8_t* p_;
  const std::uint8_t* end_;
};

// Fallback cooked data (cooked once per process) for when fuzzed cooking fails.
template <class T> struct FallbackData {
  std::shared_ptr<const ConvexMesh<T>> hull;
  std::shared_ptr<const TriangleMesh<T>> mesh;
  std::shared_ptr<const HeightField<T>> heightField;
  static const FallbackData& get() {
    static const FallbackData d = [] {
      FallbackData f;
      std::vector<Vec3<T>> cube;
      for (int i = 0; i < 8; ++i) cube.emplace_back(T(i & 1 ? 1 : -1), T(i & 2 ? 1 : -1), T(i & 4 ? 1 : -1));
      if (!cookConvexMesh(cube, f.hull).ok()) std::abort();  // fixed, valid inputs
      if (!cookTriangleMesh(cube,
                       {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                        {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}},
                       f.mesh).ok())
        std::abort();
      HeightFieldDesc<T> hf;
      hf.rows = hf.columns = 4;
      for (int i = 0; i < 16; ++i) hf.heights.push_back(T((i * 7) % 5) / T(4));
      if (!cookHeightField(hf, f.heightField).ok()) std::abort();
      return f;
    }();
    return d;
  }
};

template <class T> MeshScale<T> meshScale(Bytes& in) {
  if (in.byte() < 128) return MeshScale<T>();
  const Vec3<T> s = in.vec<T>();
  return MeshScale<T>(s, in.quat<T>());
}

// Cooking memoized by the exact values it was given. qhull (convex cooking, and the hull of every cooked triangle mesh)
// makes two 128 KB allocations per call, which ASan serves with mmap/munmap: ~1.7 ms per hull under ASan against ~1 us
// for a ray, i.e. most of an execution. libFuzzer mutates a few bytes at a time, so the same point set comes back
// again and again. Cooking is deterministic (Determinism.RecookedDataGivesIdenticalBits), so a memoized result equals
// a fresh one; every distinct input is still cooked once, and crash inputs reproduce in a fresh process.
template <class Data> class CookMemo {
 public:
  template <class Cook> std::shared_ptr<const Data> get(const std::string& key, Cook cook) {
    if (auto it = map_.find(key); it != map_.end()) return it->second;
    if (map_.size() >= kCapacity) map_.clear();
    std::shared_ptr<const Data> cooked;
    if (!cook(cooked).ok()) cooked = nullptr;
    return map_.emplace(key, cooked).first->second;
  }
  static CookMemo& instance() {
    static CookMemo memo;
    return memo;
  }

 private:
  static constexpr std::size_t kCapacity = 4096;
  std::unordered_map<std::string, std::shared_ptr<const Data>> map_;
};

// Appends the bytes of `values` to a memo key.
template <class V> void appendKey(std::string& key, const std::vector<V>& values) {
  const std::size_t n = values.size();
  key.append(reinterpret_cast<const char*>(&n), sizeof n);
  if (n > 0) key.append(reinterpret_cast<const char*>(values.data()), n * sizeof(V));
}

// A hull cooked from up to 12 fuzzed points, or the fallback cube.
template <class T> std::shared_ptr<const ConvexMesh<T>> hull(Bytes& in) {
  std::shared_ptr<const ConvexMesh<T>> out = FallbackData<T>::get().hull;
  if (in.flag()) {
    std::vector<Vec3<T>> points(4 + in.small(9));
    for (auto& p : points) p = in.vec<T>();
    std::string key;
    appendKey(key, points);
    auto cooked = CookMemo<ConvexMesh<T>>::instance().get(key, [&](auto& h) { return cookConvexMesh(points, h); });
    if (cooked) out = cooked;
  }
  return out;
}

// A mesh cooked from up to 10 fuzzed vertices and 12 triangles (indices may be out of range), or the fallback.
template <class T> std::shared_ptr<const TriangleMesh<T>> mesh(Bytes& in) {
  std::shared_ptr<const TriangleMesh<T>> out = FallbackData<T>::get().mesh;
  if (in.flag()) {
    std::vector<Vec3<T>> vertices(3 + in.small(8));
    for (auto& v : vertices) v = in.vec<T>();
    std::vector<TriangleIndices> triangles(1 + in.small(12));
    for (auto& t : triangles) t = {std::uint32_t(in.small(12)), std::uint32_t(in.small(12)), std::uint32_t(in.small(12))};
    std::string key;
    appendKey(key, vertices);
    appendKey(key, triangles);
    auto cooked = CookMemo<TriangleMesh<T>>::instance().get(
        key, [&](auto& m) { return cookTriangleMesh(vertices, triangles, m); });
    if (cooked) out = cooked;
  }
  return out;
}

// A heightfield of up to 6 x 6 fuzzed samples with fuzzed holes, or the fallback.
template <class T> std::shared_ptr<const HeightField<T>> heightField(Bytes& in) {
  std::shared_ptr<const HeightField<T>> out = FallbackData<T>::get().heightField;
  if (in.flag()) {
    HeightFieldDesc<T> desc;
    desc.rows = std::uint32_t(in.small(7));
    desc.columns = std::uint32_t(in.small(7));
    desc.heights.resize(std::size_t(desc.rows) * desc.columns);
    for (auto& h : desc.heights) h = in.scalar<T>();
    for (std::size_t i = in.small(4); i > 0; --i) desc.holes.push_back(std::uint32_t(in.small(40)));
    const std::uint32_t grid[2] = {desc.rows, desc.columns};
    std::string key(reinterpret_cast<const char*>(grid), sizeof grid);
    appendKey(key, desc.heights);
    appendKey(key, desc.holes);
    auto cooked = CookMemo<HeightField<T>>::instance().get(key, [&](auto& h) { return cookHeightField(desc, h); });
    if (cooked) out = cooked;
  }
  return out;
}

template <class T> Geometry<T> geometry(Bytes& in) {
  switch (in.small(kGeometryTypeCount)) {
    case 0: return SphereGeometry<T>(in.scalar<T>());
    case 1: return PlaneGeometry<T>();
    case 2: {
      const T r = in.scalar<T>();
      return CapsuleGeometry<T>(r, in.scalar<T>());
    }
    case 3: return BoxGeometry<T>(in.vec<T>());
    case 4: {
      auto h = hull<T>(in);
      return ConvexMeshGeometry<T>(h, meshScale<T>(in));
    }
    case 5: {
      auto m = mesh<T>(in);
      const MeshScale<T> s = meshScale<T>(in);
      return TriangleMeshGeometry<T>(m, s, in.flag() ? MeshGeometryFlag::DoubleSided : MeshGeometryFlag::None);
    }
    case 6: {
      auto hf = heightField<T>(in);
      const T hs = in.scalar<T>(), rs = in.scalar<T>(), cs = in.scalar<T>();
      return HeightFieldGeometry<T>(hf, hs, rs, cs, in.flag() ? MeshGeometryFlag::DoubleSided : MeshGeometryFlag::None);
    }
    default: {
      const bool cone = in.flag();
      const T r = in.scalar<T>(), h = in.scalar<T>();
      CustomGeometry<T> g;
      const Status s = cone ? makeCone(r, h, g) : makeCylinder(r, h, g);
      if (!s.ok()) return SphereGeometry<T>(r);  // invalid sizes: the sphere carries them to validation
      return g;
    }
  }
}

inline HitFlags hitFlags(Bytes& in) { return HitFlags(std::uint16_t(in.byte() | (in.byte() & 0x3) << 8)); }

// A broken contract is a crash for libFuzzer: it records the input and stops.
inline void require(bool condition) {
  if (!condition) std::abort();
}

}  // namespace gq::fuzz
