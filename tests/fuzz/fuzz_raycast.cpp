// libFuzzer target: raycast against any geometry; bytes = precision, geometry, pose, origin, direction, maxDist,
// flags, maxHits. Contract: ok -> hitCount <= maxHits and finite hits; error -> nothing written.
#include "fuzz_decode.h"

namespace {

template <class T> void run(gq::fuzz::Bytes& in) {
  using namespace gq;
  const Geometry<T> geom = fuzz::geometry<T>(in);
  const Transform<T> pose = in.pose<T>();
  const Vec3<T> origin = in.vec<T>();
  const Vec3<T> dir = in.direction<T>();
  const T maxDist = in.scalar<T>();
  const HitFlags flags = fuzz::hitFlags(in);
  const std::uint32_t maxHits = std::uint32_t(in.small(9));
  RaycastHit<T> hits[8];
  for (auto& h : hits) h.faceIndex = 777;
  std::uint32_t count = 999;
  const Status s = raycast(origin, dir, geom, pose, maxDist, flags, maxHits, in.flag() ? hits : nullptr, count);
  if (!s.ok()) {
    fuzz::require(count == 999 && hits[0].faceIndex == 777);
    return;
  }
  fuzz::require(count <= maxHits);
  for (std::uint32_t i = 0; i < count; ++i)
    fuzz::require(isFinite(hits[i].position) && isFinite(hits[i].normal) && std::isfinite(hits[i].distance) &&
                  std::isfinite(hits[i].u) && std::isfinite(hits[i].v) && hits[i].distance >= T(0));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  gq::fuzz::Bytes in(data, size);
  if (in.flag()) run<float>(in);
  else run<double>(in);
  return 0;
}
