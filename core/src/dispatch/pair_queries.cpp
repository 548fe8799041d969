// PLACEHOLDER façades for the pair query families until their issues land: every pair answers Unsupported.
#include "common/validate.h"
#include "gq/query.h"

namespace gq {

template <class T>
Status overlap(const Geometry<T>&, const Transform<T>&, const Geometry<T>&, const Transform<T>&, bool&) {
  return Status::unsupported("overlap is not implemented yet");
}
template <class T>
Status computePenetration(PenetrationResult<T>&, const Geometry<T>&, const Transform<T>&, const Geometry<T>&,
                          const Transform<T>&) {
  return Status::unsupported("computePenetration is not implemented yet");
}
template <class T>
Status distance(DistanceResult<T>&, const Geometry<T>&, const Transform<T>&, const Geometry<T>&, const Transform<T>&,
                GjkCache<T>*) {
  return Status::unsupported("distance is not implemented yet");
}
template <class T>
Status sweep(const Vec3<T>&, T, const Geometry<T>&, const Transform<T>&, const Geometry<T>&, const Transform<T>&,
             SweepHit<T>&, bool&, HitFlags, T) {
  return Status::unsupported("sweep is not implemented yet");
}

#define GQ_INSTANTIATE(T)                                                                                         \
  template Status overlap<T>(const Geometry<T>&, const Transform<T>&, const Geometry<T>&, const Transform<T>&,   \
                             bool&);                                                                              \
  template Status computePenetration<T>(PenetrationResult<T>&, const Geometry<T>&, const Transform<T>&,          \
                                        const Geometry<T>&, const Transform<T>&);                                 \
  template Status distance<T>(DistanceResult<T>&, const Geometry<T>&, const Transform<T>&, const Geometry<T>&,   \
                              const Transform<T>&, GjkCache<T>*);                                                 \
  template Status sweep<T>(const Vec3<T>&, T, const Geometry<T>&, const Transform<T>&, const Geometry<T>&,       \
                           const Transform<T>&, SweepHit<T>&, bool&, HitFlags, T);
GQ_INSTANTIATE(float)
GQ_INSTANTIATE(double)

}  // namespace gq
