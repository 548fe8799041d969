// libFuzzer target: pointDistance and computeGeomBounds; bytes = precision, geometry, pose, point, bounds offset and
// inflation. Contract: ok -> finite outputs (distance >= 0, min <= max); error -> outputs untouched.
#include "fuzz_decode.h"

namespace {

template <class T> void run(gq::fuzz::Bytes& in) {
  using namespace gq;
  const Geometry<T> geom = fuzz::geometry<T>(in);
  const Transform<T> pose = in.pose<T>();
  {
    PointDistanceResult<T> r;
    r.distance = T(-7);
    const Status s = pointDistance(in.vec<T>(), geom, pose, r);
    if (!s.ok()) fuzz::require(r.distance == T(-7));
    else fuzz::require(std::isfinite(r.distance) && r.distance >= T(0) && isFinite(r.closestPoint));
  }
  {
    Bounds3<T> b;
    b.min.x() = T(-7);
    const T offset = in.scalar<T>();
    const T inflation = in.flag() ? in.scalar<T>() : T(1.01);
    const Status s = computeGeomBounds(b, geom, pose, offset, inflation);
    if (!s.ok()) fuzz::require(b.min.x() == T(-7));
    else fuzz::require(isFinite(b.min) && isFinite(b.max) && (b.min.array() <= b.max.array()).all());
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  gq::fuzz::Bytes in(data, size);
  if (in.flag()) run<float>(in);
  else run<double>(in);
  return 0;
}
