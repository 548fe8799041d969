// PLACEHOLDER: every pair answers Unsupported until this family lands.
#include "gq/query.h"

namespace gq {

template <class T>
Status distance(DistanceResult<T>&, const Geometry<T>&, const Transform<T>&, const Geometry<T>&, const Transform<T>&, GjkCache<T>*) {
  return Status::unsupported("distance is not implemented yet");
}
template Status distance<float>(DistanceResult<float>&, const Geometry<float>&, const Transform<float>&, const Geometry<float>&, const Transform<float>&, GjkCache<float>*);
template Status distance<double>(DistanceResult<double>&, const Geometry<double>&, const Transform<double>&, const Geometry<double>&, const Transform<double>&, GjkCache<double>*);

}  // namespace gq
