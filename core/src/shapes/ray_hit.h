#pragma once
// Writing raycast hits for solids and planes: the spec's rules in one place.
#include "gq/hit.h"
#include "raycast/raycast.h"

namespace gq::detail {

// The origin is inside (or on) a solid: distance 0, normal = -dir, position = origin, both flags set (the spec).
template <class T> void writeInsideHit(const RayQuery<T>& ray, RaycastHit<T>& hit) {
  hit.distance = T(0);
  hit.position = ray.origin;
  hit.normal = -ray.dir;
  hit.faceIndex = kInvalidFaceIndex;
  HitFlags written = HitFlag::Position | HitFlag::Normal;
  if (ray.flags.has(HitFlag::FaceIndex)) written |= HitFlag::FaceIndex;
  hit.flags = written;
}

// A surface hit at distance t. `worldNormal()` is only called when the caller asked for the normal, so omitting
// HitFlag::Normal skips that work; the position is origin + t * dir.
template <class T, class NormalFn>
void writeSurfaceHit(const RayQuery<T>& ray, T t, std::uint32_t faceIndex, NormalFn&& worldNormal, RaycastHit<T>& hit) {
  hit.distance = t;
  hit.faceIndex = faceIndex;
  HitFlags written;
  if (ray.flags.has(HitFlag::Position)) {
    hit.position = ray.origin + t * ray.dir;
    written |= HitFlag::Position;
  }
  if (ray.flags.has(HitFlag::Normal)) {
    hit.normal = worldNormal();
    written |= HitFlag::Normal;
  }
  if (ray.flags.has(HitFlag::FaceIndex)) written |= HitFlag::FaceIndex;
  hit.flags = written;
}

}  // namespace gq::detail
