// PLACEHOLDER: every pair answers Unsupported until this family lands.
#include "gq/query.h"

namespace gq {

template <class T>
Status sweep(const Vec3<T>&, T, const Geometry<T>&, const Transform<T>&, const Geometry<T>&, const Transform<T>&, SweepHit<T>&, bool&, HitFlags, T) {
  return Status::unsupported("sweep is not implemented yet");
}
template Status sweep<float>(const Vec3<float>&, float, const Geometry<float>&, const Transform<float>&, const Geometry<float>&, const Transform<float>&, SweepHit<float>&, bool&, HitFlags, float);
template Status sweep<double>(const Vec3<double>&, double, const Geometry<double>&, const Transform<double>&, const Geometry<double>&, const Transform<double>&, SweepHit<double>&, bool&, HitFlags, double);

}  // namespace gq
