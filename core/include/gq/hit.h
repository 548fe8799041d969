#pragma once
// Hit flags and hit structs. A hit's `flags` say which optional fields hold results.
#include <cstdint>

#include "gq/math.h"

namespace gq {

enum class HitFlag : std::uint16_t {
  Position = 1 << 0,
  Normal = 1 << 1,
  UV = 1 << 2,
  FaceIndex = 1 << 3,
  MeshMultiple = 1 << 4,
  MeshBothSides = 1 << 5,
  AnyHit = 1 << 6,  // PxHitFlag::eMESH_ANY
  Mtd = 1 << 7,
  PreciseSweep = 1 << 8,
  AssumeNoInitialOverlap = 1 << 9,
};

class HitFlags {
 public:
  constexpr HitFlags() = default;
  constexpr HitFlags(HitFlag f) : bits_(static_cast<std::uint16_t>(f)) {}
  constexpr explicit HitFlags(std::uint16_t bits) : bits_(bits) {}
  constexpr bool has(HitFlag f) const { return (bits_ & static_cast<std::uint16_t>(f)) != 0; }
  constexpr HitFlags operator|(HitFlags o) const { return HitFlags(std::uint16_t(bits_ | o.bits_)); }
  constexpr HitFlags operator&(HitFlags o) const { return HitFlags(std::uint16_t(bits_ & o.bits_)); }
  constexpr HitFlags without(HitFlags o) const { return HitFlags(std::uint16_t(bits_ & ~o.bits_)); }
  HitFlags& operator|=(HitFlags o) { bits_ |= o.bits_; return *this; }
  constexpr bool operator==(HitFlags o) const { return bits_ == o.bits_; }
  constexpr bool operator!=(HitFlags o) const { return bits_ != o.bits_; }
  constexpr std::uint16_t bits() const { return bits_; }

 private:
  std::uint16_t bits_ = 0;
};
constexpr HitFlags operator|(HitFlag a, HitFlag b) { return HitFlags(a) | HitFlags(b); }

// The spec's eDEFAULT: position, normal and face index.
inline constexpr HitFlags kDefaultHitFlags = HitFlag::Position | HitFlag::Normal | HitFlag::FaceIndex;
// Reported for shapes without faces (sphere, capsule, box, plane, custom).
inline constexpr std::uint32_t kInvalidFaceIndex = 0xffffffffu;

template <class T> struct RaycastHit {
  Vec3<T> position = Vec3<T>::Zero();  // valid if flags has Position
  Vec3<T> normal = Vec3<T>::Zero();    // valid if flags has Normal
  T distance = T(0);
  HitFlags flags;
  std::uint32_t faceIndex = kInvalidFaceIndex;
  T u = T(0), v = T(0);  // valid if flags has UV: position = (1-u-v)*v0 + u*v1 + v*v2
};

template <class T> struct SweepHit {
  Vec3<T> position = Vec3<T>::Zero();
  Vec3<T> normal = Vec3<T>::Zero();
  T distance = T(0);
  HitFlags flags;
  std::uint32_t faceIndex = kInvalidFaceIndex;
  bool initialOverlap = false;
  bool hadInitialOverlap() const { return initialOverlap; }
};

}  // namespace gq
