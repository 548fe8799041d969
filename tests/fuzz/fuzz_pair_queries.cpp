// libFuzzer target: overlap, computePenetration, distance and sweep on one decoded pair; bytes = precision, two
// geometries and poses, sweep direction, maxDist, flags, inflation. Contract: ok -> finite outputs (unit normals
// where promised); error -> outputs untouched.
#include "fuzz_decode.h"

namespace {

template <class T> bool unitOrZero(const gq::Vec3<T>& n) {
  const T len = n.norm();
  return len == T(0) || std::abs(len - T(1)) < T(1e-2);
}

template <class T> void run(gq::fuzz::Bytes& in) {
  using namespace gq;
  const Geometry<T> g0 = fuzz::geometry<T>(in);
  const Transform<T> p0 = in.pose<T>();
  const Geometry<T> g1 = fuzz::geometry<T>(in);
  const Transform<T> p1 = in.pose<T>();
  {
    bool overlapping = false;
    const Status s = overlap(g0, p0, g1, p1, overlapping);
    fuzz::require(s.ok() || !overlapping);
  }
  {
    PenetrationResult<T> r;
    r.depth = T(-7);
    const Status s = computePenetration(r, g0, p0, g1, p1);
    if (!s.ok()) fuzz::require(r.depth == T(-7) && !r.penetrating);
    else fuzz::require(isFinite(r.direction) && std::isfinite(r.depth) && r.depth >= T(0) &&
                       (!r.penetrating || unitOrZero(r.direction)));
  }
  {
    DistanceResult<T> r;
    r.distance = T(-7777);
    GjkCache<T> cache;
    const Status s = distance(r, g0, p0, g1, p1, in.flag() ? &cache : nullptr);
    if (!s.ok()) fuzz::require(r.distance == T(-7777));
    else fuzz::require(std::isfinite(r.distance) && isFinite(r.point0) && isFinite(r.point1) && isFinite(r.normal));
  }
  {
    const Vec3<T> dir = in.direction<T>();
    const T maxDist = in.scalar<T>();
    const HitFlags flags = fuzz::hitFlags(in);
    const T inflation = in.flag() ? in.scalar<T>() : T(0);
    SweepHit<T> hit;
    hit.distance = T(-7777);
    bool hasHit = true;
    const Status s = sweep(dir, maxDist, g0, p0, g1, p1, hit, hasHit, flags, inflation);
    if (!s.ok()) fuzz::require(hasHit && hit.distance == T(-7777));
    else if (hasHit)
      fuzz::require(isFinite(hit.position) && isFinite(hit.normal) && std::isfinite(hit.distance));
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  gq::fuzz::Bytes in(data, size);
  if (in.flag()) run<float>(in);
  else run<double>(in);
  return 0;
}
